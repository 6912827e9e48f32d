#include "thread_pool_warm_up.hpp"

#include <system_error>

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

namespace phongrast::cli {

ThreadPoolWarmUp::ThreadPoolWarmUp(int threads) {
    if (threads == 1) return;
    try {
        thread_ = std::thread([] {
            // More pieces than threads, one each: oneTBB asks for its workers
            // (the bodies do nothing; creating the pool is the point).
            tbb::parallel_for(0, 64, [](int) {}, tbb::simple_partitioner());
        });
    } catch (const std::system_error&) {
        // No thread to spare: the render starts the pool itself, as it always could.
    }
}

ThreadPoolWarmUp::~ThreadPoolWarmUp() {
    if (thread_.joinable()) thread_.join();
}

}  // namespace phongrast::cli
