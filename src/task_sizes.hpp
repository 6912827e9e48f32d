// How many items one task of a parallel loop takes (internal header).
#ifndef PHONGRAST_SRC_TASK_SIZES_HPP
#define PHONGRAST_SRC_TASK_SIZES_HPP

#include <cassert>
#include <cstddef>

namespace phongrast::detail {

/// Tasks per thread items_per_task() aims at for a loop too small for its
/// largest tasks: enough that the threads end together.
constexpr std::size_t kTasksPerThread = 4;

/// Items per task of a parallel loop over `items` on `threads` threads:
/// `largest`, or, when that gives fewer than kTasksPerThread tasks per
/// thread, the power of two times `smallest` (both powers of two) nearest
/// above items / (threads x kTasksPerThread). On one thread: `largest`.
///
/// Why: at the largest size a small mesh's loop is one or two tasks, and
/// one thread does most of it while the other waits (spot's 5,856
/// triangles were set up as 4,096 + 1,760). Tasks smaller than `smallest`
/// would cost more to hand out than they take. The result sets only where
/// tasks start, never what an item computes, so a render gives the same
/// image whatever it is.
inline std::size_t items_per_task(std::size_t items, int threads, std::size_t largest, std::size_t smallest) {
    assert(smallest > 0 && smallest <= largest);
    if (threads <= 1) return largest;
    const std::size_t wanted = items / (static_cast<std::size_t>(threads) * kTasksPerThread);
    std::size_t size = smallest;
    while (size < wanted && size < largest) size *= 2;
    return size;
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_TASK_SIZES_HPP
