#include "process_heap.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace phongrast::cli {
namespace {

/// The block held below the first huge page. Stored where the compiler must
/// keep it: a malloc whose result is never used may be left out (GCC does),
/// and so may a malloc and free of a block that goes nowhere else.
void* volatile held_below_huge_pages = nullptr;
void* volatile grown = nullptr;

}  // namespace

void* hold_up_to_huge_page(std::uintptr_t top, std::uintptr_t first, std::uintptr_t last,
                           void* (*allocate)(std::size_t), void (*release)(void*)) {
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    constexpr std::size_t kHeader = 2 * sizeof(std::size_t);
    // malloc serves a request from a free chunk elsewhere in the heap, if one
    // fits, before its top: a hold of a few KiB could land there and leave
    // the top, and the next buffer, below the boundary (test_process_heap
    // failed 1 run in 50-400 so, the hold placed elsewhere in exactly the
    // failing run). Then hold up to the next boundary instead, a request
    // larger than any free chunk of a young heap.
    for (std::uintptr_t boundary = first; boundary + kHugePage <= last; boundary += kHugePage) {
        if (boundary - top <= 4 * kHeader) continue;  // too close to hold: the next boundary
        void* const hold = allocate(boundary - top - kHeader);
        if (hold == nullptr) return nullptr;
        if (reinterpret_cast<std::uintptr_t>(hold) == top) return hold;
        release(hold);
    }
    return nullptr;
}

void prepare_one_off_heap() {
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    constexpr std::size_t kMiB = std::size_t(1) << 20;
    constexpr std::size_t kHugePage = 2 * kMiB;
    constexpr std::size_t kHugeHeap = 32 * kMiB;
    // The values glibc's own sliding threshold reaches after the first large
    // free (mmap threshold 32 MiB, trim threshold twice that), set from the
    // start: a one-off process frees few buffers, so it never got there, and
    // every buffer over 128 KiB was a fresh mapping. Larger buffers (large
    // meshes) are still mapped apart and returned on free, as before.
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHugeHeap));
    mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * kHugeHeap));
    // (Worker threads keep malloc arenas of their own: making every thread
    // share this heap's lock saved no measurable faults here, 350-400 either
    // way, and would serialise the allocations of many cores.)
    // Grow the heap by kHugeHeap once (address space only: nothing is
    // touched), advise the 2 MiB-aligned part, and give it back to malloc as
    // free space at the top of the heap, which the trim threshold keeps.
    grown = std::malloc(kHugeHeap - kHugePage);
    void* const block = grown;
    if (block == nullptr) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(block);
    const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = end & ~(kHugePage - 1);
    // Only when the block came from the heap just below the break (not a
    // mapping of its own, not a heap that could not grow in place).
    if (!(end >= begin && end - begin <= kHugeHeap + kHugePage && last > first)) {
        std::free(block);
        return;
    }
    madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // advice: failure changes nothing
    std::free(block);
    // malloc hands out the free top from its start: hold the part below the
    // first 2 MiB boundary (never touched beyond its header; it is the
    // process's, freed at exit), so that the buffers start on huge pages.
    const auto allocate = [](std::size_t bytes) { return std::malloc(bytes); };
    const auto release = [](void* hold) { std::free(hold); };
    if (held_below_huge_pages == nullptr) {
        held_below_huge_pages = hold_up_to_huge_page(begin, first, last, allocate, release);
    }
#endif
}

}  // namespace phongrast::cli
