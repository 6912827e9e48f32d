// Exact triangle coverage in fixed point (internal header).
//
// Conventions (docs/scene-format.md, "Camera"), reproduced here because
// every rule below depends on them:
//   * Continuous pixel coordinates: x = column, y = row, rows grow downward.
//   * Pixel (i, j) is sampled at its centre (j + 0.5, i + 0.5).
//   * Vertices are snapped to 1/256 pixel (kSubpixelBits = 8), once. After
//     that, coverage uses only 64-bit integers, so it is exact and does not
//     depend on the order in which triangles or vertices are processed.
//   * A centre exactly on an edge belongs to the triangle for which that edge
//     is a top edge (horizontal, triangle below it) or a left edge. The rule
//     is applied as a bias of one on the integer edge value (as Mesa's
//     llvmpipe does): on a shared edge exactly one of the two neighbours owns
//     the centre, so shared edges leave no gap and no double cover.
//
// Edge function of the directed edge a->b at p (twice the signed area of a, b, p):
//   E_ab(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)
// Triangles are reordered so that E_01(v2) > 0; then the interior is where
// all three edge functions are positive, a top edge has dy == 0 and dx > 0,
// and a left edge has dy < 0.
//
// Overflow budget: callers keep snapped coordinates within +/- 2^28 (the
// renderer clips to a guard band of 2^18 pixels around images of at most
// 2^19 pixels a side), so deltas are below 2^29, products below 2^58, and
// every edge value and step below 2^62.
#ifndef PHONGRAST_SRC_RASTER_HPP
#define PHONGRAST_SRC_RASTER_HPP

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstdlib>

// Rows of a small triangle are solved by a mask of their centres' edge
// tests, four at a time in SSE2 (x86-64's baseline; a kernel compiled for
// AVX2 inlines the same instructions). Elsewhere rows are walked or solved
// one edge at a time, with the same results.
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define PHONGRAST_ROW_MASKS 1
#include <emmintrin.h>
#else
#define PHONGRAST_ROW_MASKS 0
#endif

/// For the per-triangle code of the fill: inlined even into a kernel compiled
/// for another instruction set (a baseline function may always be inlined
/// into an AVX2 one), where GCC's size heuristics would otherwise keep a call.
/// PHONGRAST_INLINE_LAMBDA does the same for a lambda, written after its
/// parameters; PHONGRAST_NOINLINE keeps a rarely taken path out of the caller.
#if defined(__GNUC__) || defined(__clang__)
#define PHONGRAST_ALWAYS_INLINE inline __attribute__((always_inline))
#define PHONGRAST_INLINE_LAMBDA __attribute__((always_inline))
#define PHONGRAST_NOINLINE __attribute__((noinline))
#else
#define PHONGRAST_ALWAYS_INLINE inline
#define PHONGRAST_INLINE_LAMBDA
#define PHONGRAST_NOINLINE
#endif

