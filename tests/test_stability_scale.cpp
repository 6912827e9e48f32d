// Huge and tiny coordinates: a scene scaled by 1e-6 and 1e6, translated by
// 1e7, and seen as the seed's data was (eye 15000 units away, focal 70) must
// give the unscaled picture; projected coordinates of 1e9 pixels and more must
// not overflow the fixed-point rasterizer.
//
// Tolerance for "the same picture": every transform here is exact in real
// arithmetic, so the only differences are rounding. Positions are double
// until camera space, where the eye is subtracted first, so the snapped
// vertices differ by at most one 1/256 px step, which can move an edge over a
// pixel centre only when the centre lies within 1/256 px of the edge: at most
// 0.5% of the covered pixels may change coverage (measured: far fewer). Every
// other pixel must agree to 1e-4 in each channel (float shading of values that
// differ in their last bits; measured below 1e-5).
#include <catch2/catch.hpp>

#include "test_meshes.hpp"
#include "test_stability_common.hpp"

using namespace phongrast;
using stability::max_channel_difference;

namespace {

/// A torus with vertex colours, lit by two lights, seen from the side.
Scene base_scene(Shader shader) {
    Scene scene;
    scene.mesh = test_meshes::torus(48, 24, 1.0, 0.35);
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y / 0.35, 0.5 - 0.4 * p.z));
    }
    scene.camera.eye = {0.5, 2.0, 3.5};
    scene.camera.lookat = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 1.5;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.2;
    scene.image = {96, 96, {0, 0, 0}};
    scene.material.n = 12;
    scene.lights = {{{2, 3, 2}, {1, 1, 1}}, {{-3, 0.5, 1}, {0.4f, 0.3f, 0.8f}}};
    scene.shader = shader;
    return scene;
}

/// Every point p -> scale * p + offset; focal and sensor scale with it, so the picture is unchanged.
Scene transformed(Scene scene, double scale, const glm::dvec3& offset) {
    for (glm::dvec3& p : scene.mesh.positions) p = p * scale + offset;
    scene.camera.eye = scene.camera.eye * scale + offset;
    scene.camera.lookat = scene.camera.lookat * scale + offset;
    scene.camera.focal *= scale;
    scene.camera.sensor_height *= scale;
    scene.camera.sensor_width *= scale;
    for (PointLight& light : scene.lights) light.position = light.position * scale + offset;
    return scene;
}

struct Comparison {
    std::size_t covered = 0;         ///< pixels covered in the reference
    std::size_t coverage_flips = 0;  ///< pixels background in one image only
    float worst = 0.0f;              ///< largest channel difference where both are covered
};

Comparison compare(const Image& reference, const Image& other, const glm::vec3& background) {
    Comparison c;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        const bool a = reference.pixels[i] != background, b = other.pixels[i] != background;
        c.covered += a;
        if (a != b) {
            ++c.coverage_flips;
        } else if (a) {
            c.worst = std::max(c.worst, max_channel_difference(reference.pixels[i], other.pixels[i]));
        }
    }
    return c;
}

void check_same_picture(double scale, const glm::dvec3& offset, const char* what) {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const RenderOptions& preset : {RenderOptions::seed(), RenderOptions::exact()}) {
            for (Precision precision : {Precision::single_float, Precision::double_float}) {
                RenderOptions options = preset;
                options.precision = precision;
                const Scene reference_scene = base_scene(shader);
                const RenderResult reference = render(reference_scene, options);
                const RenderResult result = render(transformed(reference_scene, scale, offset), options);
                const Comparison c = compare(reference.image, result.image, reference_scene.image.background);
                INFO(what << ", " << to_string(shader) << (preset.border == BorderPolicy::clip ? " exact" : " seed")
                          << (precision == Precision::double_float ? " double" : " float") << ": " << c.coverage_flips
                          << " coverage flips of " << c.covered << ", worst " << c.worst);
                STABILITY_CHECK_FINITE(result);
                REQUIRE(c.covered > 2000);
                CHECK(c.coverage_flips * 200 <= c.covered);
                CHECK(c.worst <= 1e-4f);
            }
        }
    }
}

}  // namespace

TEST_CASE("scaled by 1e-6: the unscaled picture (within the stated tolerance)") {
    check_same_picture(1e-6, glm::dvec3(0.0), "x 1e-6");
}

TEST_CASE("scaled by 1e6: the unscaled picture (within the stated tolerance)") {
    check_same_picture(1e6, glm::dvec3(0.0), "x 1e6");
}

TEST_CASE("translated by 1e7: the untranslated picture (within the stated tolerance)") {
    check_same_picture(1.0, glm::dvec3(1e7, -1e7, 1e7), "+ 1e7");
}

