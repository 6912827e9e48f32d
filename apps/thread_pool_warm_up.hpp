// Starting oneTBB's thread pool while a command reads its input.
#ifndef PHONGRAST_APPS_THREAD_POOL_WARM_UP_HPP
#define PHONGRAST_APPS_THREAD_POOL_WARM_UP_HPP

#include <thread>

namespace phongrast::cli {

/// oneTBB starts on its first parallel call: it loads libtbbmalloc, probes
/// for libirml and OpenMP, reads /proc, and creates its worker threads. In a
/// one-off `phongrast render` of a small mesh that first call came while
/// reading the mesh, on the main thread, before anything could overlap it.
/// This starts the pool on a thread of its own at once, so that it is ready
/// (or nearly) when the render needs it; the destructor waits for that
/// thread. Only the pool is started: what the render computes, and with
/// how many threads, does not change. With `threads` 1 (the render uses the
/// calling thread alone) nothing is started.
class ThreadPoolWarmUp {
public:
    explicit ThreadPoolWarmUp(int threads);
    ~ThreadPoolWarmUp();
    ThreadPoolWarmUp(const ThreadPoolWarmUp&) = delete;
    ThreadPoolWarmUp& operator=(const ThreadPoolWarmUp&) = delete;

private:
    std::thread thread_;
};

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_THREAD_POOL_WARM_UP_HPP
