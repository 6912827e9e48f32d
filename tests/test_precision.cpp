// Float against double: the same random scene rendered with
// RenderOptions::precision = single_float and double_float.
//
// What may differ, and the tolerance (derived in docs/robustness.md):
//   * Coverage never does for triangles in front of the near plane: positions,
//     depths and pixel coordinates are double in both pipelines until snapping.
//     Only triangles cut by the near plane get their new vertices from
//     Real-precision camera positions, so their edges may move by one 1/256 px
//     step; scenes here keep the camera outside the meshes, and the test checks
//     that the two renders wrote exactly the same samples.
//   * Colours are sums of at most 1 + 2 * lights terms, each a product of
//     inputs in [0, 1] (intensities up to 1) with unit-vector dot products.
//     Float rounds each operation by u = 2^-24 = 6e-8; normalising, dotting,
//     interpolating (perspective weights are renormalised by their sum) and
//     summing cost a few u per term, and (R.V)^n multiplies R.V's relative
//     error by n. Per pixel, with S = ka Ia + sum_lights Ip (kd + ks) bounding
//     the colour, the bound is  8 u (1 + n) S  per channel (measured: the
//     largest difference is about a fifth of it).
//   * Where a decision flips (N.L or R.V on either side of 0, the specular
//     switch of the contract at N.L = 0), the colour jumps by up to Ip ks.
//     These pixels need N.L or R.V within ~1e-6 of zero: at most 1 in 10^4
//     covered pixels over the whole run may exceed the bound.
#include <algorithm>
#include <random>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"
#include "test_stability_common.hpp"

using namespace phongrast;

namespace {

/// A random scene: a deformed sphere, a torus or a triangle soup, random
/// colours, camera outside the mesh, 1 to 3 lights, random material and shader.
Scene random_scene(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0), signed_unit(-1.0, 1.0);
    Scene scene;
    const int kind = static_cast<int>(rng() % 3);
    if (kind == 0) {
        scene.mesh = test_meshes::uv_sphere(4 + int(rng() % 12), 6 + int(rng() % 20), 1.0);
        for (glm::dvec3& p : scene.mesh.positions) p *= 0.8 + 0.4 * unit(rng);
    } else if (kind == 1) {
        scene.mesh = test_meshes::torus(6 + int(rng() % 20), 4 + int(rng() % 10), 1.0, 0.2 + 0.3 * unit(rng));
    } else {
        const int triangles = 1 + int(rng() % 40);
        for (int t = 0; t < triangles; ++t) {
            const glm::dvec3 centre(signed_unit(rng), signed_unit(rng), signed_unit(rng));
            for (int k = 0; k < 3; ++k) {
                scene.mesh.positions.push_back(centre + 0.6 * glm::dvec3(signed_unit(rng), signed_unit(rng), signed_unit(rng)));
            }
            const auto base = std::uint32_t(3 * t);
            scene.mesh.triangles.push_back({base, base + 1, base + 2});
        }
    }
    for (std::size_t i = 0; i < scene.mesh.positions.size(); ++i) {
        scene.mesh.colors.push_back(glm::vec3(unit(rng), unit(rng), unit(rng)));
    }
    // Eye 3 to 8 units from the origin (outside every mesh, which fits in radius ~1.7).
    glm::dvec3 direction;
    do {
        direction = {signed_unit(rng), signed_unit(rng), signed_unit(rng)};
    } while (glm::length(direction) < 0.2);
    scene.camera.eye = glm::normalize(direction) * (3.0 + 5.0 * unit(rng));
    scene.camera.lookat = 0.3 * glm::dvec3(signed_unit(rng), signed_unit(rng), signed_unit(rng));
    do {
        scene.camera.up = {signed_unit(rng), signed_unit(rng), signed_unit(rng)};
    } while (glm::length(glm::cross(glm::normalize(scene.camera.up),
                                    glm::normalize(scene.camera.lookat - scene.camera.eye))) < 0.1);
    scene.camera.focal = 0.5 + 2.0 * unit(rng);
    scene.camera.sensor_height = 0.5 + unit(rng);
    scene.camera.sensor_width = 0.5 + unit(rng);
    scene.image = {16 + int(rng() % 49), 16 + int(rng() % 49), {0, 0, 0}};
    scene.material.ka = glm::vec3(unit(rng), unit(rng), unit(rng));
    scene.material.kd = glm::vec3(unit(rng), unit(rng), unit(rng));
    scene.material.ks = glm::vec3(unit(rng), unit(rng), unit(rng));
    const float exponents[] = {0.0f, 1.0f, 5.0f, 32.0f, 100.0f};
    scene.material.n = exponents[rng() % 5];
    scene.ambient = glm::vec3(unit(rng), unit(rng), unit(rng));
    const int lights = 1 + int(rng() % 3);
    for (int k = 0; k < lights; ++k) {
        // 2.5 to 6 units out: never on the surface (that case has its own test).
        const glm::dvec3 position =
            glm::normalize(glm::dvec3(signed_unit(rng), signed_unit(rng), signed_unit(rng)) + glm::dvec3(1e-3)) *
            (2.5 + 3.5 * unit(rng));
        scene.lights.push_back({position, glm::vec3(unit(rng), unit(rng), unit(rng))});
    }
    const Shader shaders[] = {Shader::flat, Shader::gouraud, Shader::phong};
    scene.shader = shaders[rng() % 3];
    return scene;
}

