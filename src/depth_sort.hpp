// Painter's order by radix sort (internal header).
//
// The contract sorts triangles farthest first by mean camera depth, ties in
// mesh order: a stable sort on a double key. A comparison sort costs
// O(n log n) comparisons with random access into the key array; a least
// significant digit radix sort of the keys mapped to unsigned integers costs
// a few sequential passes and is stable by construction, so it gives exactly
// std::stable_sort's order (with -0 taken as +0, as `>` does).
//
// Each pass runs in parallel over fixed blocks of the array: every block
// counts its digits, the blocks' slices of every bucket are laid out block
// after block, and each block scatters into its own slices in order. The
// result does not depend on the number of threads.
#ifndef PHONGRAST_SRC_DEPTH_SORT_HPP
#define PHONGRAST_SRC_DEPTH_SORT_HPP

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

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

namespace depth_sort {
constexpr int kDigitBits = 11;
constexpr int kPasses = (64 + kDigitBits - 1) / kDigitBits;
constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
constexpr std::size_t kBlock = std::size_t(1) << 16;
using Counts = std::array<std::uint32_t, kBuckets>;
}  // namespace depth_sort

/// The radix sort's working memory, kept between frames by a Renderer.
struct DepthSortScratch {
    std::vector<std::uint64_t> keys, keys_scratch;
    std::vector<std::uint32_t> order_scratch;
    std::vector<std::array<depth_sort::Counts, depth_sort::kPasses>> first_counts;
    std::vector<depth_sort::Counts> block_counts;
};

namespace depth_sort {

inline std::pair<std::size_t, std::size_t> block_range(std::size_t n, std::size_t block) {
    return {block * kBlock, std::min(n, (block + 1) * kBlock)};
}

/// Small inputs: insertion sort on the keys, stable, and (unlike
/// std::stable_sort) no temporary buffer.
inline void insertion_order(const std::vector<std::uint64_t>& keys, std::size_t n, std::vector<std::uint32_t>& order) {
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t j = i;
        for (; j > 0 && keys[order[j - 1]] > keys[i]; --j) order[j] = order[j - 1];
        order[j] = static_cast<std::uint32_t>(i);
    }
}

/// The first pass over the keys: the identity order, and every pass's digit
/// counts per block.
inline void count_digits(std::size_t n, std::size_t blocks, std::vector<std::uint32_t>& order,
                         DepthSortScratch& scratch, const std::function<void()>& poll) {
    scratch.keys_scratch.resize(n);
    scratch.order_scratch.resize(n);
    scratch.first_counts.resize(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        std::array<Counts, kPasses>& counts = scratch.first_counts[block];
        for (Counts& c : counts) c.fill(0);
        const auto [begin, end] = block_range(n, block);
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint64_t key = scratch.keys[i];
            order[i] = static_cast<std::uint32_t>(i);
            for (int pass = 0; pass < kPasses; ++pass) ++counts[pass][(key >> (pass * kDigitBits)) & (kBuckets - 1)];
        }
        if (poll) poll();
    });
}

/// One stable pass on the digit at `shift`. scratch.block_counts holds each
/// block's counts of that digit; they become its cursors.
inline void scatter_pass(int shift, std::size_t blocks, std::vector<std::uint32_t>& order, DepthSortScratch& scratch,
                         const std::function<void()>& poll) {
    // Bucket-major offsets: bucket b's slice, block after block.
    std::uint32_t start = 0;
    for (std::size_t b = 0; b < kBuckets; ++b) {
        for (std::size_t block = 0; block < blocks; ++block) {
            const std::uint32_t size = scratch.block_counts[block][b];
            scratch.block_counts[block][b] = start;
            start += size;
        }
    }
    const std::vector<std::uint64_t>& keys = scratch.keys;
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        Counts& cursor = scratch.block_counts[block];
        const auto [begin, end] = block_range(order.size(), block);
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t slot = cursor[(keys[i] >> shift) & (kBuckets - 1)]++;
            scratch.keys_scratch[slot] = keys[i];
            scratch.order_scratch[slot] = order[i];
        }
        if (poll) poll();
    });
    scratch.keys.swap(scratch.keys_scratch);
    order.swap(scratch.order_scratch);
}

}  // namespace depth_sort

/// Fills `order` with the indices 0..n-1 of scratch.keys (which must hold n
/// farthest_first_key()s) in ascending key order, equal keys in index order.
/// Allocates nothing once `order` and `scratch` have held as many. `poll`,
/// if given, is called after each block of work, from whichever thread did
/// it (the renderer's progress reports).
inline void order_by_keys(std::size_t n, std::vector<std::uint32_t>& order, DepthSortScratch& scratch,
                          const std::function<void()>& poll = nullptr) {
    using namespace depth_sort;
    order.resize(n);
    if (n < 256) {
        insertion_order(scratch.keys, n, order);
        return;
    }
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    count_digits(n, blocks, order, scratch, poll);
    scratch.block_counts.resize(blocks);
    bool first_pass_done = false;
    for (int pass = 0; pass < kPasses; ++pass) {
        const int shift = pass * kDigitBits;
        Counts total{};
        for (std::size_t block = 0; block < blocks; ++block) {
            for (std::size_t b = 0; b < kBuckets; ++b) total[b] += scratch.first_counts[block][pass][b];
        }
        // A digit every key shares leaves the order as it is.
        if (std::any_of(total.begin(), total.end(), [n](std::uint32_t c) { return c == n; })) continue;
        if (first_pass_done) {
            // The keys moved in earlier passes: count this pass's digits afresh.
            tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
                Counts& c = scratch.block_counts[block];
                c.fill(0);
                const auto [begin, end] = block_range(n, block);
                for (std::size_t i = begin; i < end; ++i) ++c[(scratch.keys[i] >> shift) & (kBuckets - 1)];
                if (poll) poll();
            });
        } else {
            for (std::size_t block = 0; block < blocks; ++block) scratch.block_counts[block] = scratch.first_counts[block][pass];
        }
        scatter_pass(shift, blocks, order, scratch, poll);
        first_pass_done = true;
    }
}

/// Fills `order` with the indices 0..n-1 ordered by descending depth, equal
/// depths in index order: what std::stable_sort with `depth[a] > depth[b]`
/// returns.
inline void farthest_first_order(const std::vector<double>& depth, std::vector<std::uint32_t>& order,
                                 DepthSortScratch& scratch, const std::function<void()>& poll = nullptr) {
    scratch.keys.resize(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i) scratch.keys[i] = farthest_first_key(depth[i]);
    order_by_keys(depth.size(), order, scratch, poll);
}

/// farthest_first_order() into a new vector.
inline std::vector<std::uint32_t> farthest_first_order(const std::vector<double>& depth) {
    std::vector<std::uint32_t> order;
    DepthSortScratch scratch;
    farthest_first_order(depth, order, scratch);
    return order;
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_DEPTH_SORT_HPP
