// The renderer's per-frame buffers of a few MiB on 2 MiB pages (internal
// header).
//
// Why: on the virtual machines this project is measured on, the first
// write from user code to each fresh 4 KiB page costs about 5 us even after
// MADV_POPULATE_WRITE has mapped it, while a 2 MiB page pays that once
// (docs/startup.md, "The first frame"). A Renderer's first frame of a
// 100k-triangle mesh at 512x512 writes about 15 MiB of such fresh buffers
// outside set-up (chunk_arena.hpp): the vertex stage's screen vertices and
// varyings, the smooth normals' accumulators, painter's order, the bins, the
// fill's owner buffers. Each is one vector of 16 KiB to a few MiB: given a
// 2 MiB mapping each, most of every mapping would be waste; glibc's malloc
// maps such blocks 4 KiB-aligned, so even its huge-page tunable gets a huge
// page only where a block happens to span an aligned 2 MiB.
//
// So these vectors (FrameVector) take their memory from a pool of 2 MiB-
// aligned mappings advised MADV_HUGEPAGE (transparent huge pages in
// `madvise` mode, as on most distributions), carved into blocks side by
// side: consecutive buffers share huge pages. Pages are faulted on first
// write, never populated ahead (populating huge pages took far longer than
// faulting them here). The pool is the process's and shared by every
// Renderer; a mapping is unmapped as soon as its last block is freed, so a
// destroyed Renderer leaves nothing mapped, and nothing of the host's
// settings changes.
//
// Memory: a block is written whole by its vector (the vectors it serves are
// sized exactly, by resize or reserve, and filled), so huge pages make
// resident only what 4 KiB pages would, plus the unwritten part of each
// mapping's last 2 MiB page. A freed block's pages stay resident until its
// mapping is empty (a hole a later block of the same or smaller size
// reuses), so blocks over kMaxBlock bytes (the large frames of
// docs/performance.md, "Memory") come from the heap as before and are
// returned to the system when freed. Blocks under kMinBlock (four pages)
// come from the heap too. Where the pool cannot be used (not Linux,
// transparent huge pages `never`, mmap or madvise failing), every block
// comes from the heap: the same bytes, on 4 KiB pages.
#ifndef PHONGRAST_SRC_HUGE_PAGE_POOL_HPP
#define PHONGRAST_SRC_HUGE_PAGE_POOL_HPP

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <vector>

#include "populate_pages.hpp"

namespace phongrast::detail {

/// 2 MiB-aligned mappings advised MADV_HUGEPAGE, carved into blocks.
class HugePagePool {
public:
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;
    /// Each mapping's size, at least (address space only: a 2 MiB page becomes resident when written).
    static constexpr std::size_t kMappingBytes = std::size_t(32) << 20;
    /// Blocks of sizes in [kMinBlock, kMaxBlock] come from the pool.
    static constexpr std::size_t kMinBlock = std::size_t(16) << 10;
    static constexpr std::size_t kMaxBlock = std::size_t(16) << 20;
    /// Every block starts on a cache line.
    static constexpr std::size_t kBlockAlignment = 64;

    /// The system calls the pool makes (tests replace them to make them fail).
    struct System {
        /// Whether transparent huge pages can be had by advice (not `never`).
        bool (*huge_pages_available)();
        /// mmap of `bytes` of private anonymous memory; null on failure.
        void* (*map)(std::size_t bytes);
        /// munmap.
        void (*unmap)(void* begin, std::size_t bytes);
        /// madvise(MADV_HUGEPAGE); false on failure.
        bool (*advise_huge_pages)(void* begin, std::size_t bytes);
    };
    /// Linux's calls; elsewhere, huge_pages_available() is false.
    static System system_calls();

    explicit HugePagePool(System system = system_calls()) : system_(system) {}
    HugePagePool(const HugePagePool&) = delete;
    HugePagePool& operator=(const HugePagePool&) = delete;
    /// Unmaps every mapping: every block must have been freed.
    ~HugePagePool();

    /// A block of `bytes` (kBlockAlignment-aligned), or null: the size is
    /// outside [kMinBlock, kMaxBlock], or the pool cannot map huge pages (the
    /// caller takes heap memory). A new mapping reads as zero.
    void* allocate(std::size_t bytes);
    /// Frees a block allocate() gave with the same `bytes`: true. False,
    /// and nothing done, for memory not from this pool.
    bool deallocate(void* block, std::size_t bytes) noexcept;
    /// Whether `address` lies in one of the pool's mappings.
    bool owns(const void* address) const;
    /// madvise(MADV_HUGEPAGE) of [begin, begin + bytes), memory of the
    /// caller's (reserve_on_huge_pages): false, and nothing done, where the
    /// pool cannot have huge pages.
    bool advise(void* begin, std::size_t bytes);

