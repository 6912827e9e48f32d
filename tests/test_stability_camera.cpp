// Vertices behind the camera, on the camera plane z_c = 0, on the image plane
// z_c = focal and straddling them; invalid cameras. The seed preset drops any
// triangle with a vertex at z_c <= 0 (the contract's seed rule); the exact
// preset clips against the near plane z_c = 1e-4 * focal. Each test name
// states the expected outcome.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "test_stability_common.hpp"

using namespace phongrast;
using stability::add_triangle;
using stability::at_pixel;
using stability::count_not;

TEST_CASE("a triangle entirely behind the camera: seed drops it, exact finds nothing to draw") {
    Scene scene = stability::pixel_exact_scene();
    add_triangle(scene.mesh, {-1, -1, 2}, {1, -1, 3}, {0, 1, 4});  // z_c = -z < 0
    const RenderResult seed = render(scene, RenderOptions::seed());
    STABILITY_CHECK_FINITE(seed);
    CHECK(seed.stats.triangles_dropped == 1);
    const RenderResult exact = render(scene, RenderOptions::exact());
    STABILITY_CHECK_FINITE(exact);
    CHECK(exact.stats.triangles_outside == 1);
    CHECK(exact.stats.triangles_drawn == 0);
    CHECK(count_not(exact.image) == 0);
}

TEST_CASE("a vertex exactly on the camera plane z_c = 0: seed drops, exact clips and draws the rest") {
    Scene scene = stability::pixel_exact_scene();
    // Two vertices in front (depth 8, on the image's lower half), one at z_c = 0 above the eye.
    add_triangle(scene.mesh, at_pixel(scene, 10, 60, 8), at_pixel(scene, 54, 60, 8), {0.0, 1.0, 0.0});
    const RenderResult seed = render(scene, RenderOptions::seed());
    STABILITY_CHECK_FINITE(seed);
    CHECK(seed.stats.triangles_dropped == 1);
    const RenderResult exact = render(scene, RenderOptions::exact());
    STABILITY_CHECK_FINITE(exact);
    CHECK(exact.stats.triangles_clipped == 1);
    CHECK(exact.stats.triangles_drawn == 1);
    // Towards z_c = 0 the vertex above the eye projects to row -infinity: the
    // clipped triangle reaches the top of the image between the other two.
    CHECK(exact.image.at(0, 32) == stability::kWhite);
    CHECK(exact.image.at(59, 32) == stability::kWhite);
    CHECK(exact.image.at(59, 5) == stability::kBackground);
}

TEST_CASE("a vertex exactly on the image plane z_c = focal projects like any other: drawn unclipped") {
    Scene scene = stability::pixel_exact_scene();
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 2;  // same picture as focal 1, sensor 1
    // at_pixel works for any focal with sensor = focal; depth 2 is the image plane.
    add_triangle(scene.mesh, at_pixel(scene, 10.5, 10.5, 2), at_pixel(scene, 50.5, 10.5, 4),
                 at_pixel(scene, 10.5, 50.5, 8));
    for (const RenderOptions& options : {RenderOptions::seed(), RenderOptions::exact()}) {
        const RenderResult result = render(scene, options);
        STABILITY_CHECK_FINITE(result);
        CHECK(result.stats.triangles_drawn == 1);
        CHECK(result.stats.triangles_clipped == 0);
        CHECK(result.image.at(10, 10) == stability::kWhite);  // the vertex's own centre (top-left owned)
        CHECK(result.image.at(9, 10) == stability::kBackground);
        CHECK(result.image.at(10, 9) == stability::kBackground);
    }
}

TEST_CASE("triangles straddling z_c = 0 and z_c = focal: seed drops, exact clips, finite, no double cover") {
    Scene scene = stability::pixel_exact_scene();
    // A floor under the eye from 50 units behind it to 50 in front: the horizon is the image's middle row.
    scene.mesh.positions = {{-50, -1, 50}, {50, -1, 50}, {50, -1, -50}, {-50, -1, -50}};
    scene.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    // A small triangle crossing both z_c = 0 and z_c = focal in front of the floor.
    add_triangle(scene.mesh, {-0.2, -0.5, 0.5}, {0.2, -0.5, 0.5}, {0.0, -0.4, -3.0});
    const RenderResult seed = render(scene, RenderOptions::seed());
    STABILITY_CHECK_FINITE(seed);
    CHECK(seed.stats.triangles_dropped == 3);
    const RenderResult exact = render(scene, RenderOptions::exact());
    STABILITY_CHECK_FINITE(exact);
    CHECK(exact.stats.triangles_clipped == 3);
    // The floor half right of its diagonal (x >= z_c there) projects right of
    // column 96, outside the image: clipped, then nothing left to draw.
    CHECK(exact.stats.triangles_drawn == 2);
    CHECK(exact.stats.triangles_outside == 1);
    // The floor (y = -1, up to 50 ahead) covers the rows below row 32 + 64 / 50 = 33.3
    // (its far edge): the bottom row entirely, the top half not at all.
    for (int column = 0; column < 64; ++column) {
        CHECK(exact.image.at(63, column) == stability::kWhite);
        CHECK(exact.image.at(20, column) == stability::kBackground);
    }
    // Each pixel written once by the floor; the small triangle (nearer) paints over some.
    CHECK(exact.stats.samples_shaded > count_not(exact.image));
    CHECK(exact.stats.samples_shaded < 2 * count_not(exact.image));
}

TEST_CASE("invalid cameras are a clear error naming the field, not a picture of NaNs") {
    Scene scene = stability::pixel_exact_scene();
    add_triangle(scene.mesh, at_pixel(scene, 10, 10, 8), at_pixel(scene, 50, 10, 8), at_pixel(scene, 10, 50, 8));
    SECTION("eye equal to lookat: names camera.lookat") {
        scene.camera.lookat = scene.camera.eye;
        CHECK_THROWS_AS(render(scene), std::invalid_argument);
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.lookat") && Catch::Contains("camera.eye"));
    }
    SECTION("eye within rounding of lookat at 1e7: still distinct, renders finite") {
        scene.camera.eye = {1e7, 0, 0};
        scene.camera.lookat = {std::nextafter(1e7, 2e7), 0, 0};
        const RenderResult result = render(scene);
        STABILITY_CHECK_FINITE(result);
    }
    SECTION("up parallel to the view direction: names camera.up") {
        scene.camera.up = {0, 0, -3};
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.up") && Catch::Contains("parallel"));
        scene.camera.up = {0, 0, 2};  // anti-parallel too
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.up"));
        scene.camera.up = {1e-12, 0, 1};  // parallel to within 1e-12 rad
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.up"));
    }
    SECTION("zero up: names camera.up") {
        scene.camera.up = {0, 0, 0};
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.up"));
    }
    SECTION("zero sensor: names camera.sensor") {
        scene.camera.sensor_height = 0;
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.sensor_height"));
        scene.camera.sensor_height = 1;
        scene.camera.sensor_width = 0;
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.sensor_width"));
        scene.camera.sensor_width = -1;
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.sensor_width"));
    }
    SECTION("zero, negative or infinite focal: names camera.focal") {
        for (double focal : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
            scene.camera.focal = focal;
            CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.focal") && Catch::Contains("positive finite"));
        }
    }
    SECTION("non-finite eye: names camera.eye") {
        scene.camera.eye.x = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH(render(scene), Catch::Contains("camera.eye"));
    }
}
