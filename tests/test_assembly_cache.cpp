// A Renderer keeps a version-2 scene's assembly between frames
// (src/assembly_cache.cpp): an unchanged scene is not assembled again, and a
// scene edited in place between two frames (positions, texture coordinates,
// colours, materials, the texture's texels, an object's shared mesh) renders
// exactly what a fresh renderer renders. Texture images are scanned for
// non-finite texels once, and again when their texel array is replaced.
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "phongrast/render.hpp"
#include "scene_assembly.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

std::shared_ptr<TextureImage> checker_texture(int size) {
    auto image = std::make_shared<TextureImage>();
    image->rows = image->columns = size;
    image->name = "checker";
    for (int i = 0; i < size; ++i) {
        for (int j = 0; j < size; ++j) {
            const bool on = ((i / 4) + (j / 4)) % 2 == 0;
            image->texels.push_back(glm::vec3(on ? 0.9f : 0.2f, float(i) / float(size), float(j) / float(size)));
        }
    }
    return image;
}

/// A sphere with spherical texture coordinates, per-vertex colours and one textured material.
Mesh textured_sphere(const std::shared_ptr<const TextureImage>& image) {
    Mesh mesh = test_meshes::icosphere(6);
    mesh.colors.clear();
    for (const glm::dvec3& p : mesh.positions) {
        const glm::dvec3 n = glm::normalize(p);
        mesh.texcoords.push_back(glm::vec2(float(0.5 + std::atan2(n.z, n.x) / 6.283185307179586),
                                           float(0.5 + std::asin(n.y) / 3.141592653589793)));
        mesh.colors.push_back(glm::vec3(0.8f, 0.9f, float(0.5 + 0.5 * n.y)));
    }
    mesh.texcoord_triangles = mesh.triangles;
    FaceMaterial material;
    material.name = "checker";
    material.texture = TextureMap{image, TextureWrap::repeat, TextureWrap::repeat};
    mesh.materials = {material};
    mesh.face_materials.assign(mesh.triangles.size(), 0);
    return mesh;
}

Scene lit_scene(Shader shader) {
    Scene scene;
    scene.camera.eye = glm::dvec3(0.4, 0.7, 2.8);
    scene.camera.lookat = glm::dvec3(0.0);
    scene.image.rows = scene.image.columns = 64;
    scene.image.background = glm::vec3(0.1f, 0.2f, 0.3f);
    scene.material = PhongMaterial{glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.6f), 16.0f};
    scene.lights = {PointLight{glm::dvec3(2.0, 3.0, 4.0), glm::vec3(1.0f)},
                    PointLight{glm::dvec3(-3.0, 1.0, 2.0), glm::vec3(0.3f, 0.4f, 0.9f)}};
    scene.shader = shader;
    return scene;
}

}  // namespace

TEST_CASE("a Renderer draws a textured mesh edited in place between frames as a fresh renderer does") {
    for (const Shader shader : {Shader::phong, Shader::gouraud, Shader::flat}) {
        INFO("shader " << to_string(shader));
        const auto image = checker_texture(32);
        Scene scene = lit_scene(shader);
        scene.mesh = textured_sphere(image);
        Renderer renderer(RenderOptions::exact());
        const auto fresh = [&] { return render(scene, RenderOptions::exact()).image; };
        Image last = renderer.render(scene).image;
        CHECK(same_bits(last, fresh()));
        CHECK(same_bits(last, renderer.render(scene).image));  // unchanged: the kept assembly
        const auto check_edit = [&](const char* what) {
            INFO("after editing " << what);
            const Image now = renderer.render(scene).image;
            CHECK_FALSE(same_bits(now, last));  // the edit shows
            CHECK(same_bits(now, fresh()));
            last = now;
        };
        for (glm::dvec3& p : scene.mesh.positions) p *= 0.9;
        check_edit("positions");
        for (glm::vec2& st : scene.mesh.texcoords) st.x += 0.125f;
        check_edit("texture coordinates");
        for (glm::vec3& c : scene.mesh.colors) c.g *= 0.5f;
        check_edit("colours");
        scene.mesh.materials[0].coefficients.kd = glm::vec3(0.3f, 0.9f, 0.4f);
        check_edit("a face material");
        scene.material.ka = glm::vec3(0.4f);
        check_edit("the scene's material");
        for (glm::vec3& texel : image->texels) texel = glm::vec3(1.0f) - texel;  // in place, same array
        check_edit("the texels");
        std::swap(scene.mesh.triangles[0], scene.mesh.triangles[1]);  // the same triangles, another order
        std::swap(scene.mesh.texcoord_triangles[0], scene.mesh.texcoord_triangles[1]);
        CHECK(same_bits(renderer.render(scene).image, fresh()));
        scene.camera.eye = glm::dvec3(-1.0, 0.5, 2.6);  // the view changes, the assembly does not
        check_edit("the camera");
    }
}

