// Ctrl-C: the first SIGINT only raises a flag, which the render's progress
// callback turns into a cancellation, so the program stops at the next piece
// of work, writes nothing and exits 130 (the shell's code for SIGINT).
#ifndef PHONGRAST_APPS_INTERRUPT_HPP
#define PHONGRAST_APPS_INTERRUPT_HPP

#include <functional>
#include <string>

#include "phongrast/progress.hpp"

namespace phongrast::cli {

/// The exit status after Ctrl-C.
constexpr int kInterruptedExitStatus = 130;

/// Installs the SIGINT handler (once, at start-up).
void catch_interrupts();

/// Whether Ctrl-C was pressed since start-up.
bool interrupted();

/// Throws RenderCancelled if Ctrl-C was pressed: for the steps between renders (loading, writing).
void stop_if_interrupted();

/// A progress callback for RenderOptions::progress: shows a bar on stderr
/// (when `show_bar`: a terminal, not --quiet) once a render has taken half a
/// second, labelled `what`, and cancels the render after Ctrl-C.
ProgressCallback progress_bar(bool show_bar, std::string what);

/// Ends the bar's line if one was drawn.
void clear_progress_bar(bool show_bar);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_INTERRUPT_HPP
