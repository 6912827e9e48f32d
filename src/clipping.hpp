// Clipping of one triangle against the near plane and the guard band (internal header).
//
// Watertightness across clipped neighbours: two triangles that share an edge
// must create bit-identical vertices where that edge crosses a clip plane.
// Every intersection is therefore computed from the inside vertex towards the
// outside one, never in polygon order, so both neighbours evaluate the same
// expression on the same operands.
#ifndef PHONGRAST_SRC_CLIPPING_HPP
#define PHONGRAST_SRC_CLIPPING_HPP

#include <array>
#include <cstddef>

#include "varyings.hpp"
#include "view.hpp"

namespace phongrast::detail {

template <typename Real>
struct ClipVertex {
    Varyings<Real> varyings;
    double depth = 0.0;   ///< z_c (camera space)
    double column = 0.0;  ///< sample coordinates, valid once projected
    double row = 0.0;
};

/// A convex polygon of at most 3 + 5 vertices (one per clip plane).
template <typename Real>
struct ClipPolygon {
    std::array<ClipVertex<Real>, 8> vertices;
    std::size_t count = 0;
};

/// Sutherland-Hodgman against one plane. `distance(v)` >= 0 is inside;
/// `make(inside, outside, t)` builds the vertex at parameter t from inside to outside.
template <typename Real, typename Distance, typename Make>
void clip_against(const ClipPolygon<Real>& in, ClipPolygon<Real>& out, Distance&& distance,
                  Make&& make) {
    out.count = 0;
    for (std::size_t i = 0; i < in.count; ++i) {
        const ClipVertex<Real>& current = in.vertices[i];
        const ClipVertex<Real>& next = in.vertices[(i + 1) % in.count];
        const double d_current = distance(current);
        const double d_next = distance(next);
        const bool current_inside = d_current >= 0.0;
        const bool next_inside = d_next >= 0.0;
        if (current_inside) out.vertices[out.count++] = current;
        if (current_inside != next_inside) {
            const ClipVertex<Real>& inside = current_inside ? current : next;
            const ClipVertex<Real>& outside = current_inside ? next : current;
            const double d_inside = current_inside ? d_current : d_next;
            const double d_outside = current_inside ? d_next : d_current;
            const double t = d_inside / (d_inside - d_outside);
            out.vertices[out.count++] = make(inside, outside, t);
        }
    }
}

/// The farthest z_c in front of the eye a triangle's corner may have to be
/// drawn in Real (set-up skips the triangle otherwise). The fill's
/// perspective weights are (edge weight) / z_c, summed and inverted: up to
/// 1e30 those stay normal floats and their inverse finite (float's largest
/// value is 3.4e38, its smallest normal 1.2e-38); double has the same margin
/// at 1e300.
template <typename Real>
inline constexpr double kMaxDrawableDepth = 1e300;
template <>
inline constexpr double kMaxDrawableDepth<float> = 1e30;

/// Projected coordinates up to this size are clipped exactly (differences of
/// two of them stay finite); beyond it only overflow can have produced them.
constexpr double kMaxClippableProjection = 1e306;

enum class ClipOutcome {
    kept,          ///< `polygon` holds what is left, at least a triangle
    empty,         ///< nothing is left
    out_of_range,  ///< a corner cannot be represented (a coordinate overflowed on the way here)
};

/// Clips `polygon` to the near plane, then to the guard band around the
/// image (raster.hpp's kGuardBandPixels). Attributes are interpolated in
/// screen space, or at the matching 3D parameter when `perspective`.
/// A corner out of range makes the triangle skipped rather than fed to the
/// fixed-point snapping.
template <typename Real>
ClipOutcome clip_to_view(ClipPolygon<Real>& polygon, const View& view, bool perspective);

/// Whether a convex polygon (sample coordinates) overlaps the image
/// rectangle [0, columns] x [0, rows].
template <typename Real>
bool meets_image(const ClipPolygon<Real>& polygon, int rows, int columns);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_CLIPPING_HPP
