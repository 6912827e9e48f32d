// A material per face (contract "Materials"): the precedence object > scene
// > face > base, field by field; each triangle lit with its own material in
// all three shaders (every pixel of a mixed picture is the pixel of the
// picture with that triangle's material everywhere); the effect set is the
// union over the materials used; glTF's colour factor multiplies the colour.
#include <cstring>
#include <memory>
#include <vector>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"
#include "scene_assembly.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

Scene lit_scene(Shader shader) {
    Scene scene;
    scene.camera.eye = glm::dvec3(0.5, 0.8, 3.0);
    scene.camera.lookat = glm::dvec3(0.0);
    scene.image.rows = scene.image.columns = 40;
    scene.image.background = glm::vec3(0.1f, 0.2f, 0.3f);
    scene.material = PhongMaterial{glm::vec3(0.2f), glm::vec3(0.7f, 0.6f, 0.5f), glm::vec3(0.8f), 12.0f};
    scene.lights = {PointLight{glm::dvec3(2.0, 3.0, 4.0), glm::vec3(1.0f, 0.9f, 0.8f)},
                    PointLight{glm::dvec3(-3.0, 1.0, 2.0), glm::vec3(0.3f, 0.4f, 0.9f)}};
    scene.shader = shader;
    return scene;
}

/// A coloured sphere whose faces use material 0 (matte red) or, every third, 1 (shiny blue).
Mesh two_material_sphere() {
    Mesh mesh = test_meshes::uv_sphere(10, 14, 0.8);
    test_meshes::color_by_position(mesh);
    mesh.materials = {test_meshes::face_material("matte", glm::vec3(0.9f, 0.2f, 0.1f), glm::vec3(0.0f), 1.0f),
                      test_meshes::face_material("shiny", glm::vec3(0.1f, 0.3f, 0.8f), glm::vec3(0.9f), 20.0f)};
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) mesh.face_materials.push_back(t % 3 == 0 ? 1 : 0);
    return mesh;
}

}  // namespace

TEST_CASE("each field of a face's material comes from the object, the scene, the face, then the base") {
    Mesh mesh = test_meshes::unit_cube();
    FaceMaterial first;
    first.coefficients.kd = glm::vec3(1.0f, 0.0f, 0.0f);  // loses to the object's kd
    first.coefficients.n = 5.0f;                           // wins: nothing above gives n
    first.coefficients.ka = glm::vec3(0.9f);               // loses to the scene's ka
    FaceMaterial second;
    second.coefficients.ks = glm::vec3(0.3f);
    mesh.materials = {first, second};
    mesh.face_materials.assign(mesh.triangles.size(), kNoIndex);
    mesh.face_materials[0] = 0;
    mesh.face_materials[1] = 1;

    Scene scene = lit_scene(Shader::phong);
    scene.material = PhongMaterial{glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(1.0f), 1.0f};
    scene.material_fields.ka = glm::vec3(0.3f);
    SceneObject object{std::make_shared<const Mesh>(mesh), glm::dmat4(1.0), {}, {}, {}};
    object.material.kd = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.objects.push_back(object);

    detail::AssembledScene assembled;
    detail::NormalsScratch scratch;
    detail::assemble_scene(scene, assembled, scratch);
    REQUIRE(assembled.surfaces.size() == 3);
    REQUIRE(assembled.triangle_surfaces.size() == mesh.triangles.size());
    const auto material_of = [&](std::size_t t) { return assembled.surfaces[assembled.triangle_surfaces[t]].material; };
    const PhongMaterial a = material_of(0), b = material_of(1), none = material_of(2);
    CHECK(a.ka == glm::vec3(0.3f));
    CHECK(a.kd == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(a.ks == glm::vec3(1.0f));
    CHECK(a.n == 5.0f);
    CHECK(b.ka == glm::vec3(0.3f));
    CHECK(b.kd == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(b.ks == glm::vec3(0.3f));
    CHECK(b.n == 1.0f);
    CHECK(none.ka == glm::vec3(0.3f));
    CHECK(none.kd == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(none.ks == glm::vec3(1.0f));
    CHECK(none.n == 1.0f);
    for (std::size_t t = 3; t < mesh.triangles.size(); ++t) CHECK(assembled.triangle_surfaces[t] == assembled.triangle_surfaces[2]);
    // Vertices are split where faces of different materials meet: each vertex has one material.
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::uint32_t v : assembled.scene.mesh.triangles[t]) {
            CHECK(assembled.vertex_surfaces[v] == assembled.triangle_surfaces[t]);
        }
    }
}

TEST_CASE("every triangle is lit with its own material, in every shader and mode") {
    const Mesh mixed_mesh = two_material_sphere();
    Mesh all_matte = mixed_mesh, all_shiny = mixed_mesh;
    all_matte.face_materials.assign(mixed_mesh.triangles.size(), 0);
    all_shiny.face_materials.assign(mixed_mesh.triangles.size(), 1);
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene mixed = lit_scene(shader), matte = lit_scene(shader), shiny = lit_scene(shader);
        mixed.mesh = mixed_mesh;
        matte.mesh = all_matte;
        shiny.mesh = all_shiny;
        for (const auto& mode : test_render_modes::preset_precision_kernel_modes()) {
            INFO(to_string(shader) << ", " << mode.name);
            RenderOptions options = mode.options;
            options.aovs.id = true;
            const RenderResult picture = render(mixed, options);
            const Image a = render(matte, mode.options).image;
            const Image b = render(shiny, mode.options).image;
            CHECK(picture.stats.effects.specular);
            CHECK_FALSE(render(matte, mode.options).stats.effects.specular);  // no face is shiny: no specular work
            std::size_t from_a = 0, from_b = 0, wrong = 0;
            for (std::size_t p = 0; p < picture.image.pixels.size(); ++p) {
                const std::int32_t id = picture.aovs.id[p];
                const Image& expected = id < 0 || mixed_mesh.face_materials[std::size_t(id)] == 0 ? a : b;
                if (id >= 0) ++(mixed_mesh.face_materials[std::size_t(id)] == 0 ? from_a : from_b);
                if (std::memcmp(&picture.image.pixels[p], &expected.pixels[p], sizeof(glm::vec3)) != 0) ++wrong;
            }
            CHECK(wrong == 0);
            CHECK(from_a > 100);
            CHECK(from_b > 50);
        }
    }
}

