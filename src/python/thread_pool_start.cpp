// oneTBB started at `import phongrast`, on a thread of its own.
//
// oneTBB starts on a process's first parallel call: it loads libtbbmalloc,
// probes for libirml and OpenMP, reads /proc and sets up its market, 3.3-3.5
// ms here (docs/startup.md, "The first frame"). In the command the mesh
// check makes that call while the file is read; in Python the first call is
// the first render's, whose frame it made the slowest. Started at import
// on a thread of its own, it runs while the script builds or reads its mesh;
// import only pays for starting the thread. A render that comes sooner waits
// for oneTBB's own lock, as it would have waited for the start anyway.
#include <future>

#if defined(__unix__)
#include <pthread.h>
#endif

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "bindings.hpp"

namespace phongrast::python {
namespace {

std::future<void>& pool_start() {
    // Destroyed at exit, which waits for the start (a few ms at most) rather
    // than let oneTBB's globals go while it runs.
    static std::future<void> started;
    return started;
}

#if defined(__unix__)
// A fork (multiprocessing) while oneTBB is half started would leave the
// child its locks held: the parent waits for the start first.
void finish_start_before_fork() {
    if (pool_start().valid()) pool_start().wait();
}
#endif

}  // namespace

void start_thread_pool() {
#if defined(__unix__)
    pthread_atfork(finish_start_before_fork, nullptr, nullptr);
#endif
    pool_start() = std::async(std::launch::async, [] {
        // What a Renderer's first frame does first: an arena of one thread and
        // a parallel call in it (no worker thread is started for it).
        tbb::task_arena arena(1);
        arena.execute([] { tbb::parallel_for(0, 2, [](int) {}); });
    });
}

}  // namespace phongrast::python
