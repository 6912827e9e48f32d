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

namespace phongrast::detail {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixelScale = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;
/// Largest image side (after supersampling) the fixed-point budget allows.
constexpr int kMaxImageSide = 1 << 19;
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

/// A triangle ready for coverage: vertices ordered so that area2 > 0.
/// Kept small: the renderer stores one per drawn triangle.
struct CoverageTriangle {
    CompactPoint v[3];
    std::int64_t area2 = 0;               ///< E_01(v2) = twice the area in (1/256 px)^2
    bool swapped = false;                 ///< true if input vertices 1 and 2 were exchanged
    int row_min = 0, row_max = -1;        ///< pixel rows whose centres may be covered
    int column_min = 0, column_max = -1;  ///< pixel columns likewise
};

/// Sets up coverage for snapped vertices a, b, c inside an image of rows x
/// columns. Returns false if the triangle has zero area (it covers no centre)
/// or no pixel centre of the image lies in its bounding box.
inline bool setup_coverage(const SnappedPoint& a, const SnappedPoint& b, const SnappedPoint& c, int rows,
                           int columns, CoverageTriangle& out) {
    assert(std::abs(a.x) <= kMaxSnappedMagnitude && std::abs(a.y) <= kMaxSnappedMagnitude);
    assert(std::abs(b.x) <= kMaxSnappedMagnitude && std::abs(b.y) <= kMaxSnappedMagnitude);
    assert(std::abs(c.x) <= kMaxSnappedMagnitude && std::abs(c.y) <= kMaxSnappedMagnitude);
    std::int64_t area2 = edge_value(a, b, c.x, c.y);
    if (area2 == 0) return false;
    out.v[0] = a;
    if (area2 > 0) {
        out.v[1] = b;
        out.v[2] = c;
        out.swapped = false;
    } else {
        out.v[1] = c;
        out.v[2] = b;
        out.swapped = true;
        area2 = -area2;
    }
    out.area2 = area2;

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

/// Calls visit_span(row, first_column, count, e, step) for every row in
/// [row_begin, row_end) where the triangle covers pixel centres: the covered
/// centres of a row are contiguous (the triangle is convex), e[i] is the
/// unbiased edge value opposite vertex i at the first of them (so e[i] / area2
/// is vertex i's screen-space barycentric weight there) and step[i] its change
/// per column. Each row's span is solved exactly from the three edge
/// functions, so thin slivers cost their length, not their bounding box.
template <typename VisitSpan>
void for_each_covered_span(const CoverageTriangle& t, int row_begin, int row_end, VisitSpan&& visit_span) {
    const int first_row = std::max(row_begin, t.row_min);
    const int last_row = std::min(row_end - 1, t.row_max);
    if (first_row > last_row) return;
    const std::int64_t origin_x = std::int64_t(t.column_min) * kSubpixelScale + kHalfPixel;
    const std::int64_t origin_y = std::int64_t(first_row) * kSubpixelScale + kHalfPixel;
    std::int64_t at_origin[3], step_column[3], step_row[3], threshold[3];
    for (int i = 0; i < 3; ++i) {
        // Edge opposite vertex i runs from vertex i+1 to vertex i+2.
        const SnappedPoint a = t.v[(i + 1) % 3];
        const SnappedPoint b = t.v[(i + 2) % 3];
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        const bool top = (dy == 0 && dx > 0);
        const bool left = (dy < 0);
        at_origin[i] = edge_value(a, b, origin_x, origin_y);
        step_column[i] = -dy * kSubpixelScale;
        step_row[i] = dx * kSubpixelScale;
        threshold[i] = (top || left) ? 0 : 1;  // top-left edges own the centres on them
    }

    const std::int64_t span_columns = t.column_max - t.column_min;
    for (int row = first_row; row <= last_row; ++row) {
        const std::int64_t row_offset = row - first_row;
        std::int64_t value[3];
        for (int i = 0; i < 3; ++i) value[i] = at_origin[i] + step_row[i] * row_offset;
        std::int64_t k_lo = 0, k_hi = span_columns;
        if (span_columns < 16) {
            // Narrow (under 16 columns): walk the row with incremental edge values; cheaper than dividing.
            std::int64_t e0 = value[0], e1 = value[1], e2 = value[2];
            std::int64_t k = 0;
            for (; k <= span_columns; ++k, e0 += step_column[0], e1 += step_column[1], e2 += step_column[2]) {
                if (e0 >= threshold[0] && e1 >= threshold[1] && e2 >= threshold[2]) break;
            }
            if (k > span_columns) continue;
            k_lo = k;
            for (++k, e0 += step_column[0], e1 += step_column[1], e2 += step_column[2]; k <= span_columns;
                 ++k, e0 += step_column[0], e1 += step_column[1], e2 += step_column[2]) {
                if (!(e0 >= threshold[0] && e1 >= threshold[1] && e2 >= threshold[2])) break;
            }
            k_hi = k - 1;
        } else {
            for (int i = 0; i < 3; ++i) {
                // The integer k in [k_lo, k_hi] with value + step * k >= threshold.
                const std::int64_t need = threshold[i] - value[i];
                if (step_column[i] > 0) {
                    k_lo = std::max(k_lo, first_at_least(need, step_column[i]));
                } else if (step_column[i] < 0) {
                    k_hi = std::min(k_hi, last_at_most(-need, -step_column[i]));
                } else if (need > 0) {
                    k_hi = -1;
                }
            }
            if (k_lo > k_hi) continue;
        }
        const std::int64_t e[3] = {value[0] + step_column[0] * k_lo, value[1] + step_column[1] * k_lo,
                                   value[2] + step_column[2] * k_lo};
        visit_span(row, t.column_min + static_cast<int>(k_lo), static_cast<int>(k_hi - k_lo + 1), e,
                   step_column);
    }
}

/// Calls visit(row, column, e0, e1, e2) for every covered pixel centre in rows
/// [row_begin, row_end), with the unbiased edge values of for_each_covered_span.
template <typename Visit>
void for_each_covered_pixel(const CoverageTriangle& t, int row_begin, int row_end, Visit&& visit) {
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
