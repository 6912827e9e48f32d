// Sizes at the extremes: a 1 x 1 image, a 16384 x 16384 image, an empty mesh,
// a mesh of one triangle, and 10 million triangles all on one pixel. Each test
// name states the expected outcome.
#include <chrono>

#include <catch2/catch.hpp>

#include "test_stability_common.hpp"

using namespace phongrast;
using stability::add_triangle;
using stability::at_pixel;
using stability::count_not;

TEST_CASE("1 x 1 image: the pixel shows the triangle covering its centre, else the background") {
    for (const RenderOptions& options : {RenderOptions::seed(), RenderOptions::exact()}) {
        Scene scene = stability::pixel_exact_scene(1, 1);
        add_triangle(scene.mesh, at_pixel(scene, 0.1, 0.1, 8), at_pixel(scene, 0.9, 0.2, 8), at_pixel(scene, 0.3, 0.9, 8));
        const RenderResult covered = render(scene, options);
        STABILITY_CHECK_FINITE(covered);
        CHECK(covered.image.pixels.size() == 1);
        CHECK(covered.image.at(0, 0) == stability::kWhite);
        CHECK(covered.stats.samples_shaded == 1);
        // Moved so that the centre (0.5, 0.5) lies outside it.
        scene.mesh.positions = {at_pixel(scene, 0.6, 0.1, 8), at_pixel(scene, 0.9, 0.1, 8), at_pixel(scene, 0.9, 0.9, 8)};
        const RenderResult missed = render(scene, options);
        CHECK(missed.image.at(0, 0) == stability::kBackground);
        CHECK(missed.stats.samples_shaded == 0);
        CHECK(missed.stats.triangles_between_samples == 1);  // in the image, between sample centres
        CHECK(missed.stats.triangles_outside == 0);
    }
}

TEST_CASE("a triangle covering no sample is counted between samples when in the image, else outside") {
    Scene scene = stability::pixel_exact_scene(4, 4);
    // A sliver along rows 0.6-0.9 from column -2 to 0.4: clipped at the left
    // border, its part in the image (columns 0-0.4) holds no centre.
    add_triangle(scene.mesh, at_pixel(scene, -2.0, 0.6, 8), at_pixel(scene, 0.4, 0.6, 8), at_pixel(scene, 0.4, 0.9, 8));
    const RenderResult straddling = render(scene, RenderOptions::exact());
    CHECK(straddling.stats.triangles_clipped == 1);
    CHECK(straddling.stats.triangles_between_samples == 1);
    CHECK(straddling.stats.triangles_outside == 0);
    CHECK(straddling.stats.samples_covered == 0);
    // The same shape moved to columns -3 to -0.6: beyond the border, within the guard band.
    scene.mesh.positions = {at_pixel(scene, -3.0, 0.6, 8), at_pixel(scene, -0.6, 0.6, 8), at_pixel(scene, -0.6, 0.9, 8)};
    const RenderResult beyond = render(scene, RenderOptions::exact());
    CHECK(beyond.stats.triangles_outside == 1);
    CHECK(beyond.stats.triangles_between_samples == 0);
}

TEST_CASE("16384 x 16384 image with a tiny mesh: the triangle's pixels and nothing else, no overflow") {
    const int size = 16384;
    Scene scene = stability::pixel_exact_scene(size, size);
    // Right angle on the centre (8000.5, 9000.5), legs 40 px: covers 40 + 39 + ... + 1 = 820 centres
    // (the hypotenuse owns none of the centres on it, the legs own theirs).
    add_triangle(scene.mesh, at_pixel(scene, 8000.5, 9000.5, 8), at_pixel(scene, 8040.5, 9000.5, 8),
                 at_pixel(scene, 8000.5, 9040.5, 8));
    const auto start = std::chrono::steady_clock::now();
    const RenderResult result = render(scene, RenderOptions::exact());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WARN("16384^2 render took " << seconds << " s");  // reported, not asserted: tests take no timings
    REQUIRE(result.image.pixels.size() == std::size_t(size) * size);
    CHECK(result.stats.samples_shaded == 820);
    CHECK(count_not(result.image) == 820);
    CHECK(result.image.at(9000, 8000) == stability::kWhite);
    CHECK(result.image.at(9039, 8000) == stability::kWhite);
    CHECK(result.image.at(9000, 8039) == stability::kWhite);
    CHECK(result.image.at(size - 1, size - 1) == stability::kBackground);
    CHECK(result.stats.nonfinite_values_replaced == 0);
}