TEST_CASE("SceneAssembly assembles again only when what it reads changed") {
    const auto image = checker_texture(16);
    Scene scene = lit_scene(Shader::phong);
    scene.mesh = textured_sphere(image);
    detail::SceneAssembly assembly;
    assembly.assemble(scene);
    assembly.assemble(scene);
    CHECK(assembly.assemblies == 1);
    scene.camera.eye.x += 0.5;
    scene.lights.pop_back();
    assembly.assemble(scene);
    CHECK(assembly.assemblies == 1);
    CHECK(assembly.assembled.scene.camera.eye == scene.camera.eye);  // the view fields are this frame's
    CHECK(assembly.assembled.scene.lights.size() == 1);
    scene.mesh.positions[7].y += 1e-9;
    assembly.assemble(scene);
    CHECK(assembly.assemblies == 2);
    scene.mesh.positions[7].y = -0.0 * scene.mesh.positions[7].y;
    assembly.assemble(scene);
    scene.mesh.positions[7].y = -scene.mesh.positions[7].y;  // +0 and -0: other bits, assembled again
    assembly.assemble(scene);
    CHECK(assembly.assemblies == 4);
    scene.normals = NormalSource::file;
    assembly.assemble(scene);
    CHECK(assembly.assemblies == 5);

    SECTION("objects sharing one mesh: an edit through another pointer is seen") {
        auto shared_mesh = std::make_shared<Mesh>(textured_sphere(image));
        Scene objects = lit_scene(Shader::phong);
        objects.objects.push_back(SceneObject{shared_mesh, glm::dmat4(1.0), {}, {}, {}});
        objects.objects.push_back(
            SceneObject{shared_mesh, glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.0, -0.5)), {}, {}, {}});
        detail::SceneAssembly kept;
        kept.assemble(objects);
        kept.assemble(objects);
        CHECK(kept.assemblies == 1);
        shared_mesh->positions[3] *= 1.5;  // in place: same address, same sizes
        kept.assemble(objects);
        CHECK(kept.assemblies == 2);
        Renderer renderer(RenderOptions::exact());
        renderer.render(objects);
        shared_mesh->positions[3] /= 1.5;
        CHECK(same_bits(renderer.render(objects).image, render(objects, RenderOptions::exact()).image));
        objects.objects[1].mesh = std::make_shared<Mesh>(*shared_mesh);  // another pointer, the same content
        kept.assemble(objects);
        kept.assemble(objects);
        CHECK(kept.assemblies == 3);
        CHECK(same_bits(renderer.render(objects).image, render(objects, RenderOptions::exact()).image));
    }
}

TEST_CASE("a texture's texels are checked once per image, and again when its array is replaced") {
    auto image = checker_texture(8);
    Scene scene = lit_scene(Shader::phong);
    scene.mesh = textured_sphere(image);
    Renderer renderer(RenderOptions::exact());
    renderer.render(scene);
    detail::CheckedTextures checked;
    detail::validate_scene_objects(scene, &checked);
    REQUIRE(checked.entries.size() == 1);
    CHECK(checked.contains(*image));

    const auto message = [&] {
        try {
            renderer.render(scene);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("(accepted)");
    };
    // A new array (another address) with a NaN: scanned again, refused naming the texel.
    std::vector<glm::vec3> texels = image->texels;
    texels[5].y = std::numeric_limits<float>::quiet_NaN();
    image->texels = std::move(texels);
    CHECK_FALSE(checked.contains(*image));
    CHECK(message() == "mesh.materials[0] (checker).texture: image 'checker': texel 5 is not finite");
    // Another image with a NaN in the material: refused too.
    auto other = checker_texture(8);
    other->texels[2].x = std::numeric_limits<float>::infinity();
    image->texels[5].y = 0.5f;
    scene.mesh.materials[0].texture->image = other;
    CHECK(message() == "mesh.materials[0] (checker).texture: image 'checker': texel 2 is not finite");
    other->texels[2].x = 0.25f;
    CHECK(message() == "(accepted)");
}
