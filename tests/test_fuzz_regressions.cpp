// Inputs the fuzzers (fuzz/, run by .ci/fuzz.sh) found, kept as tests. The
// input files themselves are also in fuzz/corpus/ so the fuzzers start from them.
#include <cmath>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"

using namespace phongrast;

namespace {

// The scene fuzz/fuzz_common.hpp renders every accepted mesh with.
Scene fuzz_scene(const Mesh& mesh) {
    Scene scene;
    scene.camera.eye = {0.3, 0.4, 5};
    scene.lights = {{{2, 3, 4}, {1, 1, 1}}};
    scene.image.rows = scene.image.columns = 24;
    scene.mesh = mesh;
    return scene;
}

}  // namespace

// fuzz/corpus/obj/regression-huge-coordinate.obj: a vertex at y = 7.8e50,
// behind the eye. Clipping it at the near plane interpolates its position in
// float, where 7.8e50 is infinite, so the new corner projects to NaN, which
// the fixed-point snapping could not take (signed integer overflow in
// edge_value). Such a corner is skipped with its triangle; the rest draws.
TEST_CASE("a vertex beyond float's range behind the eye: finite picture, no overflow, the rest unchanged") {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 7.77777777777777777e50, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 3}, {0, 3, 2}, {0, 2, 3}};
    const Scene scene = fuzz_scene(mesh);
    for (const RenderOptions& preset : {RenderOptions::seed(), RenderOptions::exact()}) {
        for (Precision precision : {Precision::single_float, Precision::double_float}) {
            RenderOptions options = preset;
            options.precision = precision;
            options.threads = 1;
            const RenderResult result = render(scene, options);
            INFO("border " << (options.border == BorderPolicy::clip ? "clip" : "drop") << ", "
                           << (precision == Precision::double_float ? "double" : "float"));
            for (const glm::vec3& p : result.image.pixels) {
                REQUIRE(std::isfinite(p.x));
                REQUIRE(std::isfinite(p.y));
                REQUIRE(std::isfinite(p.z));
            }
            CHECK(result.stats.nonfinite_values_replaced == 0);
            CHECK(result.stats.triangles_in == 3);
            // Where the huge vertex cannot be represented (the seed drops the
            // triangle; a float render cannot clip it) the picture is exactly
            // that of the other two triangles.
            if (options.border == BorderPolicy::drop_triangle || precision == Precision::single_float) {
                Scene without = scene;
                without.mesh.triangles.erase(without.mesh.triangles.begin());
                const RenderResult rest = render(without, options);
                CHECK(result.image.pixels == rest.image.pixels);
                CHECK(result.stats.triangles_drawn == rest.stats.triangles_drawn);
            }
        }
    }
}

// fuzz/corpus/ply/regression-far-depth.ply (fuzz_ply, seed 9): a triangle
// whose corners lie 3e302 and 3e231 units in front of the eye. In single
// precision its depths are infinite, so the perspective weights (edge weight
// / z_c, renormalised by their sum) were 0 / 0 and 546 pixels came out NaN,
// caught only by the last guard. Past kMaxDrawableDepth (1e30 in float,
// 1e300 in double) a triangle is now skipped and counted out of range; the
// other triangle draws as without it.
TEST_CASE("a triangle beyond the drawable depth: skipped and counted, no NaN, the rest unchanged") {
    Mesh mesh;
    mesh.positions = {{-5.486124068793689e+303, 1.26e-321, 0.0},
                      {1.0, -5.486124068793689e+303, 8.062392e-317},
                      {1.724432241159034e-307, 2.69070206e-316, 2.121995792e-314},
                      {9.092228241674665e-307, 0.0, -3.152794309511059e+231}};
    mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0.7f, 0.4f}, {0.5f, 0.5f, 0.5f}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}};
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene scene = fuzz_scene(mesh);
        scene.shader = shader;
        Scene without = scene;
        without.mesh.triangles.pop_back();
        for (const RenderOptions& preset : {RenderOptions::seed(), RenderOptions::exact()}) {
            for (Precision precision : {Precision::single_float, Precision::double_float}) {
                RenderOptions options = preset;
                options.precision = precision;
                options.threads = 1;
                INFO(to_string(shader) << (options.border == BorderPolicy::clip ? " exact " : " seed ")
                                       << (precision == Precision::double_float ? "double" : "float"));
                const RenderResult result = render(scene, options);
                for (const glm::vec3& p : result.image.pixels) {
                    REQUIRE(std::isfinite(p.x));
                    REQUIRE(std::isfinite(p.y));
                    REQUIRE(std::isfinite(p.z));
                }
                CHECK(result.stats.nonfinite_values_replaced == 0);
                const RenderResult rest = render(without, options);
                CHECK(result.image.pixels == rest.image.pixels);
                // The seed's border rule drops it first (its corners project outside the image).
                CHECK(result.stats.triangles_out_of_range + result.stats.triangles_dropped ==
                      rest.stats.triangles_out_of_range + rest.stats.triangles_dropped + 1);
            }
        }
    }
}