TEST_CASE("a face material's colour factor multiplies the vertex colour") {
    Mesh mesh = test_meshes::uv_sphere(8, 12, 0.8);
    test_meshes::color_by_position(mesh);
    Mesh premultiplied = mesh;
    const glm::vec3 factor(0.5f, 1.0f, 0.25f);
    for (glm::vec3& c : premultiplied.colors) c *= factor;
    FaceMaterial tinted;
    tinted.color_factor = factor;
    mesh.materials = {tinted};
    mesh.face_materials.assign(mesh.triangles.size(), 0);
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene a = lit_scene(shader), b = lit_scene(shader);
        a.mesh = mesh;
        b.mesh = premultiplied;
        INFO(to_string(shader));
        CHECK(same_bits(render(a, RenderOptions::exact()).image, render(b, RenderOptions::exact()).image));
        CHECK(same_bits(render(a, RenderOptions::seed()).image, render(b, RenderOptions::seed()).image));
    }
}

TEST_CASE("an ambient-only picture of several materials is still painted in order") {
    // One colour per material: the fill may not skip painter's order as it does for one uniform colour.
    Mesh mesh = test_meshes::uv_sphere(8, 12, 0.8);
    FaceMaterial dark;
    dark.coefficients.ka = glm::vec3(0.1f);
    FaceMaterial light;
    light.coefficients.ka = glm::vec3(0.9f);
    mesh.materials = {dark, light};
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) mesh.face_materials.push_back(t % 2 == 0 ? 0 : 1);
    Scene scene = lit_scene(Shader::phong);
    scene.lighting = Lighting::only_ambient();
    scene.mesh = mesh;
    RenderOptions options = RenderOptions::exact();
    options.aovs.id = true;
    const RenderResult result = render(scene, options);
    CHECK(result.stats.triangles_sorted > 0);
    for (std::size_t p = 0; p < result.image.pixels.size(); ++p) {
        const std::int32_t id = result.aovs.id[p];
        if (id < 0) continue;
        const float expected = (id % 2 == 0 ? 0.1f : 0.9f) * scene.ambient.x;
        CHECK(result.image.pixels[p].x == expected);
    }
}
