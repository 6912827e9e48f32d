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

/// Fills `order` with the indices 0..n-1 ordered by descending depth, equal
/// depths in index order: what std::stable_sort with `depth[a] > depth[b]`
/// returns. Allocates nothing once `order` and `scratch` have held as many.
/// `poll`, if given, is called after each block of work (from whichever
/// thread did it): the renderer's progress reports.
inline void farthest_first_order(const std::vector<double>& depth, std::vector<std::uint32_t>& order,
                                 DepthSortScratch& scratch, const std::function<void()>& poll = nullptr) {
    using namespace depth_sort;
    const std::size_t n = depth.size();
    order.resize(n);
    if (n < 256) {
        // Insertion sort: stable, and (unlike std::stable_sort) no temporary buffer.
        for (std::size_t i = 0; i < n; ++i) {
            std::size_t j = i;
            for (; j > 0 && depth[order[j - 1]] < depth[i]; --j) order[j] = order[j - 1];
            order[j] = static_cast<std::uint32_t>(i);
        }
        return;
    }
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    const auto block_range = [n](std::size_t block) {
        return std::pair<std::size_t, std::size_t>(block * kBlock, std::min(n, (block + 1) * kBlock));
    };

    std::vector<std::uint64_t>& keys = scratch.keys;
    std::vector<std::uint64_t>& keys_scratch = scratch.keys_scratch;
    std::vector<std::uint32_t>& order_scratch = scratch.order_scratch;
    keys.resize(n);
    keys_scratch.resize(n);
    order_scratch.resize(n);
    std::vector<std::array<Counts, kPasses>>& first_counts = scratch.first_counts;
    first_counts.resize(blocks);
    // The first pass over the depths makes the keys and every pass's digit
    // counts per block; a digit every key shares leaves the order as it is.
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        std::array<Counts, kPasses>& counts = first_counts[block];
        for (Counts& c : counts) c.fill(0);
        const auto [begin, end] = block_range(block);
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint64_t key = farthest_first_key(depth[i]);
            keys[i] = key;
            order[i] = static_cast<std::uint32_t>(i);
            for (int pass = 0; pass < kPasses; ++pass) ++counts[pass][(key >> (pass * kDigitBits)) & (kBuckets - 1)];
        }
        if (poll) poll();
    });

    std::vector<Counts>& block_counts = scratch.block_counts;
    block_counts.resize(blocks);
    bool first_pass_done = false;
    for (int pass = 0; pass < kPasses; ++pass) {
        const int shift = pass * kDigitBits;
        Counts total{};
        for (std::size_t block = 0; block < blocks; ++block) {
            for (std::size_t b = 0; b < kBuckets; ++b) total[b] += first_counts[block][pass][b];
        }
        if (std::any_of(total.begin(), total.end(), [n](std::uint32_t c) { return c == n; })) continue;
        // The keys' blocks moved in earlier passes: count this pass's digits afresh.
        if (first_pass_done) {
            tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
                Counts& c = block_counts[block];
                c.fill(0);
                const auto [begin, end] = block_range(block);
                for (std::size_t i = begin; i < end; ++i) ++c[(keys[i] >> shift) & (kBuckets - 1)];
                if (poll) poll();
            });
        } else {
            for (std::size_t block = 0; block < blocks; ++block) block_counts[block] = first_counts[block][pass];
        }
        // Bucket-major offsets: bucket b's slice, block after block.
        std::uint32_t start = 0;
        for (std::size_t b = 0; b < kBuckets; ++b) {
            for (std::size_t block = 0; block < blocks; ++block) {
                const std::uint32_t size = block_counts[block][b];
                block_counts[block][b] = start;
                start += size;
            }
        }
        tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
            Counts& cursor = block_counts[block];
            const auto [begin, end] = block_range(block);
            for (std::size_t i = begin; i < end; ++i) {
                const std::uint32_t slot = cursor[(keys[i] >> shift) & (kBuckets - 1)]++;
                keys_scratch[slot] = keys[i];
                order_scratch[slot] = order[i];
            }
            if (poll) poll();
        });
        keys.swap(keys_scratch);
        order.swap(order_scratch);
        first_pass_done = true;
    }
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
