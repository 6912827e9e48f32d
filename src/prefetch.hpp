// Cache hints for the stages that walk memory in painter's order (internal header).
#ifndef PHONGRAST_SRC_PREFETCH_HPP
#define PHONGRAST_SRC_PREFETCH_HPP

#include <cstddef>

namespace phongrast::detail {

/// How many triangles ahead set-up and the fill ask for the memory they will read.
constexpr std::size_t kPrefetchAhead = 8;

/// A hint to start loading *address into the cache (no effect on results).
inline void prefetch_address(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

/// Every cache line of *object.
template <typename T>
void prefetch_object(const T* object) {
    const char* bytes = reinterpret_cast<const char*>(object);
    for (std::size_t offset = 0; offset < sizeof(T); offset += 64) prefetch_address(bytes + offset);
    prefetch_address(bytes + sizeof(T) - 1);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PREFETCH_HPP
