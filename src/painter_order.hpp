// Painter's order (internal header): the contract's draw order, farthest
// mean camera depth first, ties in mesh order, of the triangles set-up
// found to draw something.
//
// The sort: one most-significant-digit radix pass spreads the drawn
// triangles over 2048 buckets by the leading bits of their keys (relative
// to the smallest key, so that no pass is spent on bits every key shares),
// and each bucket, small enough to stay in cache, is then sorted on its
// own; a bucket too large for that gets another radix pass first. The sort
// moves the 16-byte records themselves, so binning then reads them in order
// instead of jumping through an index. Ties are broken by the place of the
// triangle's draws in set-up's mesh-order output, so the result is the one
// order a stable sort gives, whatever the number of threads.
#ifndef PHONGRAST_SRC_PAINTER_ORDER_HPP
#define PHONGRAST_SRC_PAINTER_ORDER_HPP

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include "chunk_arena.hpp"
#include "draw_span.hpp"
#include "phongrast/mesh.hpp"
#include "progress_monitor.hpp"
#include "vertex_stage.hpp"

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

/// The contract's sort key of a triangle: the mean z_c (camera space) of its
/// three vertices, as a key whose ascending order is farthest first.
inline std::uint64_t painter_key(const Triangle& triangle, const FrameVector<ScreenVertex>& screen) {
    return farthest_first_key((screen[triangle[0]].depth + screen[triangle[1]].depth + screen[triangle[2]].depth) / 3.0);
}

/// A drawn triangle and its key: what the sort moves.
struct PaintRecord {
    std::uint64_t key;
    DrawSpan drawn;
};

namespace painter_sort {
constexpr int kDigitBits = 11;
constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
using Counts = std::array<std::uint32_t, kBuckets>;
}  // namespace painter_sort

/// painter_order()'s output and scratch, kept from frame to frame.
struct PainterOrderMemory {
    FrameVector<PaintRecord> sorted;   ///< the drawn triangles in painter's order (huge pages: huge_page_pool.hpp)
    FrameVector<PaintRecord> scratch;  ///< room to sort buckets: each task's largest bucket
    std::array<std::size_t, painter_sort::kBuckets> task_scratch_start{};  ///< per task of buckets: its scratch
    std::vector<painter_sort::Counts> group_counts;  ///< per group of set-up chunks: its records per bucket
    std::vector<std::uint64_t> group_min, group_max;  ///< per group: its smallest and largest key
    std::vector<std::size_t> chunk_offsets;  ///< where each chunk starts in `sorted` (mesh order), or each bucket (sorting)
};

/// A drawn triangle's place among triangles of equal depth: its index in
/// the caller's mesh when the pipeline renders it reordered (mesh_order.hpp).
using TieRank = std::function<std::uint32_t(const DrawSpan&)>;

/// Puts the drawn triangles of the first `chunks` set-up chunks into
/// memory.sorted in painter's order: farthest mean z_c first, equal depths
/// in mesh order, or by `tie_rank` when given (the caller's order of a
/// reordered mesh). Triangles that draw nothing are not sorted at all;
/// leaving them out changes no draw's place relative to another's. With
/// `sort` false (the order cannot change the picture) they stay in mesh
/// order. Reports progress through `progress`.
void painter_order(const std::vector<ChunkVector<DrawSpan>>& chunk_drawn,
                   const std::vector<ChunkVector<std::uint64_t>>& chunk_keys, std::size_t chunks, bool sort,
                   PainterOrderMemory& memory, ProgressMonitor& progress, const TieRank& tie_rank = nullptr);

/// The indices 0..n-1 of `depth` ordered as painter_order() orders
/// triangles of those mean depths: what std::stable_sort with
/// `depth[a] > depth[b]` returns. For tests.
std::vector<std::uint32_t> farthest_first_order(const std::vector<double>& depth);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PAINTER_ORDER_HPP
