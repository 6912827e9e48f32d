// Painter's order by radix sort (internal header).
//
// The contract sorts triangles farthest first by mean camera depth, ties in
// mesh order: a stable sort on a double key. A comparison sort costs
// O(n log n) comparisons with random access into the key array; a least
// significant digit radix sort of the keys mapped to unsigned integers costs
// a few sequential passes and is stable by construction, so it gives exactly
// std::stable_sort's order (with -0 taken as +0, as `>` does).
#ifndef PHONGRAST_SRC_DEPTH_SORT_HPP
#define PHONGRAST_SRC_DEPTH_SORT_HPP

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

namespace phongrast::detail {

/// An unsigned key whose ascending order is the descending order of finite
/// (or infinite) depths. (NaN never occurs: every input is validated finite.)
inline std::uint64_t farthest_first_key(double depth) {
    if (depth == 0.0) depth = 0.0;  // -0 and +0 compare equal: one key
    std::uint64_t bits;
    std::memcpy(&bits, &depth, sizeof bits);
    // Ascending order of doubles: flip every bit of negatives, only the sign of the others.
    const std::uint64_t ascending = (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t(1) << 63);
    return ~ascending;
}

/// Indices 0..n-1 ordered by descending depth, equal depths in index order:
/// what std::stable_sort with `depth[a] > depth[b]` returns.
inline std::vector<std::uint32_t> farthest_first_order(const std::vector<double>& depth) {
    const std::size_t n = depth.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n < 256) {
        std::stable_sort(order.begin(), order.end(), [&depth](std::uint32_t a, std::uint32_t b) {
            return depth[a] > depth[b];
        });
        return order;
    }
    constexpr int kDigitBits = 11;
    constexpr int kPasses = (64 + kDigitBits - 1) / kDigitBits;
    constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
    std::vector<std::uint64_t> keys(n), keys_scratch(n);
    std::vector<std::uint32_t> order_scratch(n);
    std::vector<std::array<std::uint32_t, kBuckets>> counts(kPasses);
    for (auto& c : counts) c.fill(0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t key = farthest_first_key(depth[i]);
        keys[i] = key;
        for (int pass = 0; pass < kPasses; ++pass) ++counts[pass][(key >> (pass * kDigitBits)) & (kBuckets - 1)];
    }
    for (int pass = 0; pass < kPasses; ++pass) {
        std::array<std::uint32_t, kBuckets>& count = counts[pass];
        // A digit every key shares leaves the order as it is: skip the pass.
        if (std::any_of(count.begin(), count.end(), [n](std::uint32_t c) { return c == n; })) continue;
        std::uint32_t start = 0;
        for (std::uint32_t& c : count) {
            const std::uint32_t bucket_size = c;
            c = start;
            start += bucket_size;
        }
        const int shift = pass * kDigitBits;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t slot = count[(keys[i] >> shift) & (kBuckets - 1)]++;
            keys_scratch[slot] = keys[i];
            order_scratch[slot] = order[i];
        }
        keys.swap(keys_scratch);
        order.swap(order_scratch);
    }
    return order;
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_DEPTH_SORT_HPP
