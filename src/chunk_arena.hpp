// Set-up's per-chunk buffers of a small frame in one huge-page mapping
// (internal header).
//
// Why: on the virtual machines this project is measured on, the first
// write from user code to each fresh 4 KiB page costs several microseconds
// even after MADV_POPULATE_WRITE has mapped it (the hypervisor's own page
// tables are filled lazily): in a Renderer's first frame of a 100k-triangle
// sphere, the stores of set-up's records into their fresh pages took 13x
// their time in later frames (perf, docs/startup.md "The first frame").
// One 2 MiB page costs that once. The set-up buffers are many vectors of
// under 2 MiB each (per chunk of kSetupChunk triangles), so they only get
// huge pages when they share a mapping: a ChunkArena gives each chunk's
// vectors a fixed slot in one 2 MiB-aligned mapping advised MADV_HUGEPAGE
// (transparent huge pages in `madvise` mode, the default of many
// distributions). Measured with a test program on this machine, writing
// 14 MiB of fresh memory took 1.4 ms on huge pages against 4.5 ms to map
// 4 KiB pages with MADV_POPULATE_WRITE plus 18 ms for the first writes.
//
// Only for small frames (kHugePageArenaBytes): a slot's unwritten tail
// (triangles culled or covering no sample) is then resident too, which a
// frame of the 8M mesh could not afford (docs/performance.md, Memory);
// larger frames keep plain vectors, mapped 64 KiB ahead of the writes as
// before, what a chunk leaves unwritten given back (record_pages.hpp). The mapping is the arena's own, advice and all, and unmapped with
// it: nothing of the host's memory or settings changes.
#ifndef PHONGRAST_SRC_CHUNK_ARENA_HPP
#define PHONGRAST_SRC_CHUNK_ARENA_HPP

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace phongrast::detail {

/// One chunk's place for one buffer in a ChunkArena: lent to one vector at a time.
struct ArenaSlot {
    void* base = nullptr;  ///< null: no arena (a large frame); the vector uses the heap
    std::size_t bytes = 0;
    bool lent = false;
};

/// std::allocator, except that the first request that fits the slot (while
/// it is not lent) gets the slot's memory. Anything else (a vector grown
/// past its slot, no slot) comes from and goes back to the heap.
template <typename T>
class SlotAllocator {
public:
    using value_type = T;

    SlotAllocator() noexcept = default;
    explicit SlotAllocator(ArenaSlot* slot) noexcept : slot_(slot) {}
    template <typename U>
    SlotAllocator(const SlotAllocator<U>& other) noexcept : slot_(other.slot()) {}

    T* allocate(std::size_t n) {
        if (slot_ != nullptr && slot_->base != nullptr && !slot_->lent && n <= slot_->bytes / sizeof(T)) {
            slot_->lent = true;
            return static_cast<T*>(slot_->base);
        }
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* values, std::size_t n) noexcept {
        if (slot_ != nullptr && slot_->base != nullptr && values == slot_->base) {
            slot_->lent = false;
            return;
        }
        std::allocator<T>().deallocate(values, n);
    }

    ArenaSlot* slot() const noexcept { return slot_; }

private:
    ArenaSlot* slot_ = nullptr;
};

template <typename T, typename U>
bool operator==(const SlotAllocator<T>& a, const SlotAllocator<U>& b) noexcept {
    return a.slot() == b.slot();
}
template <typename T, typename U>
bool operator!=(const SlotAllocator<T>& a, const SlotAllocator<U>& b) noexcept {
    return a.slot() != b.slot();
}

/// A vector of one set-up chunk: in its arena slot when the frame has one.
template <typename T>
using ChunkVector = std::vector<T, SlotAllocator<T>>;

/// Arenas up to this size get huge pages: at most this much of a small
/// frame's set-up buffers is resident without being written.
constexpr std::size_t kHugePageArenaBytes = std::size_t(64) << 20;

/// The slots of `kinds` buffers for each of `chunks` chunks, in one mapping
/// when they fit kHugePageArenaBytes.
class ChunkArena {
public:
    static constexpr std::size_t kKinds = 3;

    ChunkArena() = default;
    ChunkArena(const ChunkArena&) = delete;
    ChunkArena& operator=(const ChunkArena&) = delete;
    ~ChunkArena() { release(); }

    /// Slots for `chunks` chunks of bytes[k] bytes of each kind k: one
    /// mapping, advised MADV_HUGEPAGE, when they fit kHugePageArenaBytes;
    /// slots with no memory (heap vectors) otherwise. Every vector using the
    /// old slots must be gone.
    void reset(std::size_t chunks, const std::array<std::size_t, kKinds>& bytes);

    ArenaSlot* slot(std::size_t chunk, std::size_t kind) { return &slots_[chunk * kKinds + kind]; }
    std::size_t chunks() const { return slots_.size() / kKinds; }
    /// Whether the slots have memory of the arena's (huge pages: no map-ahead).
    bool mapped() const { return base_ != nullptr; }

private:
    void release();

    std::vector<ArenaSlot> slots_;
    void* base_ = nullptr;
    std::size_t bytes_ = 0;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_CHUNK_ARENA_HPP
