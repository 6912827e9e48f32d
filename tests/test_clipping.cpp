// Clipping on its own: the near plane, the guard band, corners that cannot be
// represented, and whether a clipped polygon still meets the image.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "clipping.hpp"
#include "raster.hpp"

using phongrast::detail::ClipPolygon;
using phongrast::detail::ClipVertex;
using phongrast::detail::View;

namespace {

/// The default camera (eye at z = 1 looking at the origin, focal 1, sensor 1 x 1) on 64 x 64 samples.
View test_view() { return View(phongrast::Camera{}, 64, 64, glm::dvec2(0.0)); }

/// A corner at camera-space (x, y, depth) (z looks forward), projected like the vertex stage does.
ClipVertex<float> corner(const View& view, double x, double y, double depth) {
    ClipVertex<float> v;
    v.varyings.position = glm::vec3(float(x), float(y), float(depth));
    v.varyings.color = glm::vec3(1.0f);
    v.depth = depth;
    if (depth > 0.0) {
        const glm::dvec2 sample = view.sample_from_camera(glm::dvec3(x, y, depth));
        v.column = sample.x;
        v.row = sample.y;
    }
    return v;
}

ClipPolygon<float> triangle(const ClipVertex<float>& a, const ClipVertex<float>& b, const ClipVertex<float>& c) {
    ClipPolygon<float> polygon;
    polygon.vertices[0] = a;
    polygon.vertices[1] = b;
    polygon.vertices[2] = c;
    polygon.count = 3;
    return polygon;
}

}  // namespace

TEST_CASE("a triangle inside the view is left as it is") {
    const View view = test_view();
    ClipPolygon<float> polygon = triangle(corner(view, -0.2, -0.2, 1.0), corner(view, 0.2, -0.2, 1.0),
                                          corner(view, 0.0, 0.2, 1.0));
    const ClipPolygon<float> before = polygon;
    REQUIRE(phongrast::detail::clip_to_view(polygon, view, true) == phongrast::detail::ClipOutcome::kept);
    REQUIRE(polygon.count == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(polygon.vertices[i].column == before.vertices[i].column);
        CHECK(polygon.vertices[i].row == before.vertices[i].row);
        CHECK(polygon.vertices[i].depth == before.vertices[i].depth);
    }
}

TEST_CASE("the near plane cuts a triangle with one corner behind the eye into a quadrilateral") {
    const View view = test_view();
    ClipPolygon<float> polygon = triangle(corner(view, -0.2, 0.0, 1.0), corner(view, 0.2, 0.0, 1.0),
                                          corner(view, 0.0, 0.0, -1.0));
    REQUIRE(phongrast::detail::clip_to_view(polygon, view, true) == phongrast::detail::ClipOutcome::kept);
    REQUIRE(polygon.count == 4);
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const ClipVertex<float>& v = polygon.vertices[i];
        CHECK(v.depth >= view.near_depth * (1.0 - 1e-12));  // on the plane up to rounding, or in front of it
        CHECK(std::isfinite(v.column));
        CHECK(std::isfinite(v.row));
        CHECK(v.varyings.position.z == static_cast<float>(v.depth));
    }
}

TEST_CASE("a triangle wholly behind the near plane leaves nothing") {
    const View view = test_view();
    ClipPolygon<float> polygon = triangle(corner(view, -0.2, 0.0, -1.0), corner(view, 0.2, 0.0, -1.0),
                                          corner(view, 0.0, 0.2, -2.0));
    CHECK(phongrast::detail::clip_to_view(polygon, view, true) == phongrast::detail::ClipOutcome::empty);
}

TEST_CASE("neighbours clipped at the near plane create bit-identical corners on their shared edge") {
    const View view = test_view();
    const ClipVertex<float> front = corner(view, 0.1, 0.05, 2.0), behind = corner(view, -0.1, 0.02, -0.5);
    ClipPolygon<float> left = triangle(front, behind, corner(view, -0.3, 0.3, 1.5));
    ClipPolygon<float> right = triangle(behind, front, corner(view, 0.3, -0.3, 1.0));
    REQUIRE(phongrast::detail::clip_to_view(left, view, true) == phongrast::detail::ClipOutcome::kept);
    REQUIRE(phongrast::detail::clip_to_view(right, view, true) == phongrast::detail::ClipOutcome::kept);
    // Of the new corners (in front of 1.0), exactly one is on the shared edge: the same bits in both.
    int shared = 0;
    for (std::size_t i = 0; i < left.count; ++i) {
        for (std::size_t j = 0; j < right.count; ++j) {
            const ClipVertex<float>& a = left.vertices[i];
            const ClipVertex<float>& b = right.vertices[j];
            if (a.depth < 1.0 && a.depth == b.depth && a.column == b.column && a.row == b.row &&
                a.varyings.position == b.varyings.position) {
                ++shared;
            }
        }
    }
    CHECK(shared == 1);
}

TEST_CASE("corners beyond the guard band are clipped to it, in both screen-space and perspective modes") {
    const View view = test_view();
    const double far = 100.0 * phongrast::detail::kGuardBandPixels;
    for (const bool perspective : {false, true}) {
        ClipVertex<float> a = corner(view, 0.0, 0.0, 1.0), b = corner(view, 0.0, 0.0, 1.0), c = a;
        a.column = 10.0, a.row = 10.0;
        b.column = far, b.row = 20.0, b.depth = 3.0;
        c.column = 30.0, c.row = 40.0;
        ClipPolygon<float> polygon = triangle(a, b, c);
        REQUIRE(phongrast::detail::clip_to_view(polygon, view, perspective) == phongrast::detail::ClipOutcome::kept);
        CHECK(polygon.count == 4);
        for (std::size_t i = 0; i < polygon.count; ++i) {
            const ClipVertex<float>& v = polygon.vertices[i];
            CHECK(v.column <= view.frame.columns + phongrast::detail::kGuardBandPixels);
            CHECK(v.depth >= 1.0);
            CHECK(v.depth <= 3.0);
        }
    }
}

TEST_CASE("a corner that overflowed is not clipped but skipped") {
    const View view = test_view();
    ClipVertex<float> a = corner(view, 0.0, 0.0, 1.0), b = a, c = a;
    b.column = 2.0 * phongrast::detail::kMaxClippableProjection;
    c.row = std::numeric_limits<double>::infinity();
    ClipPolygon<float> polygon = triangle(a, b, c);
    CHECK(phongrast::detail::clip_to_view(polygon, view, true) == phongrast::detail::ClipOutcome::out_of_range);
}

TEST_CASE("meets_image tells polygons over the image from those beside it") {
    const View view = test_view();
    const auto at = [&](double column, double row) {
        ClipVertex<float> v = corner(view, 0.0, 0.0, 1.0);
        v.column = column;
        v.row = row;
        return v;
    };
    // Overlapping the top-left corner.
    CHECK(phongrast::detail::meets_image(triangle(at(-10, -10), at(10, -10), at(-10, 10)), 64, 64));
    // Wholly to the right of the image.
    CHECK_FALSE(phongrast::detail::meets_image(triangle(at(70, 0), at(90, 0), at(80, 30)), 64, 64));
    // Its bounding box overlaps the image, but its long edge passes outside the corner (-1 <= column + row).
    CHECK_FALSE(phongrast::detail::meets_image(triangle(at(-50, 49), at(49, -50), at(-50, -50)), 64, 64));
    // Either winding.
    CHECK(phongrast::detail::meets_image(triangle(at(-10, -10), at(-10, 10), at(10, -10)), 64, 64));
}
