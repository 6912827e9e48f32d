#include "interrupts.hpp"

namespace phongrast::python {

PythonProgress::PythonProgress(py::object progress) : progress_(std::move(progress)) {}

ProgressCallback PythonProgress::callback() {
    return [this](double fraction) { return report(fraction); };
}

bool PythonProgress::report(double fraction) {
    py::gil_scoped_acquire gil;
    if (error_) return false;
    // Pending signals first: a Ctrl-C during the render raises KeyboardInterrupt here.
    if (PyErr_CheckSignals() != 0) {
        error_.emplace();  // takes the pending exception
        return false;
    }
    if (progress_.is_none()) return true;
    try {
        const py::object answer = progress_(fraction);
        // None (a callable that returns nothing) goes on; anything false cancels.
        return answer.is_none() || PyObject_IsTrue(answer.ptr()) != 0;
    } catch (py::error_already_set& error) {
        error_.emplace(std::move(error));
        return false;
    }
}

py::object progress_keyword(const py::kwargs& keywords) {
    if (!keywords.contains("progress")) return py::none();
    py::object progress = keywords["progress"];
    if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
        throw py::type_error("progress: expected a callable taking the fraction done (0 to 1), or None");
    }
    return progress;
}

}  // namespace phongrast::python