    /// Held across fork() (pthread_atfork in huge_page_pool()).
    void lock_for_fork() { mutex_.lock(); }
    void unlock_after_fork() { mutex_.unlock(); }

    /// For tests: the mappings held, and whether the pool has given up (mmap or madvise failed, or THP off).
    std::size_t mappings() const;
    bool disabled() const;

private:
    struct Mapping {
        char* base = nullptr;
        std::size_t bytes = 0;
        std::size_t top = 0;   ///< blocks lie below; above is untouched
        std::size_t live = 0;  ///< blocks allocated and not freed
        std::map<std::size_t, std::size_t> holes;  ///< freed blocks below `top`: offset -> bytes, coalesced
    };

    bool available();  ///< with mutex_ held
    void* take(Mapping& mapping, std::size_t bytes);
    bool map_another(std::size_t bytes);

    System system_;
    mutable std::mutex mutex_;
    std::vector<Mapping> mappings_;
    int availability_ = -1;  ///< -1 not asked yet, 0 no huge pages (or a call failed: use the heap), 1 yes
};

/// The process's pool (never destroyed: vectors of static objects may
/// outlive any destructor order; its mappings go when their blocks do).
HugePagePool& huge_page_pool();

/// std::allocator, except that blocks the pool takes come from huge_page_pool().
template <typename T>
class HugePageAllocator {
public:
    using value_type = T;
    static_assert(alignof(T) <= HugePagePool::kBlockAlignment, "a block is aligned to a cache line only");

    HugePageAllocator() noexcept = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
        if (void* block = huge_page_pool().allocate(n * sizeof(T))) return static_cast<T*>(block);
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* values, std::size_t n) noexcept {
        if (!huge_page_pool().deallocate(values, n * sizeof(T))) std::allocator<T>().deallocate(values, n);
    }

    /// For populate_pages.hpp: memory of the pool is left to be faulted in as huge pages.
    static bool on_huge_pages(const void* address) { return huge_page_pool().owns(address); }
};

template <typename T, typename U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) noexcept {
    return true;
}
template <typename T, typename U>
bool operator!=(const HugePageAllocator<T>&, const HugePageAllocator<U>&) noexcept {
    return false;
}

/// A per-frame buffer of the renderer: a std::vector whose memory, between
/// kMinBlock and kMaxBlock, lies on huge pages.
template <typename T>
using FrameVector = std::vector<T, HugePageAllocator<T>>;

/// For a buffer that must stay a std::vector with std::allocator (Image's
/// pixels, a public type): values.reserve(size), with a slack of 2 MiB when
/// `size` elements take 2 MiB to kMaxBlock, so that the new part's end lies
/// inside a whole 2 MiB-aligned page of the buffer; those whole pages are
/// advised MADV_HUGEPAGE, the rest (a head of under 2 MiB) populated
/// (populate_pages.hpp). malloc places such a block 4 KiB-aligned, so the
/// head cannot be a huge page: on average 2 MiB of a 3 MiB image is.
/// Memory: the part of the last huge page past `size`, up to 2 MiB,
/// becomes resident with it. Outside that range of sizes, or without huge
/// pages: reserve_populated() (4 KiB pages mapped ahead), as before.
/// Returns whether the vector grew (its new part then needs no populating).
template <typename T>
bool reserve_on_huge_pages(std::vector<T>& values, std::size_t size) {
    constexpr std::size_t kHuge = HugePagePool::kHugePage;
    if (size <= values.capacity()) return false;
    const std::size_t bytes = size * sizeof(T);
    if (bytes < kHuge || bytes > HugePagePool::kMaxBlock) {
        reserve_populated(values, size);
        return true;
    }
    values.reserve(size + (kHuge + sizeof(T) - 1) / sizeof(T));
    const auto round_up = [](std::uintptr_t a) { return (a + kHuge - 1) / kHuge * kHuge; };
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(values.data() + values.size());
    const std::uintptr_t huge_begin = round_up(begin);
    const std::uintptr_t huge_end = round_up(reinterpret_cast<std::uintptr_t>(values.data() + size));
    // huge_end <= the buffer's end: the slack is at least 2 MiB.
    if (huge_end > huge_begin &&
        huge_page_pool().advise(reinterpret_cast<void*>(huge_begin), huge_end - huge_begin)) {
        populate_for_writing(values.data() + values.size(), huge_begin - begin);
    } else {
        populate_for_writing(values.data() + values.size(), (values.capacity() - values.size()) * sizeof(T));
    }
    return true;
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_HUGE_PAGE_POOL_HPP