namespace phongrast::detail {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixelScale = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;
/// Largest image side in samples (kMaxImageSide pixels x 16 samples) the fixed-point budget allows.
constexpr int kMaxSampleSide = 1 << 19;
/// Geometry is clipped to this many pixels beyond each image border.
constexpr double kGuardBandPixels = double(1 << 18);
constexpr std::int64_t kMaxSnappedMagnitude = std::int64_t(1) << 28;

struct SnappedPoint {
    std::int64_t x = 0;  ///< column * 256, rounded to nearest
    std::int64_t y = 0;  ///< row * 256, rounded to nearest
};

/// Rounds to the nearest 1/256 pixel (ties to even, the default rounding
/// mode; llrint compiles to one instruction with -fno-math-errno, llround to a call).
inline SnappedPoint snap(double column, double row) {
    return {static_cast<std::int64_t>(std::llrint(column * double(kSubpixelScale))),
            static_cast<std::int64_t>(std::llrint(row * double(kSubpixelScale)))};
}

inline std::int64_t edge_value(const SnappedPoint& a, const SnappedPoint& b, std::int64_t px,
                               std::int64_t py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

/// floor(numerator / denominator) for denominator > 0.
inline std::int64_t floor_div(std::int64_t numerator, std::int64_t denominator) {
    std::int64_t quotient = numerator / denominator;
    if ((numerator % denominator != 0) && (numerator < 0)) --quotient;
    return quotient;
}

/// Smallest k with step * k >= need, for step > 0: ceil(need / step). The
/// quotient is estimated in double (one fast division instead of a slow
/// 64-bit integer one) and then corrected with exact integer products, so the
/// result is exact.
inline std::int64_t first_at_least(std::int64_t need, std::int64_t step) {
    std::int64_t k =
        static_cast<std::int64_t>(std::ceil(static_cast<double>(need) / static_cast<double>(step)));
    while (step * k < need) ++k;
    while (step * (k - 1) >= need) --k;
    return k;
}

/// Largest k with step * k <= limit, for step > 0: floor(limit / step), exact likewise.
inline std::int64_t last_at_most(std::int64_t limit, std::int64_t step) {
    std::int64_t k =
        static_cast<std::int64_t>(std::floor(static_cast<double>(limit) / static_cast<double>(step)));
    while (step * k > limit) --k;
    while (step * (k + 1) <= limit) ++k;
    return k;
}

/// A snapped point stored in half the space: |coordinates| <= 2^28 fit 32 bits.
struct CompactPoint {
    std::int32_t x = 0, y = 0;
    CompactPoint() = default;
    CompactPoint(const SnappedPoint& p) : x(static_cast<std::int32_t>(p.x)), y(static_cast<std::int32_t>(p.y)) {}
    operator SnappedPoint() const { return {x, y}; }
};

/// A triangle snapped for coverage: its vertices ordered so that
/// E_01(v2) > 0 and the pixel centres its bounding box may hold. All that
/// coverage and the fill's weights need: the renderer stores one per drawn
/// triangle, so it is kept to 40 bytes, and the area is recomputed (exactly)
/// rather than stored.
struct SnappedTriangle {
    CompactPoint v[3];
    int row_min = 0, row_max = -1;        ///< pixel rows whose centres may be covered
    int column_min = 0, column_max = -1;  ///< pixel columns likewise

    /// E_01(v2) = twice the area in (1/256 px)^2: > 0 once set up, 0 for a
    /// degenerate triangle. The same integer set-up tested, so the same
    /// inverse in the fill.
    std::int64_t area2() const { return edge_value(v[0], v[1], v[2].x, v[2].y); }
};

/// setup_coverage()'s result: the snapped triangle and how its vertices were ordered.
struct CoverageTriangle : SnappedTriangle {
    bool swapped = false;  ///< true if input vertices 1 and 2 were exchanged
};

/// Sets up coverage for snapped vertices a, b, c inside an image of rows x
/// columns. Returns false if the triangle has zero area (it covers no centre;
/// the vertices are stored all the same, so area2() tells this case apart)
/// or no pixel centre of the image lies in its bounding box.
inline bool setup_coverage(const SnappedPoint& a, const SnappedPoint& b, const SnappedPoint& c, int rows,
                           int columns, CoverageTriangle& out) {
    assert(std::abs(a.x) <= kMaxSnappedMagnitude && std::abs(a.y) <= kMaxSnappedMagnitude);
    assert(std::abs(b.x) <= kMaxSnappedMagnitude && std::abs(b.y) <= kMaxSnappedMagnitude);
    assert(std::abs(c.x) <= kMaxSnappedMagnitude && std::abs(c.y) <= kMaxSnappedMagnitude);
    const std::int64_t area2 = edge_value(a, b, c.x, c.y);
    out.swapped = area2 < 0;
    out.v[0] = a;
    out.v[1] = out.swapped ? c : b;
    out.v[2] = out.swapped ? b : c;
    if (area2 == 0) return false;

    const std::int64_t x_min = std::min({a.x, b.x, c.x}), x_max = std::max({a.x, b.x, c.x});
    const std::int64_t y_min = std::min({a.y, b.y, c.y}), y_max = std::max({a.y, b.y, c.y});
    // Centre of pixel j is at 256 j + 128: the covered range is the j with
    // x_min <= 256 j + 128 <= x_max.
    const std::int64_t column_lo = -floor_div(-(x_min - kHalfPixel), kSubpixelScale);
    const std::int64_t column_hi = floor_div(x_max - kHalfPixel, kSubpixelScale);
    const std::int64_t row_lo = -floor_div(-(y_min - kHalfPixel), kSubpixelScale);
    const std::int64_t row_hi = floor_div(y_max - kHalfPixel, kSubpixelScale);
    out.column_min = static_cast<int>(std::max<std::int64_t>(column_lo, 0));
    out.column_max = static_cast<int>(std::min<std::int64_t>(column_hi, columns - 1));
    out.row_min = static_cast<int>(std::max<std::int64_t>(row_lo, 0));
    out.row_max = static_cast<int>(std::min<std::int64_t>(row_hi, rows - 1));
    return out.row_min <= out.row_max && out.column_min <= out.column_max;
}

/// The covered pixel centres of one row of a triangle: they are contiguous
/// (the triangle is convex). e[i] is the unbiased edge value opposite vertex
/// i at the first of them, so e[i] / area2() is vertex i's screen-space
/// barycentric weight there.
struct CoveredSpan {
    int row;
    int first_column;
    int count;
    std::int64_t e[3];
};

/// A triangle's edge functions set up for the rows [row_begin, row_end) of
/// its bounding box, to find its covered centres row by row (solve()) or, for
/// a bounding box of at most 2 x 2 centres, all at once (tiny_spans()). The
/// member functions are inline and take no callback, so a fill kernel
/// compiled for another instruction set inlines them into its own loop.
///
/// The values kept are biased by the top-left rule: a centre is covered when
/// all three biased values are >= 0, i.e. when their bitwise OR is.
class CoveredRows {
public:
    /// Rows of a bounding box of fewer columns than this may be solved by
    /// masks (solves_rows_by_masks()).
    static constexpr std::int64_t kMaskColumns = 32;
    /// Else rows of a box of fewer columns than this are walked centre by
    /// centre (cheaper than solving), wider ones solved one edge at a time.
    static constexpr std::int64_t kWalkedSpanColumns = 16;

    PHONGRAST_ALWAYS_INLINE CoveredRows(const SnappedTriangle& t, int row_begin, int row_end)
        : first_row_(std::max(row_begin, t.row_min)),
          last_row_(std::min(row_end - 1, t.row_max)),
          column_min_(t.column_min),
          span_columns_(t.column_max - t.column_min) {
        const std::int64_t origin_x = std::int64_t(t.column_min) * kSubpixelScale + kHalfPixel;
        const std::int64_t origin_y = std::int64_t(first_row_) * kSubpixelScale + kHalfPixel;
        // The edge opposite vertex i runs from vertex i+1 to vertex i+2.
        const SnappedPoint v0 = t.v[0], v1 = t.v[1], v2 = t.v[2];
        set_up_edge(0, v1, v2, origin_x, origin_y);
        set_up_edge(1, v2, v0, origin_x, origin_y);
        set_up_edge(2, v0, v1, origin_x, origin_y);
#if PHONGRAST_ROW_MASKS
        if (span_columns_ < kMaskColumns && !tiny() && !empty()) set_up_masks();
#endif
    }

    /// No row of the range meets the bounding box.
    bool empty() const { return first_row_ > last_row_; }
    int first_row() const { return first_row_; }
    int last_row() const { return last_row_; }
    /// The change of each edge value per column.
    const std::int64_t* step() const { return step_column_; }
    /// Rows are solved by masks of their centres (covered_columns()): a box
    /// under kMaskColumns columns whose edge values fit 32 bits.
    bool solves_rows_by_masks() const {
#if PHONGRAST_ROW_MASKS
        return mask_groups_ > 0;
#else
        return false;
#endif
    }
    /// At most two rows and two columns of centres: tiny_spans() applies.
    bool tiny() const { return last_row_ - first_row_ < 2 && span_columns_ < 2; }

    /// The covered centres of `row` (in [first_row(), last_row()]) into
    /// `span`; false if there are none. The span is solved exactly from the
    /// three edge functions, so thin slivers cost their length, not their
    /// bounding box.
    PHONGRAST_ALWAYS_INLINE bool solve(int row, CoveredSpan& span) const {
        std::int64_t value[3];
        const std::int64_t row_offset = row - first_row_;
        for (int i = 0; i < 3; ++i) value[i] = biased_[i] + step_row_[i] * row_offset;
        std::int64_t k_lo = 0, k_hi = span_columns_;
#if PHONGRAST_ROW_MASKS
        if (mask_groups_ > 0) {
            const std::uint32_t covered = covered_columns(value);
            if (covered == 0) return false;
            k_lo = __builtin_ctz(covered);
            k_hi = 31 - __builtin_clz(covered);
        } else
#endif
        if (span_columns_ < kWalkedSpanColumns) {
            // Narrow: walk the row with incremental edge values; cheaper than dividing.
            std::int64_t e0 = value[0], e1 = value[1], e2 = value[2];
            std::int64_t k = 0;
            for (; k <= span_columns_;
                 ++k, e0 += step_column_[0], e1 += step_column_[1], e2 += step_column_[2]) {
                if ((e0 | e1 | e2) >= 0) break;
            }
            if (k > span_columns_) return false;
            k_lo = k;
            for (++k, e0 += step_column_[0], e1 += step_column_[1], e2 += step_column_[2]; k <= span_columns_;
                 ++k, e0 += step_column_[0], e1 += step_column_[1], e2 += step_column_[2]) {
                if ((e0 | e1 | e2) < 0) break;
            }
            k_hi = k - 1;
        } else {
            for (int i = 0; i < 3; ++i) {
                // The integer k in [k_lo, k_hi] with value + step * k >= 0.
                const std::int64_t need = -value[i];
                if (step_column_[i] > 0) {
                    k_lo = std::max(k_lo, first_at_least(need, step_column_[i]));
                } else if (step_column_[i] < 0) {
                    k_hi = std::min(k_hi, last_at_most(-need, -step_column_[i]));
                } else if (need > 0) {
                    k_hi = -1;
                }
            }
            if (k_lo > k_hi) return false;
        }
        write_span(row, k_lo, k_hi, value, span);
        return true;
    }

#if PHONGRAST_ROW_MASKS
    /// solve() for rows first_row(), first_row() + 1, ... in turn, when
    /// solves_rows_by_masks(): the rows' edge values carried from row to row
    /// (64-bit values and the masks' 32-bit lanes, which set_up_masks() found
    /// to hold every value of the box exactly) instead of computed from the
    /// first row by a multiplication per edge. The same spans as solve().
    class MaskedRows {
    public:
        PHONGRAST_ALWAYS_INLINE explicit MaskedRows(const CoveredRows& rows) : rows_(rows) {
            for (int i = 0; i < 3; ++i) {
                value_[i] = rows.biased_[i];
                lanes_[i] = _mm_add_epi32(_mm_set1_epi32(static_cast<std::int32_t>(value_[i])), rows.lane_offset_[i]);
                lanes_row_step_[i] = _mm_set1_epi32(static_cast<std::int32_t>(rows.step_row_[i]));
            }
        }
        /// The current row's span as solve(row, span) finds it (false: none), then moves to the next row.
        PHONGRAST_ALWAYS_INLINE bool solve_and_advance(int row, CoveredSpan& span) {
            const std::uint32_t covered = rows_.covered_columns_from(lanes_);
            const std::int64_t value[3] = {value_[0], value_[1], value_[2]};
            for (int i = 0; i < 3; ++i) {
                value_[i] += rows_.step_row_[i];
                lanes_[i] = _mm_add_epi32(lanes_[i], lanes_row_step_[i]);
            }
            if (covered == 0) return false;
            rows_.write_span(row, __builtin_ctz(covered), 31 - __builtin_clz(covered), value, span);
            return true;
        }

    private:
        const CoveredRows& rows_;
        std::int64_t value_[3];
        __m128i lanes_[3];           ///< the row's values at the box's columns 0-3
        __m128i lanes_row_step_[3];  ///< their change per row
    };
#endif

    /// tiny() only: tests the (at most four) centres of the bounding box
    /// directly, without solving rows. Writes the covered spans, in row
    /// order, to spans[0..1] and returns their number: exactly what solve()
    /// finds row by row.
    PHONGRAST_ALWAYS_INLINE int tiny_spans(CoveredSpan* spans) const {
        assert(tiny());
        int found = tiny_row(first_row_, biased_, spans);
        if (last_row_ > first_row_) {
            const std::int64_t below[3] = {biased_[0] + step_row_[0], biased_[1] + step_row_[1],
                                           biased_[2] + step_row_[2]};
            found += tiny_row(last_row_, below, spans + found);
        }
        return found;
    }

private:
    /// A row's span of covered columns k_lo..k_hi of the box, the row's biased values at its first column `value`.
    PHONGRAST_ALWAYS_INLINE void write_span(int row, std::int64_t k_lo, std::int64_t k_hi, const std::int64_t* value,
                                            CoveredSpan& span) const {
        span.row = row;
        span.first_column = column_min_ + static_cast<int>(k_lo);
        span.count = static_cast<int>(k_hi - k_lo + 1);
        for (int i = 0; i < 3; ++i) span.e[i] = value[i] + step_column_[i] * k_lo + threshold_[i];
    }

    PHONGRAST_ALWAYS_INLINE void set_up_edge(int i, const SnappedPoint& a, const SnappedPoint& b,
                                             std::int64_t origin_x, std::int64_t origin_y) {
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        // Top-left edges (top: dy == 0 and dx > 0; left: dy < 0) own the centres on
        // them; the others (dy > 0, or dy == 0 and dx <= 0: 2 dy - [dx > 0] >= 0) need 1.
        threshold_[i] = std::int64_t(2 * dy - std::int64_t(dx > 0) >= 0);
        biased_[i] = edge_value(a, b, origin_x, origin_y) - threshold_[i];
        step_column_[i] = -dy * kSubpixelScale;
        step_row_[i] = dx * kSubpixelScale;
    }

#if PHONGRAST_ROW_MASKS
    /// Enables covered_columns() when every edge value it would compute (the
    /// box's rows in range, columns 0 to the last of its groups of four)
    /// fits 32 bits, so that the 32-bit lanes give exactly the 64-bit
    /// values' signs; else rows are solved as before.
    void set_up_masks() {
        const int groups = static_cast<int>(span_columns_ / 4 + 1);
        const std::int64_t last_lane = 4 * groups - 1, last_row = last_row_ - first_row_;
        for (int i = 0; i < 3; ++i) {
            // The edge function is linear, so no value in the box exceeds this.
            const std::int64_t bound =
                std::abs(biased_[i]) + std::abs(step_row_[i]) * last_row + std::abs(step_column_[i]) * last_lane;
            if (bound > INT32_MAX) return;
        }
        for (int i = 0; i < 3; ++i) {
            // Products in 64 bits: 4 x step may not fit 32 when a box has one group (it is then
            // only added after the last group, in lanes that wrap harmlessly and are not read).
            const std::int64_t step = step_column_[i];
            lane_offset_[i] = _mm_setr_epi32(0, static_cast<std::int32_t>(step), static_cast<std::int32_t>(2 * step),
                                             static_cast<std::int32_t>(3 * step));
            group_step_[i] = _mm_set1_epi32(static_cast<std::int32_t>(4 * step));
        }
        valid_columns_ = span_columns_ == 31 ? ~std::uint32_t(0)
                                              : (std::uint32_t(1) << (span_columns_ + 1)) - std::uint32_t(1);
        mask_groups_ = groups;
    }

    /// Bit k set where column k of a row whose biased values at column 0
    /// are `value` is covered: all three values >= 0, i.e. the sign of
    /// their OR clear. No branch per column, so the span's ends cost no
    /// mispredicted branch as a walk's do.
    PHONGRAST_ALWAYS_INLINE std::uint32_t covered_columns(const std::int64_t* value) const {
        const __m128i lanes[3] = {
            _mm_add_epi32(_mm_set1_epi32(static_cast<std::int32_t>(value[0])), lane_offset_[0]),
            _mm_add_epi32(_mm_set1_epi32(static_cast<std::int32_t>(value[1])), lane_offset_[1]),
            _mm_add_epi32(_mm_set1_epi32(static_cast<std::int32_t>(value[2])), lane_offset_[2])};
        return covered_columns_from(lanes);
    }

    /// covered_columns() from the row's values at the box's columns 0-3.
    PHONGRAST_ALWAYS_INLINE std::uint32_t covered_columns_from(const __m128i* lanes) const {
        __m128i e0 = lanes[0], e1 = lanes[1], e2 = lanes[2];
        std::uint32_t outside = 0;
        for (int group = 0; group < mask_groups_; ++group) {
            const __m128i any = _mm_or_si128(_mm_or_si128(e0, e1), e2);
            outside |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(any))) << (4 * group);
            e0 = _mm_add_epi32(e0, group_step_[0]);
            e1 = _mm_add_epi32(e1, group_step_[1]);
            e2 = _mm_add_epi32(e2, group_step_[2]);
        }
        return ~outside & valid_columns_;
    }
#endif

