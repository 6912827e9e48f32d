// Overdraw::shade_visible (shade only the samples a triangle paints last)
// against Overdraw::shade_all (the classic painter's fill): the same image bit
// for bit, the same coverage, and fewer samples shaded wherever triangles
// overlap; Overdraw::automatic picks shade_visible for per-pixel lighting and
// for textured scenes (a texture lookup per sample), in every shader.
#include <cstdint>
#include <memory>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"
#include "phongrast/texture.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

/// No lit colour of these scenes lands exactly on it, so a pixel equal to it was never written.
const glm::vec3 kBackground{0.3141f, 0.2718f, 0.1618f};

std::uint64_t count_written(const Image& image) {
    std::uint64_t written = 0;
    for (const glm::vec3& p : image.pixels) written += p != kBackground;
    return written;
}

/// A torus (its inner back faces show through in painter's order) plus a
/// soup of random coloured triangles crossing it and each other, some
/// reaching past the image border and behind the eye.
Scene random_scene(std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Scene scene;
    scene.mesh = test_meshes::torus(24, 12, 1.0, 0.35);
    for (int t = 0; t < 40; ++t) {
        const auto first = static_cast<std::uint32_t>(scene.mesh.positions.size());
        for (int k = 0; k < 3; ++k) scene.mesh.positions.push_back({coordinate(random), coordinate(random), coordinate(random)});
        scene.mesh.triangles.push_back({first, first + 1, first + 2});
    }
    for (std::size_t v = 0; v < scene.mesh.positions.size(); ++v) {
        scene.mesh.colors.push_back({unit(random), unit(random), unit(random)});
    }
    scene.camera.eye = {coordinate(random), 1.5 + unit(random), 3.0 + unit(random)};
    scene.camera.focal = 1.2;
    scene.image = {61 + static_cast<int>(seed % 7) * 9, 47 + static_cast<int>(seed % 5) * 11, kBackground};
    scene.material = {glm::vec3(0.1f), glm::vec3(0.7f), glm::vec3(0.5f), 16.0f};
    scene.lights = {{{2.0, 2.0, 2.0}, {1.0f, 0.9f, 0.8f}}, {{-2.0, 1.0, 0.5}, {0.3f, 0.4f, 0.9f}}};
    return scene;
}

/// random_scene() with (s, t) at every vertex (some outside [0, 1]) and a
/// random texture on the torus's faces, each axis its own wrap mode; the
/// soup's faces have no material: textured and untextured faces mixed.
Scene textured_scene(std::uint32_t seed, TextureWrap wrap_s, TextureWrap wrap_t) {
    Scene scene = random_scene(seed);
    std::mt19937 random(seed + 100);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), coordinate(-0.5f, 1.5f);
    auto image = std::make_shared<TextureImage>();
    image->rows = 5;
    image->columns = 7;
    image->name = "random";
    for (int k = 0; k < image->rows * image->columns; ++k) image->texels.push_back({unit(random), unit(random), unit(random)});
    Mesh& mesh = scene.mesh;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) mesh.texcoords.push_back({coordinate(random), coordinate(random)});
    mesh.texcoord_triangles = mesh.triangles;
    FaceMaterial material;
    material.name = "textured";
    material.texture = TextureMap{image, wrap_s, wrap_t};
    mesh.materials = {material};
    const std::size_t torus_triangles = mesh.triangles.size() - 40;
    mesh.face_materials.assign(mesh.triangles.size(), kNoIndex);
    std::fill(mesh.face_materials.begin(), mesh.face_materials.begin() + static_cast<std::ptrdiff_t>(torus_triangles), 0u);
    return scene;
}

RenderOptions with_overdraw(RenderOptions options, Overdraw overdraw) {
    options.overdraw = overdraw;
    return options;
}

}  // namespace

