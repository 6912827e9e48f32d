// Spans of a triangle painted whole are shaded in vector batches
// (fill_kernels.hpp: fill_span_lanes()) or, in the AVX2 float kernels, by
// span writers of their own (fill_span_writers.hpp: Gouraud's and Phong's
// ambient-only interpolation, short spans in four lanes and long ones eight
// at a time; flat's and a uniform ambient's one colour in groups of eight);
// spans the depth buffer tests are shaded sample by sample. On triangles that
// do not overlap the two must paint the same bits: this compares them where
// the spans are long and where they are 1-3 samples.
#include <cstdint>
#include <string>

#include <catch2/catch.hpp>

#include "fill_dispatch.hpp"
#include "phongrast/render.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

/// Four large triangles around the image centre, none overlapping another,
/// tilted in depth (so perspective-correct weights differ from screen-space
/// ones) and coloured per vertex.
Scene fan_scene() {
    Scene scene;
    const double z[5] = {0.0, -0.7, 0.4, -0.2, 0.6};
    scene.mesh.positions = {{0.0, 0.0, z[0]}, {1.0, 0.0, z[1]}, {0.0, 1.0, z[2]}, {-1.0, 0.0, z[3]}, {0.0, -1.0, z[4]}};
    scene.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    scene.mesh.colors = {{0.9f, 0.1f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.1f, 0.3f, 0.9f}, {0.7f, 0.7f, 0.1f}, {0.3f, 0.6f, 0.6f}};
    scene.camera = Camera::look_at({0.3, 0.2, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.2, 1.0, 1.0);
    scene.image = {131, 157, {0.0f, 0.0f, 0.0f}};
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.5f), 12.0f};
    scene.lights = {{{2.0, 2.0, 3.0}, {1.0f, 0.9f, 0.8f}}, {{-2.0, 1.0, 1.0}, {0.3f, 0.4f, 0.9f}}};
    return scene;
}

/// The scene painted in painter's order with every layer shaded (spans
/// painted whole: the batches, or a kernel's own span code) and through the
/// depth buffer (sample by sample), with kernels of `isa`.
struct TwoFills {
    RenderResult batched, one_by_one;
};
TwoFills render_both_ways(const Scene& scene, const RenderOptions& options, detail::KernelIsa isa) {
    detail::override_kernel_isa(isa);
    RenderOptions painter = options;
    painter.visibility = Visibility::painter;
    painter.overdraw = Overdraw::shade_all;
    RenderOptions depth_buffer = options;
    depth_buffer.visibility = Visibility::depth_buffer;
    TwoFills fills{render(scene, painter), render(scene, depth_buffer)};
    detail::override_kernel_isa(std::nullopt);
    return fills;
}

/// The two fills shaded as many samples, all finite, into the same bits.
void check_same(const TwoFills& fills) {
    // Enough of the picture to matter goes through the spans painted whole.
    REQUIRE(fills.batched.stats.samples_shaded > 5000);
    CHECK(fills.batched.stats.samples_shaded == fills.one_by_one.stats.samples_shaded);
    CHECK(fills.batched.stats.nonfinite_values_replaced == 0);
    CHECK(same_bits(fills.batched.image, fills.one_by_one.image));
}

/// The kernels whose spans are painted whole by batches or span writers.
struct ShadingCase {
    Shader shader;
    Lighting lighting;
    bool uniform_color;
    std::string name;
};
const ShadingCase kShadingCases[] = {
    {Shader::gouraud, Lighting::full(), false, "Gouraud"},
    {Shader::gouraud, Lighting::full(), true, "Gouraud, one colour"},
    {Shader::phong, Lighting::only_ambient(), false, "Phong ambient-only"},
    {Shader::phong, Lighting::only_ambient(), true, "Phong ambient-only, one colour"},
    {Shader::flat, Lighting::full(), false, "flat"},
};

/// `scene` shaded as `c` says.
Scene shaded_as(Scene scene, const ShadingCase& c) {
    scene.shader = c.shader;
    scene.lighting = c.lighting;
    if (c.uniform_color) scene.mesh.colors.clear();
    return scene;
}

}  // namespace

TEST_CASE("long spans shaded in batches paint what sample-by-sample shading paints") {
    for (const ShadingCase& c : kShadingCases) {
        for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
            for (detail::KernelIsa isa : {detail::KernelIsa::baseline, detail::KernelIsa::avx2}) {
                if (!detail::kernel_isa_available(isa)) continue;
                const Scene scene = shaded_as(fan_scene(), c);
                INFO(c.name << ", " << mode.name << (isa == detail::KernelIsa::avx2 ? ", AVX2" : ", baseline"));
                // Spans of 30 and more samples: most of the picture goes through the batches.
                check_same(render_both_ways(scene, mode.options, isa));
            }
        }
    }
}

namespace {

/// A plane of 48 x 48 quads, tilted in depth and coloured per vertex, whose
/// triangles are a few samples wide: most of their spans are 1 to 3 samples
/// (under kMinLanesSpan), which the AVX2 kernels shade four lanes at a time.
Scene fine_grid_scene() {
    Scene scene;
    constexpr int kQuads = 48;
    scene.mesh = test_meshes::grid_plane(kQuads, 0.6, -0.3);
    for (std::size_t v = 0; v < scene.mesh.positions.size(); ++v) {
        const int i = static_cast<int>(v % (kQuads + 1)), j = static_cast<int>(v / (kQuads + 1));
        const glm::dvec3& p = scene.mesh.positions[v];
        scene.mesh.colors.push_back({0.5f + 0.5f * static_cast<float>(p.x), 0.5f + 0.5f * static_cast<float>(p.y),
                                     static_cast<float>((i * 7 + j * 3) % 11) / 10.0f});
    }
    scene.camera = Camera::look_at({0.3, 0.2, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.2, 1.0, 1.0);
    scene.image = {131, 157, {0.0f, 0.0f, 0.0f}};
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.5f), 12.0f};
    scene.lights = {{{2.0, 2.0, 3.0}, {1.0f, 0.9f, 0.8f}}, {{-2.0, 1.0, 1.0}, {0.3f, 0.4f, 0.9f}}};
    scene.shader = Shader::gouraud;
    return scene;
}

}  // namespace

TEST_CASE("short spans shaded in four lanes paint what sample-by-sample shading paints") {
    for (const ShadingCase& c : kShadingCases) {
        for (bool orthographic : {false, true}) {  // perspective-correct weights, then screen-linear ones
            Scene scene = shaded_as(fine_grid_scene(), c);
            if (orthographic) {
                const Camera pinhole = scene.camera;
                scene.camera = Camera::orthographic(pinhole.eye, pinhole.lookat, pinhole.up, 2.4, 2.4);
            }
            for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                for (detail::KernelIsa isa : {detail::KernelIsa::baseline, detail::KernelIsa::avx2}) {
                    if (!detail::kernel_isa_available(isa)) continue;
                    INFO(c.name << ", " << mode.name << (isa == detail::KernelIsa::avx2 ? ", AVX2" : ", baseline")
                                << (orthographic ? ", orthographic" : ""));
                    // 4,608 triangles over ~10,000 samples: about two samples each.
                    check_same(render_both_ways(scene, mode.options, isa));
                }
            }
        }
    }
}
