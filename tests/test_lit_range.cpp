// Lit values beyond float's range: a scene whose colours, material and lights
// could light a channel past kMaxLitValue (1e30, src/validation.hpp) is refused
// with a message naming what to scale, before anything is drawn; up to that
// bound every pixel is finite, supersampled too. Found by fuzz_ply: a PLY
// vertex colour of 3e38 lit to infinity, which only the last guard caught.
#include <cmath>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"

using namespace phongrast;
using Catch::Matchers::Contains;

namespace {

Scene tetrahedron_scene() {
    Scene scene;
    scene.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    scene.mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    scene.camera.eye = {0.3, 0.4, 5};
    scene.lights = {{{2, 3, 4}, {1, 1, 1}}, {{-2, 3, 4}, {1, 1, 1}}};
    scene.image.rows = scene.image.columns = 32;
    return scene;
}

void check_finite(const RenderResult& result) {
    for (const glm::vec3& p : result.image.pixels) {
        REQUIRE(std::isfinite(p.x));
        REQUIRE(std::isfinite(p.y));
        REQUIRE(std::isfinite(p.z));
    }
    CHECK(result.stats.nonfinite_values_replaced == 0);
}

}  // namespace

TEST_CASE("a vertex colour that could be lit past 1e30 is refused, naming the vertex") {
    Scene scene = tetrahedron_scene();
    scene.mesh.colors.assign(4, glm::vec3(0.5f));
    scene.mesh.colors[2] = {0.5f, 2e38f, 0.5f};
    // ka Ia + 2 kd Ip = 0.02 + 1.6: 2e38 could be lit to 3.24e38.
    CHECK_THROWS_WITH(render(scene), Contains("mesh: colour of vertex 2 (0.5, 2e+38, 0.5) could be lit to 3.24e+38") &&
                                         Contains("expected at most 1e+30"));
    // Negative colours count by their magnitude.
    scene.mesh.colors[2] = {0.5f, -1e30f, 0.5f};
    CHECK_THROWS_WITH(render(scene), Contains("mesh: colour of vertex 2"));
}

TEST_CASE("lights and material that could light a white surface past 1e30 are refused") {
    Scene scene = tetrahedron_scene();
    scene.lights[1].intensity = glm::vec3(2e30f);
    // Specular alone: ks Ip summed over the lights does not scale with the colour.
    CHECK_THROWS_WITH(render(scene), Contains("lights: the specular term") && Contains("could reach 2e+30") &&
                                         Contains("expected at most 1e+30"));
    scene.material.ks = glm::vec3(0.0f);
    // No vertex colours: the surface is white, ka Ia + kd (Ip1 + Ip2) = 0.02 + 0.8 * (2e30 + 1).
    CHECK_THROWS_WITH(render(scene), Contains("material and lights: a white surface could be lit to 1.6e+30"));
    scene.material.kd = glm::vec3(0.4f);
    const RenderResult result = render(scene);
    check_finite(result);
    CHECK(result.stats.triangles_drawn > 0);
}

TEST_CASE("only the selected terms count: huge lights are fine for an ambient-only render") {
    Scene scene = tetrahedron_scene();
    scene.lights[0].intensity = glm::vec3(1e35f);
    CHECK_THROWS_AS(render(scene), std::invalid_argument);
    scene.lighting = Lighting::only_ambient();
    const RenderResult result = render(scene);
    check_finite(result);
    CHECK(result.stats.triangles_drawn > 0);
}

TEST_CASE("colours lit up to the bound give finite pixels, for every shader and with 16 x 16 supersampling") {
    Scene scene = tetrahedron_scene();
    // 6e29 * (0.02 + 1.6) + 2 = 9.7e29: just within the bound.
    scene.mesh.colors = {{6e29f, 6e29f, 6e29f}, {-6e29f, 6e29f, 0}, {6e29f, -6e29f, 6e29f}, {0, 6e29f, -6e29f}};
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        scene.shader = shader;
        for (RenderOptions options : {RenderOptions::seed(), RenderOptions::exact()}) {
            for (int samples : {1, 16}) {
                options.samples_per_axis = samples;
                INFO(to_string(shader) << ", " << samples << " samples per axis");
                const RenderResult result = render(scene, options);
                check_finite(result);
                float largest = 0.0f;
                for (const glm::vec3& p : result.image.pixels) largest = std::max({largest, p.x, p.y, p.z});
                CHECK(largest > 1e29f);  // the colours did light, far beyond 1
                CHECK(largest <= 1e30f);
            }
        }
    }
}
