#include "clipping.hpp"

#include <algorithm>
#include <cmath>

#include "raster.hpp"

namespace phongrast::detail {
namespace {

template <typename Real>
bool clip_to_near_plane(ClipPolygon<Real>& polygon, const View& view) {
    bool behind = false;
    for (std::size_t i = 0; i < polygon.count; ++i) behind |= polygon.vertices[i].depth < view.near_depth;
    if (!behind) return true;
    ClipPolygon<Real> clipped;
    const double near_depth = view.near_depth;
    clip_against<Real>(
        polygon, clipped, [near_depth](const ClipVertex<Real>& v) { return v.depth - near_depth; },
        [&view](const ClipVertex<Real>& inside, const ClipVertex<Real>& outside, double t) {
            ClipVertex<Real> v;
            v.varyings = lerp(inside.varyings, outside.varyings, static_cast<Real>(t));
            v.depth = inside.depth + (outside.depth - inside.depth) * t;
            v.varyings.position.z = static_cast<Real>(v.depth);
            const glm::dvec2 sample = view.sample_from_camera(glm::dvec3(v.varyings.position));
            v.column = sample.x;
            v.row = sample.y;
            return v;
        });
    polygon = clipped;
    return polygon.count >= 3;
}

template <typename Real>
bool representable(const ClipPolygon<Real>& polygon) {
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const ClipVertex<Real>& v = polygon.vertices[i];
        if (!(std::abs(v.column) <= kMaxClippableProjection && std::abs(v.row) <= kMaxClippableProjection)) {
            return false;
        }
    }
    return true;
}

template <typename Real>
bool clip_to_guard_band(ClipPolygon<Real>& polygon, const View& view, bool perspective) {
    const double lo = -kGuardBandPixels;
    const double column_hi = view.frame.columns + kGuardBandPixels;
    const double row_hi = view.frame.rows + kGuardBandPixels;
    bool beyond_guard = false;
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const ClipVertex<Real>& v = polygon.vertices[i];
        beyond_guard |= !(v.column >= lo && v.column <= column_hi && v.row >= lo && v.row <= row_hi);
    }
    if (!beyond_guard) return true;

    const auto make = [perspective](const ClipVertex<Real>& inside, const ClipVertex<Real>& outside, double t) {
        // t is linear in screen space; for perspective-correct attributes the
        // matching 3D parameter weights each end by 1/z.
        double s = t;
        if (perspective) {
            const double wi = (1.0 - t) / inside.depth, wo = t / outside.depth;
            s = wo / (wi + wo);
        }
        ClipVertex<Real> v;
        v.varyings = lerp(inside.varyings, outside.varyings, static_cast<Real>(s));
        v.depth = inside.depth + (outside.depth - inside.depth) * s;
        v.column = inside.column + (outside.column - inside.column) * t;
        v.row = inside.row + (outside.row - inside.row) * t;
        return v;
    };
    ClipPolygon<Real> clipped;
    const auto plane = [&](auto distance) {
        clip_against<Real>(polygon, clipped, distance, make);
        polygon = clipped;
        return polygon.count >= 3;
    };
    return plane([lo](const ClipVertex<Real>& v) { return v.column - lo; }) &&
           plane([column_hi](const ClipVertex<Real>& v) { return column_hi - v.column; }) &&
           plane([lo](const ClipVertex<Real>& v) { return v.row - lo; }) &&
           plane([row_hi](const ClipVertex<Real>& v) { return row_hi - v.row; });
}

}  // namespace

template <typename Real>
ClipOutcome clip_to_view(ClipPolygon<Real>& polygon, const View& view, bool perspective) {
    if (!clip_to_near_plane(polygon, view)) return ClipOutcome::empty;
    if (!representable(polygon)) return ClipOutcome::out_of_range;
    return clip_to_guard_band(polygon, view, perspective) ? ClipOutcome::kept : ClipOutcome::empty;
}

// Separating axes: the rectangle's two and the polygon's edges, each with
// every rectangle corner strictly outside.
template <typename Real>
bool meets_image(const ClipPolygon<Real>& polygon, int rows, int columns) {
    const double width = columns, height = rows;
    double column_min = polygon.vertices[0].column, column_max = column_min;
    double row_min = polygon.vertices[0].row, row_max = row_min;
    double twice_area = 0.0;
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const ClipVertex<Real>& a = polygon.vertices[i];
        const ClipVertex<Real>& b = polygon.vertices[(i + 1) % polygon.count];
        column_min = std::min(column_min, a.column);
        column_max = std::max(column_max, a.column);
        row_min = std::min(row_min, a.row);
        row_max = std::max(row_max, a.row);
        twice_area += a.column * b.row - b.column * a.row;
    }
    if (column_max < 0.0 || column_min > width || row_max < 0.0 || row_min > height) return false;
    const double corners[4][2] = {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const ClipVertex<Real>& a = polygon.vertices[i];
        const ClipVertex<Real>& b = polygon.vertices[(i + 1) % polygon.count];
        bool all_outside = true;
        for (const auto& corner : corners) {
            const double side = (b.column - a.column) * (corner[1] - a.row) - (b.row - a.row) * (corner[0] - a.column);
            all_outside = all_outside && (twice_area > 0.0 ? side < 0.0 : side > 0.0);
        }
        if (all_outside) return false;
    }
    return true;
}

template ClipOutcome clip_to_view<float>(ClipPolygon<float>&, const View&, bool);
template ClipOutcome clip_to_view<double>(ClipPolygon<double>&, const View&, bool);
template bool meets_image<float>(const ClipPolygon<float>&, int, int);
template bool meets_image<double>(const ClipPolygon<double>&, int, int);

}  // namespace phongrast::detail