    /// tiny_spans() for one row whose biased values at the first column are `left`: 0 or 1 span.
    PHONGRAST_ALWAYS_INLINE int tiny_row(int row, const std::int64_t* left, CoveredSpan* span) const {
        // Scalars, not arrays: GCC would otherwise pair these up in vector
        // registers through the stack, loading 16 bytes just stored as two 8s (a stall).
        const std::int64_t left0 = left[0], left1 = left[1], left2 = left[2];
        const std::int64_t right0 = left0 + step_column_[0], right1 = left1 + step_column_[1],
                           right2 = left2 + step_column_[2];
        const bool left_in = (left0 | left1 | left2) >= 0;
        const bool right_in = span_columns_ > 0 && (right0 | right1 | right2) >= 0;
        if (!(left_in || right_in)) return 0;
        span->row = row;
        span->first_column = column_min_ + (left_in ? 0 : 1);
        span->count = int(left_in) + int(right_in);
        span->e[0] = (left_in ? left0 : right0) + threshold_[0];
        span->e[1] = (left_in ? left1 : right1) + threshold_[1];
        span->e[2] = (left_in ? left2 : right2) + threshold_[2];
        return 1;
    }

    int first_row_, last_row_, column_min_;
    std::int64_t span_columns_;  ///< the bounding box's columns minus one
    std::int64_t biased_[3];     ///< edge values at the first row's first centre, minus the thresholds
    std::int64_t step_column_[3], step_row_[3];
    std::int64_t threshold_[3];  ///< 0 for a top or left edge, else 1
#if PHONGRAST_ROW_MASKS
    int mask_groups_ = 0;  ///< groups of four columns covered_columns() tests; 0: rows are not solved by masks
    std::uint32_t valid_columns_ = 0;  ///< bit k set for the box's columns k
    __m128i lane_offset_[3];           ///< step_column_ times 0, 1, 2, 3
    __m128i group_step_[3];            ///< step_column_ times 4
#endif
};

