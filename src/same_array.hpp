// Bit-for-bit comparison of two arrays, for the caches that keep a copy of
// what they were computed from (the assembled scene, computed normals): equal
// bytes give equal results, so -0 against +0 or another NaN payload merely
// recomputes, which is never wrong.
#ifndef PHONGRAST_SRC_SAME_ARRAY_HPP
#define PHONGRAST_SRC_SAME_ARRAY_HPP

#include <cstring>
#include <type_traits>
#include <vector>

namespace phongrast::detail {

/// The same size and bytes. An empty vector's data() may be null, which memcmp
/// must not be given even for no bytes (UBSan reports it).
template <typename T, typename AllocatorA, typename AllocatorB>
bool same_array(const std::vector<T, AllocatorA>& a, const std::vector<T, AllocatorB>& b) {
    static_assert(std::is_trivially_copyable_v<T>);
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SAME_ARRAY_HPP