TEST_CASE("shade_visible paints the same image as shade_all, bit for bit, in every mode") {
    for (std::uint32_t seed = 1; seed <= 6; ++seed) {
        Scene scene = random_scene(seed);
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            scene.shader = shader;
            for (test_render_modes::RenderMode mode : test_render_modes::preset_precision_kernel_modes()) {
                mode.options.threads = 1 + static_cast<int>(seed % 2);
                const RenderResult all = render(scene, with_overdraw(mode.options, Overdraw::shade_all));
                const RenderResult visible = render(scene, with_overdraw(mode.options, Overdraw::shade_visible));
                INFO("seed " << seed << ", " << to_string(shader) << ", " << mode.name);
                CHECK(same_bits(all.image, visible.image));
                CHECK(all.stats.samples_covered == visible.stats.samples_covered);
                CHECK(all.stats.samples_shaded == all.stats.samples_covered);
                // Each written pixel shaded exactly once; the torus overlaps itself.
                CHECK(visible.stats.samples_shaded == count_written(visible.image));
                CHECK(visible.stats.samples_shaded < all.stats.samples_shaded);
                CHECK(visible.stats.nonfinite_values_replaced == 0);
            }
        }
    }
}

TEST_CASE("textured scenes: shade_visible paints shade_all's image bit for bit, and automatic picks it") {
    const TextureWrap wraps[] = {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat};
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        Scene scene = textured_scene(seed, wraps[seed % 3], wraps[(seed + 1) % 3]);
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            scene.shader = shader;
            for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest, TextureFilter::trilinear}) {
                for (test_render_modes::RenderMode mode : test_render_modes::preset_precision_kernel_modes()) {
                    mode.options.threads = 1 + static_cast<int>(seed % 2);
                    mode.options.texture_filter = filter;
                    const RenderResult all = render(scene, with_overdraw(mode.options, Overdraw::shade_all));
                    const RenderResult visible = render(scene, with_overdraw(mode.options, Overdraw::shade_visible));
                    const RenderResult automatic = render(scene, with_overdraw(mode.options, Overdraw::automatic));
                    INFO("seed " << seed << ", " << to_string(shader) << ", " << to_string(filter) << ", " << mode.name);
                    CHECK(same_bits(all.image, visible.image));
                    CHECK(same_bits(all.image, automatic.image));
                    // Counted by the textured kernels as they claim, not by a coverage pass of their own.
                    CHECK(visible.stats.samples_covered == all.stats.samples_covered);
                    CHECK(visible.stats.samples_shaded == count_written(visible.image));
                    CHECK(visible.stats.samples_shaded < all.stats.samples_shaded);
                    CHECK(automatic.stats.samples_shaded == visible.stats.samples_shaded);
                    CHECK(visible.stats.nonfinite_values_replaced == 0);
                }
            }
        }
    }
}

TEST_CASE("shade_visible with supersampling and partial lighting: the same image as shade_all") {
    Scene scene = random_scene(42);
    scene.shader = Shader::phong;
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        for (Lighting lighting : {Lighting::full(), Lighting{true, false, false}, Lighting{false, false, true}}) {
            scene.lighting = lighting;
            RenderOptions options = RenderOptions::exact();
            options.samples_per_axis = 2;
            options.sample_pattern = pattern;
            const RenderResult all = render(scene, with_overdraw(options, Overdraw::shade_all));
            const RenderResult visible = render(scene, with_overdraw(options, Overdraw::shade_visible));
            INFO(to_string(lighting) << (pattern == SamplePattern::rotated_grid ? ", rotated grid" : ", ordered grid"));
            CHECK(same_bits(all.image, visible.image));
            CHECK(visible.stats.samples_covered == all.stats.samples_covered);
            CHECK(visible.stats.samples_shaded < all.stats.samples_shaded);
            // Term counts follow the samples shaded.
            CHECK(visible.stats.ambient_evaluations <= all.stats.ambient_evaluations);
            CHECK(visible.stats.specular_evaluations <= all.stats.specular_evaluations);
        }
    }
}