float largest(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

float colour_bound(const Scene& scene) {
    float sum = largest(scene.material.ka * scene.ambient);
    for (const PointLight& light : scene.lights) {
        sum += largest(light.intensity) * (largest(scene.material.kd) + largest(scene.material.ks));
    }
    return sum;
}

}  // namespace

TEST_CASE("float and double renders of 400 random scenes agree within 8 u (1 + n) S, but for 1 in 10^4 pixels") {
    constexpr float kUnitRoundoff = 5.9604645e-8f;  // 2^-24
    std::mt19937 rng(20261122);
    std::uint64_t covered = 0, beyond = 0, coverage_differences = 0;
    float worst_ratio = 0.0f;
    for (int scene_index = 0; scene_index < 400; ++scene_index) {
        const Scene scene = random_scene(rng);
        RenderOptions options = (rng() % 2) ? RenderOptions::exact() : RenderOptions::seed();
        options.threads = 1;
        options.precision = Precision::single_float;
        const RenderResult single = render(scene, options);
        options.precision = Precision::double_float;
        const RenderResult twice = render(scene, options);
        INFO("scene " << scene_index);
        STABILITY_CHECK_FINITE(single);
        STABILITY_CHECK_FINITE(twice);
        // Same coverage: the same triangles set up and the same samples written.
        coverage_differences += single.stats.samples_shaded != twice.stats.samples_shaded;
        coverage_differences += single.stats.triangles_drawn != twice.stats.triangles_drawn;
        const float tolerance = 8.0f * kUnitRoundoff * (1.0f + scene.material.n) * colour_bound(scene);
        for (std::size_t i = 0; i < single.image.pixels.size(); ++i) {
            const glm::vec3 a = single.image.pixels[i], b = twice.image.pixels[i];
            if (b == scene.image.background && a == scene.image.background) continue;
            ++covered;
            const float difference = stability::max_channel_difference(a, b);
            worst_ratio = std::max(worst_ratio, difference / tolerance);
            beyond += difference > tolerance;
        }
    }
    INFO(covered << " covered pixels, " << beyond << " beyond the bound; worst difference / bound " << worst_ratio);
    CHECK(coverage_differences == 0);
    CHECK(covered > 100000);
    CHECK(beyond * 10000 <= covered);
    WARN("float vs double: " << covered << " covered pixels, " << beyond
                             << " beyond 8 u (1 + n) S; largest difference / bound = " << worst_ratio);
}
