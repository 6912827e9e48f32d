// Exact triangle coverage in fixed point (internal header).
//
// Conventions (../shared/scene-format.md, "Camera"), reproduced here because
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

inline SnappedPoint snap(double column, double row) {
    return {static_cast<std::int64_t>(std::llround(column * double(kSubpixelScale))),
            static_cast<std::int64_t>(std::llround(row * double(kSubpixelScale)))};
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

/// A triangle ready for coverage: vertices ordered so that area2 > 0.
struct CoverageTriangle {
    SnappedPoint v[3];
    std::int64_t area2 = 0;  ///< E_01(v2) = twice the area in (1/256 px)^2
    bool swapped = false;    ///< true if input vertices 1 and 2 were exchanged
    int row_min = 0, row_max = -1;        ///< pixel rows whose centres may be covered
    int column_min = 0, column_max = -1;  ///< pixel columns likewise
};

/// Sets up coverage for snapped vertices a, b, c inside an image of rows x
/// columns. Returns false if the triangle has zero area (it covers no centre)
/// or no pixel centre of the image lies in its bounding box.
inline bool setup_coverage(const SnappedPoint& a, const SnappedPoint& b, const SnappedPoint& c,
                           int rows, int columns, CoverageTriangle& out) {
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

/// Calls visit(row, column, e0, e1, e2) for every pixel centre in rows
/// [row_begin, row_end) that the triangle covers, where e_i is the unbiased
/// edge value opposite vertex i (so e_i / area2 is vertex i's screen-space
/// barycentric weight). Each row's covered span is solved exactly from the
/// three edge functions, so thin slivers cost their length, not their box.
template <typename Visit>
void for_each_covered_pixel(const CoverageTriangle& t, int row_begin, int row_end, Visit&& visit) {
    struct Edge {
        std::int64_t at_origin;  ///< value at the centre of pixel (row_min, column_min)
        std::int64_t step_column;
        std::int64_t step_row;
        std::int64_t threshold;  ///< 0 for top-left edges (E >= 0 owns), 1 otherwise (E > 0)
    };
    Edge edges[3];
    const std::int64_t origin_x = std::int64_t(t.column_min) * kSubpixelScale + kHalfPixel;
    const int first_row = std::max(row_begin, t.row_min);
    const int last_row = std::min(row_end - 1, t.row_max);
    if (first_row > last_row) return;
    const std::int64_t origin_y = std::int64_t(first_row) * kSubpixelScale + kHalfPixel;
    for (int i = 0; i < 3; ++i) {
        // Edge opposite vertex i runs from vertex i+1 to vertex i+2.
        const SnappedPoint& a = t.v[(i + 1) % 3];
        const SnappedPoint& b = t.v[(i + 2) % 3];
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        const bool top = (dy == 0 && dx > 0);
        const bool left = (dy < 0);
        edges[i].at_origin = edge_value(a, b, origin_x, origin_y);
        edges[i].step_column = -dy * kSubpixelScale;
        edges[i].step_row = dx * kSubpixelScale;
        edges[i].threshold = (top || left) ? 0 : 1;
    }

    const std::int64_t span_columns = t.column_max - t.column_min;
    for (int row = first_row; row <= last_row; ++row) {
        const std::int64_t row_offset = row - first_row;
        std::int64_t k_lo = 0, k_hi = span_columns;
        std::int64_t value[3];
        for (int i = 0; i < 3; ++i) {
            const Edge& e = edges[i];
            value[i] = e.at_origin + e.step_row * row_offset;
            // Solve value + step * k >= threshold for the integer k in [k_lo, k_hi].
            const std::int64_t need = e.threshold - value[i];
            if (e.step_column > 0) {
                k_lo = std::max(k_lo, -floor_div(-need, e.step_column));
            } else if (e.step_column < 0) {
                k_hi = std::min(k_hi, floor_div(-need, -e.step_column));
            } else if (need > 0) {
                k_hi = -1;
            }
        }
        for (std::int64_t k = k_lo; k <= k_hi; ++k) {
            const std::int64_t e0 = value[0] + edges[0].step_column * k;
            const std::int64_t e1 = value[1] + edges[1].step_column * k;
            const std::int64_t e2 = value[2] + edges[2].step_column * k;
            assert(e0 >= edges[0].threshold && e1 >= edges[1].threshold && e2 >= edges[2].threshold);
            visit(row, t.column_min + static_cast<int>(k), e0, e1, e2);
        }
    }
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_RASTER_HPP