TEST_CASE("an empty mesh renders the background, with every count zero") {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene scene = stability::pixel_exact_scene();
        scene.shader = shader;
        scene.lighting = Lighting::full();
        scene.lights = {{{1, 1, 1}, {1, 1, 1}}};
        for (bool with_vertices : {false, true}) {
            if (with_vertices) scene.mesh.positions = {{0, 0, -1}, {1, 0, -1}};  // vertices but no triangle
            const RenderResult result = render(scene);
            STABILITY_CHECK_FINITE(result);
            CHECK(count_not(result.image) == 0);
            CHECK(result.stats.triangles_in == 0);
            CHECK(result.stats.samples_shaded == 0);
            CHECK(result.stats.triangles_drawn == 0);
        }
    }
}

TEST_CASE("a mesh of one triangle is drawn with every shader and preset") {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const RenderOptions& options : {RenderOptions::seed(), RenderOptions::exact()}) {
            Scene scene = stability::pixel_exact_scene();
            scene.shader = shader;
            scene.lighting = Lighting::full();
            scene.lights = {{{1, 2, 3}, {1, 1, 1}}};
            add_triangle(scene.mesh, at_pixel(scene, 10.5, 10.5, 8), at_pixel(scene, 50.5, 10.5, 8),
                         at_pixel(scene, 10.5, 50.5, 8));
            const RenderResult result = render(scene, options);
            STABILITY_CHECK_FINITE(result);
            CHECK(result.stats.triangles_drawn == 1);
            CHECK(result.stats.samples_shaded == 820);  // 40 + 39 + ... + 1
            CHECK(count_not(result.image) == 820);
        }
    }
}

TEST_CASE("10 million triangles on one pixel: each covers that one pixel, the last in mesh order wins") {
    // Painter's order with equal depths keeps mesh order, so the pixel shows
    // the last triangle. The triangles share their vertices (memory stays at
    // the index list); the last one alone uses a red vertex set.
    const std::uint32_t count = 10'000'000;
    Scene scene = stability::pixel_exact_scene(4, 4);
    scene.shader = Shader::gouraud;
    scene.mesh.positions = {at_pixel(scene, 1.2, 1.2, 8), at_pixel(scene, 1.8, 1.3, 8), at_pixel(scene, 1.4, 1.9, 8)};
    scene.mesh.colors = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
    scene.mesh.triangles.assign(count - 1, Triangle{0, 1, 2});
    add_triangle(scene.mesh, scene.mesh.positions[0], scene.mesh.positions[1], scene.mesh.positions[2]);
    scene.mesh.colors.resize(6, glm::vec3(1, 0, 0));
    const auto start = std::chrono::steady_clock::now();
    const RenderResult result = render(scene, RenderOptions::exact());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WARN("10M triangles on one pixel took " << seconds << " s");
    STABILITY_CHECK_FINITE(result);
    CHECK(result.stats.triangles_in == count);
    CHECK(result.stats.triangles_drawn == count);
    CHECK(result.stats.samples_covered == count);
    CHECK(result.stats.samples_shaded == count);  // Gouraud: Overdraw::automatic shades every layer
    CHECK(result.image.at(1, 1) == glm::vec3(1, 0, 0));
    CHECK(count_not(result.image) == 1);
}
