// The fill kernels and the lighting lanes (exact Gouraud's vertices, the
// seed's corners) compiled for AVX2 (src/fill_kernels_avx2.hpp,
// src/lighting_avx2.cpp) against the baseline ones: the same image bit for
// bit in every shader, mode, precision and effect set, untextured and
// textured, so the picture does not depend on the CPU.
#include <cstdint>
#include <memory>
#include <random>

#include <catch2/catch.hpp>

#include "fill_dispatch.hpp"
#include "phongrast/render.hpp"
#include "phongrast/texture.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

/// Restores the automatic choice however the test ends.
struct IsaOverride {
    explicit IsaOverride(detail::KernelIsa isa) { detail::override_kernel_isa(isa); }
    ~IsaOverride() { detail::override_kernel_isa(std::nullopt); }
    IsaOverride(const IsaOverride&) = delete;
    IsaOverride& operator=(const IsaOverride&) = delete;
};

RenderResult render_with(detail::KernelIsa isa, const Scene& scene, const RenderOptions& options) {
    const IsaOverride use(isa);
    REQUIRE(detail::kernel_isa() == isa);
    return render(scene, options);
}

/// A sphere with random vertex colours and three lights; large triangles
/// (long spans, full vector batches) and, at the rim, tiny ones (scalar path).
Scene sphere_scene(std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(12 + static_cast<int>(seed % 3) * 10, 24, 1.0);
    for (std::size_t v = 0; v < scene.mesh.positions.size(); ++v) {
        scene.mesh.colors.push_back({unit(random), unit(random), unit(random)});
    }
    scene.camera.eye = {0.4 * unit(random), 0.6, 2.6 + unit(random)};
    scene.camera.focal = 1.5;
    scene.image = {97, 83, {0.05f, 0.05f, 0.1f}};
    scene.material = {glm::vec3(0.1f), glm::vec3(0.7f), glm::vec3(0.6f), seed % 2 ? 16.0f : 7.5f};
    scene.lights = {{{2.0, 2.0, 2.0}, {1.0f, 0.9f, 0.8f}},
                    {{-2.0, 1.0, 0.5}, {0.3f, 0.4f, 0.9f}},
                    {{0.0, -3.0, 1.0}, {0.5f, 0.5f, 0.5f}}};
    return scene;
}

/// sphere_scene() with a texture of random texels: (s, t) from the position,
/// reaching past [0, 1] so that the wrap modes matter, and a few faces
/// without texture coordinates (drawn with T = 1: a second, untextured material).
Scene textured_sphere_scene(std::uint32_t seed) {
    Scene scene = sphere_scene(seed);
    std::mt19937 random(seed + 100);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto image = std::make_shared<TextureImage>();
    image->rows = 5;
    image->columns = 7;
    image->name = "random";
    for (int k = 0; k < image->rows * image->columns; ++k) image->texels.push_back({unit(random), unit(random), unit(random)});
    TextureMap map;
    map.image = std::move(image);
    map.wrap_s = seed % 2 ? TextureWrap::mirrored_repeat : TextureWrap::repeat;
    map.wrap_t = seed % 2 ? TextureWrap::repeat : TextureWrap::clamp_to_edge;
    Mesh& mesh = scene.mesh;
    for (const glm::dvec3& p : mesh.positions) mesh.texcoords.push_back({float(1.7 * p.x + 0.4), float(1.3 * p.y - 0.1)});
    mesh.texcoord_triangles = mesh.triangles;
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 7) mesh.texcoord_triangles[t][1] = kNoIndex;
    FaceMaterial material;
    material.name = "textured";
    material.texture = map;
    mesh.materials = {material};
    mesh.face_materials.assign(mesh.triangles.size(), 0);
    return scene;
}

}  // namespace

TEST_CASE("AVX2 kernels paint the baseline kernels' image bit for bit") {
    if (!detail::kernel_isa_available(detail::KernelIsa::avx2)) {
        WARN("skipped: this build has no AVX2 kernels or this CPU has no AVX2 (the baseline kernels draw everything)");
        return;
    }
    CHECK(detail::kernel_isa() == detail::KernelIsa::avx2);  // the best one is the default
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        Scene scene = sphere_scene(seed);
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            scene.shader = shader;
            for (Lighting lighting : {Lighting::full(), Lighting::only_ambient(), Lighting::only_specular()}) {
                scene.lighting = lighting;
                for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                    const RenderResult baseline = render_with(detail::KernelIsa::baseline, scene, mode.options);
                    const RenderResult avx2 = render_with(detail::KernelIsa::avx2, scene, mode.options);
                    INFO("seed " << seed << ", " << to_string(shader) << ", " << to_string(lighting) << ", "
                                 << mode.name);
                    REQUIRE(baseline.stats.samples_shaded > 1000);
                    CHECK(same_bits(baseline.image, avx2.image));
                    CHECK(baseline.stats.samples_shaded == avx2.stats.samples_shaded);
                }
            }
        }
    }
}

// Textured faces have their own kernels (Phong's T x c, flat's and Gouraud's T x A + S).
TEST_CASE("AVX2 kernels paint the baseline kernels' textured image bit for bit") {
    if (!detail::kernel_isa_available(detail::KernelIsa::avx2)) {
        WARN("skipped: this build has no AVX2 kernels or this CPU has no AVX2 (the baseline kernels draw everything)");
        return;
    }
    for (std::uint32_t seed = 1; seed <= 2; ++seed) {
        Scene scene = textured_sphere_scene(seed);
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            scene.shader = shader;
            for (Lighting lighting : {Lighting::full(), Lighting::only_ambient(), Lighting::only_specular()}) {
                scene.lighting = lighting;
                for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest, TextureFilter::trilinear}) {
                    for (test_render_modes::RenderMode mode : test_render_modes::preset_precision_kernel_modes()) {
                        mode.options.texture_filter = filter;
                        const RenderResult baseline = render_with(detail::KernelIsa::baseline, scene, mode.options);
                        const RenderResult avx2 = render_with(detail::KernelIsa::avx2, scene, mode.options);
                        INFO("seed " << seed << ", " << to_string(shader) << ", " << to_string(lighting) << ", "
                                     << to_string(filter) << ", " << mode.name);
                        REQUIRE(baseline.stats.samples_shaded > 1000);
                        CHECK(same_bits(baseline.image, avx2.image));
                        CHECK(baseline.stats.samples_shaded == avx2.stats.samples_shaded);
                    }
                }
            }
        }
    }
}

TEST_CASE("an instruction set the build or the CPU lacks cannot be forced") {
    if (detail::kernel_isa_available(detail::KernelIsa::avx2)) {
        const IsaOverride use(detail::KernelIsa::baseline);
        CHECK(detail::kernel_isa() == detail::KernelIsa::baseline);
    } else {
        CHECK_THROWS_AS(detail::override_kernel_isa(detail::KernelIsa::avx2), std::invalid_argument);
        CHECK(detail::kernel_isa() == detail::KernelIsa::baseline);
    }
    detail::override_kernel_isa(std::nullopt);
    CHECK(detail::kernel_isa_available(detail::KernelIsa::baseline));
}
