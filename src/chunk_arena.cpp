#include "chunk_arena.hpp"

#include <cstdint>
#include <stdexcept>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace phongrast::detail {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kSlotAlignment = 4096;  // slots start on a page: a slot's unwritten tail is its own

std::size_t round_up(std::size_t value, std::size_t to) { return (value + to - 1) / to * to; }

}  // namespace

void ChunkArena::reset(std::size_t chunks, const std::array<std::size_t, kKinds>& bytes) {
    for (const ArenaSlot& slot : slots_) {
        if (slot.lent) throw std::logic_error("ChunkArena::reset: a slot is still lent");
    }
    release();
    slots_.assign(chunks * kKinds, ArenaSlot{});
    std::size_t per_chunk = 0;
    for (std::size_t size : bytes) per_chunk += round_up(size, kSlotAlignment);
    const std::size_t total = round_up(chunks * per_chunk, kHugePage);
    if (chunks == 0 || total > kHugePageArenaBytes) return;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // A 2 MiB-aligned range of `total` bytes: map one huge page more and trim both ends.
    void* raw = mmap(nullptr, total + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return;  // heap vectors, as for a large frame
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = round_up(start, kHugePage);
    if (aligned > start) munmap(raw, aligned - start);
    const std::uintptr_t end = start + total + kHugePage;
    if (end > aligned + total) munmap(reinterpret_cast<void*>(aligned + total), end - (aligned + total));
    base_ = reinterpret_cast<void*>(aligned);
    bytes_ = total;
    // Only a hint: where transparent huge pages are off ("never") the pages
    // are 4 KiB ones, faulted in on first write. Not mapped ahead with
    // MADV_POPULATE_WRITE: here that took longer than the 2 MiB page faults
    // it saves (64 MiB: 180-200 ms against 6-11 ms for the first writes;
    // 14 MiB: 1.5 ms against 1.4 ms; 4 KiB pages populated: 4.5 ms, and
    // 18 ms more for the first writes).
    madvise(base_, bytes_, MADV_HUGEPAGE);
#else
    return;
#endif
    char* next = static_cast<char*>(base_);
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
        for (std::size_t kind = 0; kind < kKinds; ++kind) {
            ArenaSlot& s = *slot(chunk, kind);
            s.base = next;
            s.bytes = bytes[kind];
            next += round_up(bytes[kind], kSlotAlignment);
        }
    }
}

void ChunkArena::release() {
#if defined(__linux__)
    if (base_ != nullptr) munmap(base_, bytes_);
#endif
    base_ = nullptr;
    bytes_ = 0;
    slots_.clear();
}

}  // namespace phongrast::detail
