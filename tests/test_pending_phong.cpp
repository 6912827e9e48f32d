// Phong with per-sample light vectors shades the visible samples of several
// triangles together (PendingPhongSamples, src/fill_types.hpp): a batch
// holds samples of many small triangles, and is shaded when it is full, when
// a triangle of another material comes, or when the band ends. The general
// kernel (RenderOptions::specialize_effects = false) still shades each
// triangle's samples on their own, so comparing the two checks that the
// joint batches change no bit, count alike, and write in triangle order
// (overlapping triangles whose samples wait in one batch).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "phongrast/render.hpp"
#include "same_render_stats.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;

namespace {

/// A sphere of small triangles (two or three samples each at 96x96), coloured
/// by position; with `materials`, every third face shiny, the others matte
/// (so batches end at every change of material).
Scene small_triangles_scene(bool materials) {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(40, 80, 1.0);
    test_meshes::color_by_position(scene.mesh);
    if (materials) {
        scene.mesh.materials = {test_meshes::face_material("matte", glm::vec3(0.9f, 0.2f, 0.1f), glm::vec3(0.0f), 1.0f),
                                test_meshes::face_material("shiny", glm::vec3(0.1f, 0.3f, 0.8f), glm::vec3(0.9f), 20.0f)};
        for (std::size_t t = 0; t < scene.mesh.triangles.size(); ++t) {
            scene.mesh.face_materials.push_back(t % 3 == 0 ? 1 : 0);
        }
    }
    scene.camera.eye = {0.3, 0.4, 3.2};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.5;
    scene.image = {96, 96, {0.1f, 0.2f, 0.3f}};
    scene.material.n = 16;
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}, {{-3, 1, 2}, {0.4f, 0.3f, 0.2f}}, {{0, -3, 2}, {0.2f, 0.2f, 0.3f}}};
    scene.shader = Shader::phong;
    return scene;
}

/// Three stacked copies of one small fan of triangles at the same depth, each
/// in its own colour: every sample is covered three times, at equal depth, by
/// triangles drawn one after another, so their samples wait in the same
/// batch and only the write order decides the picture.
Scene stacked_fans_scene() {
    Scene scene;
    const int fan = 12;
    for (int copy = 0; copy < 3; ++copy) {
        const std::uint32_t centre = static_cast<std::uint32_t>(scene.mesh.positions.size());
        scene.mesh.positions.push_back({0, 0, 0});
        for (int k = 0; k < fan; ++k) {
            const double angle = 6.283185307179586 * k / fan;
            scene.mesh.positions.push_back({0.3 * std::cos(angle), 0.3 * std::sin(angle), 0});
        }
        for (int k = 0; k < fan; ++k) {
            scene.mesh.triangles.push_back({centre, centre + 1 + static_cast<std::uint32_t>(k),
                                            centre + 1 + static_cast<std::uint32_t>((k + 1) % fan)});
        }
        for (int v = 0; v <= fan; ++v) {
            scene.mesh.colors.push_back(copy == 0 ? glm::vec3(1, 0, 0) : copy == 1 ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
        }
    }
    scene.camera.eye = {0, 0, 2};
    scene.camera.focal = 1;
    scene.camera.sensor_height = scene.camera.sensor_width = 1;
    scene.image = {24, 24, {0, 0, 0}};
    scene.lights = {{{1, 1, 2}, {1, 1, 1}}};
    scene.lighting = parse_lighting("ambient+diffuse");  // no white highlight: a sample's colour is its triangle's
    scene.shader = Shader::phong;
    return scene;
}

void check_joint_batches_change_nothing(const Scene& scene, RenderOptions options) {
    options.specialize_effects = false;
    const RenderResult general = render(scene, options);
    options.specialize_effects = true;
    const RenderResult joint = render(scene, options);
    CHECK(test_render_modes::same_bits(joint.image, general.image));
    check_same_render_stats(joint.stats, general.stats);
}

}  // namespace

TEST_CASE("Phong's samples of many triangles shaded in one batch are those shaded triangle by triangle") {
    int compared = 0;
    for (bool materials : {false, true}) {
        const Scene scene = small_triangles_scene(materials);
        for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
            for (Overdraw overdraw : {Overdraw::shade_all, Overdraw::shade_visible}) {
                for (Precision precision : {Precision::single_float, Precision::double_float}) {
                    for (int threads : {1, 2}) {
                        for (int samples : {1, 3}) {
                            INFO("materials " << materials << ", depth buffer "
                                              << (visibility == Visibility::depth_buffer) << ", shade all "
                                              << (overdraw == Overdraw::shade_all) << ", double "
                                              << (precision == Precision::double_float) << ", threads " << threads
                                              << ", samples " << samples);
                            RenderOptions options = RenderOptions::exact();
                            options.visibility = visibility;
                            options.overdraw = overdraw;
                            options.precision = precision;
                            options.threads = threads;
                            options.samples_per_axis = samples;
                            check_joint_batches_change_nothing(scene, options);
                            ++compared;
                        }
                    }
                }
            }
        }
    }
    CHECK(compared == 2 * 2 * 2 * 2 * 2 * 2);
    // Most triangles show two or three samples: the case the joint batches are for.
    const RenderResult result = render(small_triangles_scene(false), RenderOptions::exact());
    CHECK(result.stats.samples_shaded < 4 * result.stats.triangles_drawn);
}

TEST_CASE("joint Phong batches keep each lighting set, one colour and the orthographic camera") {
    Scene scene = small_triangles_scene(false);
    for (const char* lighting : {"diffuse", "specular", "full", "ambient+specular", "diffuse+specular"}) {
        INFO(lighting);
        scene.lighting = parse_lighting(lighting);
        check_joint_batches_change_nothing(scene, RenderOptions::exact());
    }
    scene.lighting = parse_lighting("full");
    Scene one_colour = scene;
    one_colour.mesh.colors.assign(one_colour.mesh.positions.size(), {0.3f, 0.6f, 0.9f});
    check_joint_batches_change_nothing(one_colour, RenderOptions::exact());
    Scene orthographic = scene;
    orthographic.camera = Camera::orthographic({0.3, 0.4, 3.2}, {0, 0, 0}, {0, 1, 0}, 2.5, 2.5);
    check_joint_batches_change_nothing(orthographic, RenderOptions::exact());
}

TEST_CASE("samples of overlapping triangles waiting in one batch are written in painter's order") {
    const Scene scene = stacked_fans_scene();
    for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
        for (Overdraw overdraw : {Overdraw::shade_all, Overdraw::shade_visible}) {
            INFO("depth buffer " << (visibility == Visibility::depth_buffer) << ", shade all "
                                 << (overdraw == Overdraw::shade_all));
            RenderOptions options = RenderOptions::exact();
            options.visibility = visibility;
            options.overdraw = overdraw;
            options.threads = 1;
            check_joint_batches_change_nothing(scene, options);
            // Equal keys keep the mesh's order in painter's order, and the depth
            // buffer lets an equal depth win: the last copy (blue) shows.
            const RenderResult result = render(scene, options);
            const glm::vec3 centre = result.image.pixels[12 * 24 + 12];
            CHECK(centre.b > 0.0f);
            CHECK(centre.r == 0.0f);
            CHECK(centre.g == 0.0f);
        }
    }
}