/// False when a set-up triangle whose bounding box holds at most 2 x 2
/// centres covers none of them (exactly as the fill would find, with the
/// same integer edge values); true otherwise, larger triangles untested.
/// Set-up drops such triangles: most one-pixel triangles' boxes hold a
/// centre, a third of them cover none, and a dropped one costs no record,
/// no sort, no binning and no fill.
inline bool may_cover_a_centre(const SnappedTriangle& t) {
    if (t.row_max - t.row_min >= 2 || t.column_max - t.column_min >= 2) return true;
    const CoveredRows rows(t, t.row_min, t.row_max + 1);
    CoveredSpan spans[2];
    return rows.tiny_spans(spans) > 0;
}

/// for_each_covered_span() for a triangle that is not tiny, row by row. Kept
/// out of line, so that the tiny triangles' path keeps its values in registers.
template <typename VisitSpan>
PHONGRAST_NOINLINE void for_each_solved_span(const CoveredRows& rows, VisitSpan& visit_span) {
    for (int row = rows.first_row(); row <= rows.last_row(); ++row) {
        CoveredSpan span;
        if (rows.solve(row, span)) visit_span(span.row, span.first_column, span.count, span.e, rows.step());
    }
}

/// Calls visit_span(row, first_column, count, e, step) for every row in
/// [row_begin, row_end) where the triangle covers pixel centres, with e as in
/// CoveredSpan and step[i] the change of e[i] per column.
template <typename VisitSpan>
void for_each_covered_span(const SnappedTriangle& t, int row_begin, int row_end, VisitSpan&& visit_span) {
    const CoveredRows rows(t, row_begin, row_end);
    if (rows.empty()) return;
    if (!rows.tiny()) {
        for_each_solved_span(rows, visit_span);
        return;
    }
    CoveredSpan spans[2];
    const int found = rows.tiny_spans(spans);
    for (int s = 0; s < found; ++s) {
        visit_span(spans[s].row, spans[s].first_column, spans[s].count, spans[s].e, rows.step());
    }
}

/// Calls visit(row, column, e0, e1, e2) for every covered pixel centre in rows
/// [row_begin, row_end), with the unbiased edge values of for_each_covered_span.
template <typename Visit>
void for_each_covered_pixel(const SnappedTriangle& t, int row_begin, int row_end, Visit&& visit) {
    for_each_covered_span(
        t, row_begin, row_end,
        [&](int row, int first_column, int count, const std::int64_t* e, const std::int64_t* step) {
            for (int k = 0; k < count; ++k) {
                visit(row, first_column + k, e[0] + step[0] * k, e[1] + step[1] * k, e[2] + step[2] * k);
            }
        });
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_RASTER_HPP