TEST_CASE("with a depth buffer the overdraw setting changes nothing: the buffer shades as it tests") {
    Scene scene = random_scene(7);
    scene.shader = Shader::phong;
    RenderOptions options = RenderOptions::exact();
    options.visibility = Visibility::depth_buffer;
    const RenderResult all = render(scene, with_overdraw(options, Overdraw::shade_all));
    const RenderResult visible = render(scene, with_overdraw(options, Overdraw::shade_visible));
    CHECK(same_bits(all.image, visible.image));
    CHECK(all.stats.samples_shaded == visible.stats.samples_shaded);
    CHECK(all.stats.samples_covered == visible.stats.samples_covered);
    CHECK(all.stats.samples_shaded <= all.stats.samples_covered);
}

TEST_CASE("shade_visible: a triangle painted over entirely costs no shading, and equal depths keep mesh order") {
    // Two identical squares at the same depth: painter's order keeps mesh
    // order, so the second (red) one is the picture and the only one shaded.
    Scene scene;
    scene.image = {32, 32, kBackground};
    scene.camera.eye = {0, 0, 2};
    scene.camera.focal = 2;
    for (int copy = 0; copy < 2; ++copy) {
        const auto first = static_cast<std::uint32_t>(scene.mesh.positions.size());
        scene.mesh.positions.insert(scene.mesh.positions.end(), {{-0.3, -0.3, 0}, {0.3, -0.3, 0}, {0.3, 0.3, 0}, {-0.3, 0.3, 0}});
        const glm::vec3 color = copy == 0 ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
        scene.mesh.colors.insert(scene.mesh.colors.end(), 4, color);
        scene.mesh.triangles.push_back({first, first + 1, first + 2});
        scene.mesh.triangles.push_back({first, first + 2, first + 3});
    }
    scene.lights = {{{0, 0, 3}, {1, 1, 1}}};
    scene.material.ks = glm::vec3(0.0f);  // no white highlight: the blue channel tells the squares apart
    scene.shader = Shader::phong;
    const RenderResult all = render(scene, with_overdraw(RenderOptions::exact(), Overdraw::shade_all));
    const RenderResult visible = render(scene, with_overdraw(RenderOptions::exact(), Overdraw::shade_visible));
    REQUIRE(visible.stats.samples_covered > 100);
    CHECK(same_bits(all.image, visible.image));
    CHECK(all.stats.samples_shaded == visible.stats.samples_covered);
    CHECK(visible.stats.samples_shaded * 2 == visible.stats.samples_covered);
    const glm::vec3 centre = visible.image.at(16, 16);
    CHECK(centre.x > 0.0f);
    CHECK(centre.z == 0.0f);  // red, not blue
}

TEST_CASE("automatic overdraw, untextured: only Phong with diffuse or specular light shades the visible samples alone") {
    Scene scene = random_scene(3);
    struct Case {
        Shader shader;
        Lighting lighting;
        bool visible_only;
    };
    for (const Case& c : {Case{Shader::phong, Lighting::full(), true}, Case{Shader::phong, Lighting::only_diffuse(), true},
                          Case{Shader::phong, Lighting::only_specular(), true},
                          Case{Shader::phong, Lighting::only_ambient(), false}, Case{Shader::gouraud, Lighting::full(), false},
                          Case{Shader::flat, Lighting::full(), false}}) {
        scene.shader = c.shader;
        scene.lighting = c.lighting;
        for (bool specialize : {true, false}) {
            RenderOptions options = RenderOptions::exact();
            options.specialize_effects = specialize;
            REQUIRE(options.overdraw == Overdraw::automatic);
            const RenderResult automatic = render(scene, options);
            const RenderResult all = render(scene, with_overdraw(options, Overdraw::shade_all));
            INFO(to_string(c.shader) << ", " << to_string(c.lighting) << (specialize ? ", specialised" : ", general"));
            CHECK(same_bits(automatic.image, all.image));
            if (c.visible_only) {
                CHECK(automatic.stats.samples_shaded == count_written(automatic.image));
                CHECK(automatic.stats.samples_shaded < automatic.stats.samples_covered);
            } else {
                CHECK(automatic.stats.samples_shaded == automatic.stats.samples_covered);
            }
        }
    }
}
