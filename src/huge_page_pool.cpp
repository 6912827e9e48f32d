#include "huge_page_pool.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>

#if defined(__linux__)
#include <pthread.h>
#include <sys/mman.h>
#endif

namespace phongrast::detail {
namespace {

std::size_t round_up(std::size_t value, std::size_t to) { return (value + to - 1) / to * to; }

#if defined(__linux__) && defined(MADV_HUGEPAGE)
bool linux_huge_pages_available() {
    // "always [madvise] never": advice gets huge pages unless `never` is chosen.
    std::FILE* file = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (file == nullptr) return false;  // a kernel without transparent huge pages
    char text[128] = {};
    const std::size_t read = std::fread(text, 1, sizeof text - 1, file);
    std::fclose(file);
    return read > 0 && std::strstr(text, "[never]") == nullptr;
}
void* linux_map(std::size_t bytes) {
    void* raw = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    return raw == MAP_FAILED ? nullptr : raw;
}
void linux_unmap(void* begin, std::size_t bytes) { munmap(begin, bytes); }
bool linux_advise(void* begin, std::size_t bytes) { return madvise(begin, bytes, MADV_HUGEPAGE) == 0; }
#else
bool linux_huge_pages_available() { return false; }
void* linux_map(std::size_t) { return nullptr; }
void linux_unmap(void*, std::size_t) {}
bool linux_advise(void*, std::size_t) { return false; }
#endif

}  // namespace

HugePagePool::System HugePagePool::system_calls() {
    return {linux_huge_pages_available, linux_map, linux_unmap, linux_advise};
}

HugePagePool::~HugePagePool() {
    for (const Mapping& mapping : mappings_) system_.unmap(mapping.base, mapping.bytes);
}

bool HugePagePool::available() {
    if (availability_ < 0) availability_ = system_.huge_pages_available() ? 1 : 0;
    return availability_ == 1;
}

bool HugePagePool::advise(void* begin, std::size_t bytes) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!available()) return false;
    if (system_.advise_huge_pages(begin, bytes)) return true;
    availability_ = 0;
    return false;
}

void* HugePagePool::allocate(std::size_t bytes) {
    if (bytes < kMinBlock || bytes > kMaxBlock) return nullptr;
    const std::size_t size = round_up(bytes, kBlockAlignment);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!available()) return nullptr;
    for (Mapping& mapping : mappings_) {
        if (void* block = take(mapping, size)) return block;
    }
    if (!map_another(size)) return nullptr;
    return take(mappings_.back(), size);
}

// First fit among the holes (the blocks of a Renderer's frame are few and
// live as long as it: holes appear when a buffer grows), else above `top`.
void* HugePagePool::take(Mapping& mapping, std::size_t size) {
    for (auto hole = mapping.holes.begin(); hole != mapping.holes.end(); ++hole) {
        if (hole->second < size) continue;
        const std::size_t offset = hole->first, left = hole->second - size;
        mapping.holes.erase(hole);
        if (left > 0) mapping.holes.emplace(offset + size, left);
        ++mapping.live;
        return mapping.base + offset;
    }
    if (mapping.bytes - mapping.top < size) return nullptr;
    const std::size_t offset = mapping.top;
    mapping.top += size;
    ++mapping.live;
    return mapping.base + offset;
}

bool HugePagePool::map_another(std::size_t size) {
    const std::size_t bytes = std::max(kMappingBytes, round_up(size, kHugePage));
    // A 2 MiB-aligned range: map one huge page more and trim both ends.
    void* raw = system_.map(bytes + kHugePage);
    if (raw == nullptr) return false;  // this block from the heap; the next one tries again
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = round_up(start, kHugePage);
    const std::uintptr_t end = start + bytes + kHugePage;
    if (aligned > start) system_.unmap(raw, aligned - start);
    if (end > aligned + bytes) system_.unmap(reinterpret_cast<void*>(aligned + bytes), end - (aligned + bytes));
    Mapping mapping;
    mapping.base = reinterpret_cast<char*>(aligned);
    mapping.bytes = bytes;
    // Without the advice the pages would be 4 KiB ones faulted one by one,
    // worse than the heap's (populated ahead): give up on the pool for good.
    if (!system_.advise_huge_pages(mapping.base, mapping.bytes)) {
        system_.unmap(mapping.base, mapping.bytes);
        availability_ = 0;
        return false;
    }
    mappings_.push_back(std::move(mapping));
    return true;
}

bool HugePagePool::deallocate(void* block, std::size_t bytes) noexcept {
    if (block == nullptr || bytes < kMinBlock || bytes > kMaxBlock) return false;
    const std::size_t size = round_up(bytes, kBlockAlignment);
    const char* address = static_cast<const char*>(block);
    const std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t m = 0; m < mappings_.size(); ++m) {
        Mapping& mapping = mappings_[m];
        if (address < mapping.base || address >= mapping.base + mapping.bytes) continue;
        if (--mapping.live == 0) {
            // The last block: the mapping goes back to the system, pages and all.
            system_.unmap(mapping.base, mapping.bytes);
            mappings_.erase(mappings_.begin() + static_cast<std::ptrdiff_t>(m));
            return true;
        }
        std::size_t offset = static_cast<std::size_t>(address - mapping.base), length = size;
        // Coalesce with the holes on either side, then give the top back.
        auto next = mapping.holes.lower_bound(offset);
        if (next != mapping.holes.end() && next->first == offset + length) {
            length += next->second;
            next = mapping.holes.erase(next);
        }
        if (next != mapping.holes.begin()) {
            auto previous = std::prev(next);
            if (previous->first + previous->second == offset) {
                offset = previous->first;
                length += previous->second;
                mapping.holes.erase(previous);
            }
        }
        if (offset + length == mapping.top) {
            mapping.top = offset;
        } else {
            mapping.holes.emplace(offset, length);
        }
        return true;
    }
    return false;
}

bool HugePagePool::owns(const void* address) const {
    const char* a = static_cast<const char*>(address);
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Mapping& mapping : mappings_) {
        if (a >= mapping.base && a < mapping.base + mapping.bytes) return true;
    }
    return false;
}

std::size_t HugePagePool::mappings() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return mappings_.size();
}

bool HugePagePool::disabled() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return availability_ == 0;
}

HugePagePool& huge_page_pool() {
    static HugePagePool* const pool = [] {
        auto* made = new HugePagePool();
#if defined(__linux__)
        // A fork while another thread holds the lock would leave the child
        // a lock nobody releases: hold it across the fork, as malloc does.
        pthread_atfork([] { huge_page_pool().lock_for_fork(); }, [] { huge_page_pool().unlock_after_fork(); },
                       [] { huge_page_pool().unlock_after_fork(); });
#endif
        return made;
    }();
    return *pool;
}

}  // namespace phongrast::detail
