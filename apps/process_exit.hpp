// Ending a one-off command's process once its output is written.
#ifndef PHONGRAST_APPS_PROCESS_EXIT_HPP
#define PHONGRAST_APPS_PROCESS_EXIT_HPP

namespace phongrast::cli {

/// Called by render and thumbnail when every file is written and every
/// message printed: flushes standard output and error and ends the process
/// with `status` at once, without destroying the scene, the renderer's
/// buffers and oneTBB's threads one by one (about 1 ms of `phongrast render`
/// of a small mesh, freeing and unmapping what the process's exit frees
/// anyway). In a sanitizer build it returns `status` instead, so that the
/// leak check at exit still sees every buffer freed.
int end_one_off_process(int status);

}  // namespace phongrast::cli

#endif
