// Scans of a whole mesh for the first bad element (internal header): the
// checks every render makes of the caller's arrays (validation.cpp,
// api_checks.cpp), which on a large mesh read tens of megabytes per frame.
//
// Each block of elements is first asked, by a loop with no branch per
// element that GCC vectorises, whether it holds a bad one at all; only a
// block that does is searched element by element. Same answer as a loop
// from element 0 (the smallest bad index), so the same error message.
#ifndef PHONGRAST_SRC_MESH_SCANS_HPP
#define PHONGRAST_SRC_MESH_SCANS_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "phongrast/mesh.hpp"

namespace phongrast::detail {

/// The smallest i in [0, n) for which bad(i) holds, or n, in parallel over
/// blocks; any_bad(begin, end) says first whether [begin, end) holds one.
template <typename AnyBad, typename Bad>
std::size_t first_bad(std::size_t n, const AnyBad& any_bad, const Bad& bad) {
    const auto first_in = [&](std::size_t begin, std::size_t end) {
        if (!any_bad(begin, end)) return end;
        for (std::size_t i = begin; i < end; ++i) {
            if (bad(i)) return i;
        }
        return end;
    };
    constexpr std::size_t kBlock = 65536;
    if (n <= kBlock) return first_in(0, n);  // no task (nor oneTBB's start-up for a small mesh)
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, kBlock), n,
        [&](const tbb::blocked_range<std::size_t>& range, std::size_t found) {
            if (range.begin() >= found) return found;  // a bad element before this block is known
            const std::size_t end = std::min(range.end(), found);
            const std::size_t first = first_in(range.begin(), end);
            return first < end ? first : found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

/// The bits any_beyond() compares a float's magnitude with for "|a| <=
/// limit": those of the largest float at most `limit`, never above FLT_MAX
/// (so an infinite or NaN a never passes); all ones when nothing passes.
std::uint32_t passing_magnitude_bits(double limit);
/// passing_magnitude_bits(FLT_MAX): "a is finite".
std::uint32_t finite_magnitude_bits();

/// Whether a channel c of v[begin, end) fails |c| <= its limit, the limits
/// given per channel by passing_magnitude_bits().
bool any_beyond(const glm::vec3* v, std::size_t begin, std::size_t end, const std::uint32_t channel_bits[3]);
/// Whether a number of v[begin, end) is infinite or NaN.
bool any_nonfinite(const glm::dvec3* v, std::size_t begin, std::size_t end);
/// Whether an index of triangles[begin, end) is at least `vertices`.
bool any_index_at_least(const Triangle* triangles, std::size_t begin, std::size_t end, std::size_t vertices);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_MESH_SCANS_HPP