TEST_CASE("the seed's camera, 15000 units away with focal 70: the picture at 1/1000 scale") {
    // The base camera is 4.06 units from the torus with focal 1.5; scaled so
    // that the eye is 15000 units away, focal and sensor follow (focal 5540).
    // Then, the seed's own numbers: eye 15000 away, focal 70, sensor 15, and
    // a mesh sized to fill the view, compared with everything / 1000.
    const double distance = glm::length(base_scene(Shader::phong).camera.eye);
    check_same_picture(15000.0 / distance, glm::dvec3(0.0), "eye 15000 away");
    Scene seed_like = base_scene(Shader::phong);
    seed_like.camera.eye = glm::normalize(seed_like.camera.eye) * 15.0;
    seed_like.camera.focal = 0.07;
    seed_like.camera.sensor_height = seed_like.camera.sensor_width = 0.015;
    for (glm::dvec3& p : seed_like.mesh.positions) p *= 1.3;
    for (PointLight& light : seed_like.lights) light.position *= 5.0;
    const RenderResult reference = render(seed_like);
    const RenderResult far = render(transformed(seed_like, 1000.0, glm::dvec3(0.0)));
    const Comparison c = compare(reference.image, far.image, seed_like.image.background);
    INFO(c.coverage_flips << " coverage flips of " << c.covered << ", worst " << c.worst);
    STABILITY_CHECK_FINITE(far);
    REQUIRE(c.covered > 2000);
    CHECK(c.coverage_flips * 200 <= c.covered);
    CHECK(c.worst <= 1e-4f);
}

TEST_CASE("projected coordinates of 1e9 pixels and beyond: clipped to the guard band, no fixed-point overflow") {
    // Vertices 1e9 to 1e300 pixels out: the triangle covers the whole
    // image, whose every pixel must be covered exactly once and lit finitely.
    for (double reach : {1e9, 1e12, 1e15, 1e300}) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            Scene scene = stability::pixel_exact_scene();
            scene.shader = shader;
            scene.lighting = Lighting::full();
            scene.lights = {{{0.3, 0.2, -1}, {1, 1, 1}}};
            const double far = reach / 64.0 * 8.0;  // world units at depth 8 for `reach` pixels
            stability::add_triangle(scene.mesh, {-far, -far, -8}, {far, -far, -8}, {0, far, -8});
            const RenderResult result = render(scene, RenderOptions::exact());
            INFO("reach " << reach << " px, " << to_string(shader));
            STABILITY_CHECK_FINITE(result);
            CHECK(result.stats.triangles_clipped == 1);
            CHECK(result.stats.samples_shaded == 64u * 64u);
            CHECK(stability::count_not(result.image) == 64u * 64u);
        }
    }
    // One vertex 1e9 px out, two inside: a sliver reaching across the image.
    Scene scene = stability::pixel_exact_scene();
    stability::add_triangle(scene.mesh, stability::at_pixel(scene, 10.3, 10.3, 8), stability::at_pixel(scene, 10.3, 20.7, 8),
                            stability::at_pixel(scene, 1e9, 15.1, 8));
    const RenderResult result = render(scene, RenderOptions::exact());
    STABILITY_CHECK_FINITE(result);
    CHECK(result.image.at(15, 12) == stability::kWhite);  // near the two close vertices
    CHECK(result.image.at(15, 63) == stability::kWhite);  // the sliver still spans 10 rows at the right border
    CHECK(result.image.at(5, 63) == stability::kBackground);
}

TEST_CASE("scaled by 1e29, just inside float's drawable depth: the unscaled picture") {
    check_same_picture(1e29, glm::dvec3(0.0), "x 1e29");
}

TEST_CASE("scaled by 1e31, beyond float's drawable depth: float skips every triangle, double draws the picture") {
    // Float weighs each corner by 1/z_c; past 1e30 (kMaxDrawableDepth) those
    // weights and their sum leave float's normal range and pixels would be NaN.
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        const Scene reference_scene = base_scene(shader);
        const Scene far = transformed(reference_scene, 1e31, glm::dvec3(0.0));
        RenderOptions single = RenderOptions::exact();
        single.precision = Precision::single_float;
        const RenderResult skipped = render(far, single);
        INFO(to_string(shader));
        STABILITY_CHECK_FINITE(skipped);
        CHECK(skipped.stats.triangles_out_of_range == far.mesh.triangles.size());
        CHECK(skipped.stats.triangles_drawn == 0);
        for (const glm::vec3& p : skipped.image.pixels) REQUIRE(p == far.image.background);

        RenderOptions twice = RenderOptions::exact();
        twice.precision = Precision::double_float;
        const RenderResult reference = render(reference_scene, twice);
        const RenderResult drawn = render(far, twice);
        STABILITY_CHECK_FINITE(drawn);
        CHECK(drawn.stats.triangles_out_of_range == 0);
        const Comparison c = compare(reference.image, drawn.image, reference_scene.image.background);
        REQUIRE(c.covered > 2000);
        CHECK(c.coverage_flips * 200 <= c.covered);
        CHECK(c.worst <= 1e-4f);
    }
}
