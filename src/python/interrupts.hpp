// Ctrl-C and progress callbacks during a render that runs with the GIL
// released. The render's progress callback (phongrast/progress.hpp) runs on
// the thread that called render(), about every 20 ms: it takes the GIL, runs
// Python's pending signal handlers (PyErr_CheckSignals: SIGINT raises
// KeyboardInterrupt there) and the user's `progress` callable, and on an
// exception cancels the render; the exception is raised again once the
// render has stopped and the GIL is back.
#ifndef PHONGRAST_PYTHON_INTERRUPTS_HPP
#define PHONGRAST_PYTHON_INTERRUPTS_HPP

#include <optional>
#include <utility>

#include <pybind11/pybind11.h>

#include "phongrast/render.hpp"

namespace phongrast::python {

namespace py = pybind11;

class PythonProgress {
public:
    /// `progress`: None, or a callable taking the fraction done (0 to 1);
    /// returning False cancels the render (RenderCancelled).
    explicit PythonProgress(py::object progress);

    /// The callback to put into RenderOptions::progress; valid while this lives.
    ProgressCallback callback();

    /// Call with the GIL held. Runs `render` (which must release the GIL
    /// itself), and when it was cancelled because of a Python exception
    /// (KeyboardInterrupt from Ctrl-C, or one the callable raised) raises
    /// that exception instead of RenderCancelled.
    template <typename Render>
    auto run(Render&& render) -> decltype(render()) {
        try {
            return render();
        } catch (const RenderCancelled&) {
            if (error_) {
                py::error_already_set error = std::move(*error_);
                error_.reset();
                throw error;
            }
            throw;
        }
    }

private:
    bool report(double fraction);

    py::object progress_;
    std::optional<py::error_already_set> error_;
};

/// The `progress` keyword (None when absent); checks it is callable.
py::object progress_keyword(const py::kwargs& keywords);

}  // namespace phongrast::python

#endif  // PHONGRAST_PYTHON_INTERRUPTS_HPP
