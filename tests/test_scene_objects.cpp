// Scenes of several objects (contract "Objects" and "Lighting"): assembly
// into one render mesh must give exactly the pictures of the equivalent
// version-1 meshes (an object with the identity is the plain mesh, a placed
// object is the pre-transformed mesh, a mirror is the mirrored mesh with its
// corners reversed, file normals with a hard edge are an unwelded mesh), and
// bad objects are refused naming the member.
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

Scene lit_scene(Shader shader) {
    Scene scene;
    scene.camera.eye = glm::dvec3(0.6, 0.9, 3.2);
    scene.camera.lookat = glm::dvec3(0.0);
    scene.camera.focal = 1.0;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.0;
    scene.image.rows = scene.image.columns = 48;
    scene.image.background = glm::vec3(0.1f, 0.2f, 0.3f);
    scene.material = PhongMaterial{glm::vec3(0.2f), glm::vec3(0.7f, 0.6f, 0.5f), glm::vec3(0.8f), 12.0f};
    scene.lights = {PointLight{glm::dvec3(2.0, 3.0, 4.0), glm::vec3(1.0f, 0.9f, 0.8f)},
                    PointLight{glm::dvec3(-3.0, 1.0, 2.0), glm::vec3(0.3f, 0.4f, 0.9f)}};
    scene.shader = shader;
    return scene;
}

Mesh coloured_sphere() {
    Mesh mesh = test_meshes::uv_sphere(10, 14, 0.6);
    test_meshes::color_by_position(mesh);
    return mesh;
}

std::shared_ptr<const Mesh> shared(Mesh mesh) { return std::make_shared<const Mesh>(std::move(mesh)); }

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

Mesh transformed(Mesh mesh, const glm::dmat4& m, bool reverse) {
    for (glm::dvec3& p : mesh.positions) p = apply(m, p);
    if (reverse) {
        for (Triangle& t : mesh.triangles) std::swap(t[0], t[2]);
    }
    return mesh;
}

/// Exact and seed modes, float and double, specialised and general kernels.
const std::vector<test_render_modes::RenderMode>& modes() {
    static const auto all = test_render_modes::preset_precision_kernel_modes();
    return all;
}

const Shader kShaders[] = {Shader::flat, Shader::gouraud, Shader::phong};

}  // namespace

TEST_CASE("a version-1 scene is not assembled, one that uses a version-2 field is") {
    Scene scene = lit_scene(Shader::phong);
    scene.mesh = coloured_sphere();
    CHECK_FALSE(detail::needs_assembly(scene));
    scene.mesh.file_normals = {glm::vec3(0.0f, 0.0f, 1.0f)};
    scene.mesh.file_normal_triangles.assign(scene.mesh.triangles.size(), Triangle{0, 0, 0});
    CHECK_FALSE(detail::needs_assembly(scene));  // file normals unused with computed normals
    scene.normals = NormalSource::file;
    CHECK(detail::needs_assembly(scene));
    Scene objects = lit_scene(Shader::phong);
    objects.objects.push_back(SceneObject{shared(coloured_sphere()), glm::dmat4(1.0), {}, {}, {}});
    CHECK(detail::needs_assembly(objects));
}

TEST_CASE("one object with the identity transform is the plain mesh, bit for bit") {
    for (Shader shader : kShaders) {
        Scene plain = lit_scene(shader);
        plain.mesh = coloured_sphere();
        Scene placed = lit_scene(shader);
        placed.objects.push_back(SceneObject{shared(plain.mesh), glm::dmat4(1.0), {}, {}, "sphere"});
        for (const auto& mode : modes()) {
            INFO(to_string(shader) << ", " << mode.name);
            RenderOptions options = mode.options;
            options.aovs = AovRequest::all();
            const RenderResult a = render(plain, options);
            const RenderResult b = render(placed, options);
            CHECK(same_bits(a.image, b.image));
            CHECK(a.aovs.id == b.aovs.id);
            CHECK(a.aovs.normal == b.aovs.normal);
            CHECK(a.stats.triangles_drawn == b.stats.triangles_drawn);
        }
    }
}

TEST_CASE("object transforms give the pictures of the pre-transformed meshes, in one painter's order") {
    const Mesh sphere = coloured_sphere();
    const Mesh cube = test_meshes::unit_cube();
    glm::dmat4 first = glm::translate(glm::dmat4(1.0), glm::dvec3(0.4, -0.1, 0.2));
    first = glm::rotate(first, 0.7, glm::dvec3(0.3, 1.0, 0.2));
    first = glm::scale(first, glm::dvec3(0.5, 0.8, 0.6));
    const glm::dmat4 second = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, 0.3, -0.4)) *
                              glm::rotate(glm::dmat4(1.0), -0.4, glm::dvec3(1.0, 0.0, 0.0));
    // The same objects, pre-transformed into one mesh: object 1's vertices after object 0's.
    Mesh merged = transformed(sphere, first, false);
    const Mesh moved_cube = transformed(cube, second, false);
    const std::uint32_t offset = static_cast<std::uint32_t>(merged.positions.size());
    merged.positions.insert(merged.positions.end(), moved_cube.positions.begin(), moved_cube.positions.end());
    merged.colors.resize(merged.positions.size(), glm::vec3(1.0f));  // the cube has no colours: white
    for (Triangle t : moved_cube.triangles) merged.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});

    for (Shader shader : kShaders) {
        Scene reference = lit_scene(shader);
        reference.mesh = merged;
        Scene placed = lit_scene(shader);
        placed.objects.push_back(SceneObject{shared(sphere), first, {}, {}, {}});
        placed.objects.push_back(SceneObject{shared(cube), second, {}, {}, {}});
        for (const auto& mode : modes()) {
            INFO(to_string(shader) << ", " << mode.name);
            RenderOptions options = mode.options;
            options.aovs.id = true;
            const RenderResult a = render(reference, options);
            const RenderResult b = render(placed, options);
            CHECK(same_bits(a.image, b.image));
            CHECK(a.aovs.id == b.aovs.id);  // the id output indexes the one list of all objects' triangles
        }
    }
}

TEST_CASE("a mirrored object keeps its normals outward: the mirrored mesh with reversed corners") {
    const Mesh sphere = coloured_sphere();
    const glm::dmat4 mirror = glm::translate(glm::dmat4(1.0), glm::dvec3(0.1, 0.0, 0.0)) *
                              glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0));
    Scene placed = lit_scene(Shader::phong);
    placed.objects.push_back(SceneObject{shared(sphere), mirror, {}, {}, {}});

    detail::AssembledScene assembled;
    detail::NormalsScratch scratch;
    detail::assemble_scene(placed, assembled, scratch);
    const Mesh& render_mesh = assembled.scene.mesh;
    REQUIRE(render_mesh.normals.size() == render_mesh.positions.size());
    const glm::dvec3 centre(0.1, 0.0, 0.0);
    for (std::size_t i = 0; i < render_mesh.positions.size(); ++i) {
        INFO("vertex " << i);
        CHECK(glm::dot(glm::dvec3(render_mesh.normals[i]), render_mesh.positions[i] - centre) > 0.0);
    }

    for (Shader shader : kShaders) {
        Scene reference = lit_scene(shader);
        reference.mesh = transformed(sphere, mirror, true);
        placed.shader = shader;
        for (const auto& mode : modes()) {
            INFO(to_string(shader) << ", " << mode.name);
            CHECK(same_bits(render(reference, mode.options).image, render(placed, mode.options).image));
        }
    }
}

namespace {

/// An axis-aligned box whose 8 corners are shared by its 12 triangles, with
/// per-corner file normals: each face's own axis (a hard edge everywhere).
Mesh box_with_face_normals() {
    Mesh mesh = test_meshes::unit_cube();
    for (const Triangle& t : mesh.triangles) {
        const glm::dvec3 face = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                           mesh.positions[t[2]] - mesh.positions[t[0]]);
        const glm::vec3 normal(glm::normalize(face));
        // One normal per face (its two triangles share it).
        std::uint32_t index = 0;
        while (index < mesh.file_normals.size() && mesh.file_normals[index] != normal) ++index;
        if (index == mesh.file_normals.size()) mesh.file_normals.push_back(normal);
        mesh.file_normal_triangles.push_back({index, index, index});
    }
    return mesh;
}

/// Every triangle with its own three vertices: computed normals are the faces' normals.
Mesh unwelded(const Mesh& mesh) {
    Mesh out;
    for (const Triangle& t : mesh.triangles) {
        const std::uint32_t base = static_cast<std::uint32_t>(out.positions.size());
        for (std::uint32_t v : t) out.positions.push_back(mesh.positions[v]);
        out.triangles.push_back({base, base + 1, base + 2});
    }
    return out;
}

}  // namespace

TEST_CASE("file normals with a hard edge: the picture of the unwelded mesh") {
    const Mesh box = box_with_face_normals();
    for (const glm::vec3& n : box.file_normals) {
        REQUIRE(std::abs(n.x) + std::abs(n.y) + std::abs(n.z) == 1.0f);  // axis-aligned: exact
    }
    const glm::dmat4 place = glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0.2, 1.0, 0.1));
    for (Shader shader : {Shader::gouraud, Shader::phong}) {
        Scene reference = lit_scene(shader);
        reference.mesh = unwelded(box);
        Scene file = lit_scene(shader);
        file.mesh = box;
        file.normals = NormalSource::file;
        Scene computed = file;
        computed.normals = NormalSource::computed;
        for (const auto& mode : modes()) {
            INFO(to_string(shader) << ", " << mode.name);
            const Image expected = render(reference, mode.options).image;
            CHECK(same_bits(expected, render(file, mode.options).image));
            // Computed normals average the faces at each corner: a different (smooth) picture.
            CHECK_FALSE(same_bits(expected, render(computed, mode.options).image));
        }
        // Under a rotation the normals go through the inverse transpose: still the faces' normals.
        Scene placed = lit_scene(shader);
        placed.objects.push_back(SceneObject{shared(box), place, {}, NormalSource::file, {}});
        detail::AssembledScene assembled;
        detail::NormalsScratch scratch;
        detail::assemble_scene(placed, assembled, scratch);
        const Mesh& render_mesh = assembled.scene.mesh;
        CHECK(render_mesh.positions.size() == 24);  // each corner split into its three faces' normals
        for (const Triangle& t : render_mesh.triangles) {
            const glm::dvec3 face = glm::normalize(glm::cross(render_mesh.positions[t[1]] - render_mesh.positions[t[0]],
                                                              render_mesh.positions[t[2]] - render_mesh.positions[t[0]]));
            for (std::uint32_t v : t) CHECK(glm::dot(glm::dvec3(render_mesh.normals[v]), face) > 1.0 - 1e-6);
        }
    }
}

TEST_CASE("a corner without a usable file normal takes the computed one") {
    Mesh box = box_with_face_normals();
    box.file_normals.push_back(glm::vec3(0.0f));                    // zero
    box.file_normals.push_back(glm::vec3(NAN, 0.0f, 0.0f));         // not finite
    const std::uint32_t zero = static_cast<std::uint32_t>(box.file_normals.size() - 2);
    box.file_normal_triangles[0] = {kNoIndex, zero, zero + 1};
    Scene scene = lit_scene(Shader::phong);
    scene.mesh = box;
    scene.normals = NormalSource::file;
    detail::AssembledScene assembled;
    detail::NormalsScratch scratch;
    detail::assemble_scene(scene, assembled, scratch);
    const std::vector<glm::vec3> computed = calculate_normals(box);
    const Triangle& first = assembled.scene.mesh.triangles[0];
    for (int k = 0; k < 3; ++k) {
        INFO("corner " << k);
        CHECK(assembled.scene.mesh.normals[first[k]] == computed[box.triangles[0][k]]);
    }
}

TEST_CASE("a Renderer reuses an objects scene's assembly only while nothing it depends on changed") {
    const auto sphere = shared(coloured_sphere());
    Scene scene = lit_scene(Shader::phong);
    scene.objects.push_back(SceneObject{sphere, glm::dmat4(1.0), {}, {}, {}});
    scene.objects.push_back(
        SceneObject{sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.0, -0.5)), {}, {}, {}});
    Renderer renderer(RenderOptions::exact());
    const Image first = renderer.render(scene).image;
    CHECK(same_bits(first, renderer.render(scene).image));
    scene.objects[1].transform = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, 0.2, -0.5));
    const Image moved = renderer.render(scene).image;
    CHECK_FALSE(same_bits(first, moved));
    CHECK(same_bits(moved, render(scene, RenderOptions::exact()).image));
    scene.objects[0].material.kd = glm::vec3(0.1f, 0.9f, 0.1f);
    CHECK(same_bits(renderer.render(scene).image, render(scene, RenderOptions::exact()).image));
    scene.camera.eye = glm::dvec3(-1.0, 0.5, 3.0);  // the view changes, the assembly does not
    CHECK(same_bits(renderer.render(scene).image, render(scene, RenderOptions::exact()).image));
}

namespace {

std::string error_of(const Scene& scene) {
    try {
        validate_render(scene, RenderOptions::exact());
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "(accepted)";
}

}  // namespace

TEST_CASE("invalid objects are refused naming the member") {
    const auto sphere = shared(coloured_sphere());
    const auto with_object = [&](const SceneObject& object) {
        Scene scene = lit_scene(Shader::phong);
        scene.objects.push_back(SceneObject{sphere, glm::dmat4(1.0), {}, {}, {}});
        scene.objects.push_back(object);
        return scene;
    };
    CHECK_THAT(error_of(with_object(SceneObject{nullptr, glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh: null"));
    CHECK_THAT(error_of(with_object(SceneObject{sphere, glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 0.0, 1.0)), {}, {}, {}})),
               Catch::StartsWith("objects[1].transform: singular"));
    glm::dmat4 infinite(1.0);
    infinite[3][0] = INFINITY;
    CHECK_THAT(error_of(with_object(SceneObject{sphere, infinite, {}, {}, {}})),
               Catch::StartsWith("objects[1].transform: expected finite"));
    glm::dmat4 projective(1.0);
    projective[0][3] = 0.5;  // last row 0.5 0 0 1
    CHECK_THAT(error_of(with_object(SceneObject{sphere, projective, {}, {}, {}})),
               Catch::StartsWith("objects[1].transform: expected the last row"));
    glm::dmat4 huge(1.0);
    huge[0][0] = 1e300;  // finite, not singular, but x' = 1e300 x + DBL_MAX overflows for x > 0
    huge[3][0] = std::numeric_limits<double>::max();
    CHECK_THAT(error_of(with_object(SceneObject{sphere, huge, {}, {}, {}})),
               Catch::Contains("objects[1].transform: takes vertex"));

    MaterialFields bad_material;
    bad_material.ks = glm::vec3(NAN);
    CHECK_THAT(error_of(with_object(SceneObject{sphere, glm::dmat4(1.0), bad_material, {}, {}})),
               Catch::StartsWith("objects[1].material.ks"));

    Mesh bad = coloured_sphere();
    bad.texcoords = {glm::vec2(0.0f), glm::vec2(1.0f)};
    bad.texcoord_triangles.assign(bad.triangles.size(), Triangle{0, 1, 0});
    bad.texcoord_triangles[5] = {0, 2, 1};
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh.texcoord_triangles[5]: index 2, expected below 2"));
    bad.texcoord_triangles[5] = {0, 1, 0};
    bad.texcoords[1].y = NAN;
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh.texcoords[1]: expected finite"));
    bad.texcoords[1].y = 1.0f;
    bad.file_normals = {glm::vec3(0.0f, 0.0f, 1.0f)};
    bad.file_normal_triangles.assign(bad.triangles.size() - 1, Triangle{0, 0, 0});
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh.file_normal_triangles: "));
    bad.file_normal_triangles.clear();
    bad.materials.resize(1);
    bad.face_materials.assign(bad.triangles.size(), 0);
    bad.face_materials[3] = 1;
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh.face_materials[3]: index 1, expected below 1"));
    bad.face_materials[3] = kNoIndex;
    bad.materials[0].name = "glass";
    bad.materials[0].color_factor = glm::vec3(1.0f, INFINITY, 1.0f);
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh.materials[0] (glass).color_factor"));
    bad.materials[0].color_factor = glm::vec3(1.0f);
    CHECK(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})) == "(accepted)");
    // A bad triangle of an object's mesh is named as that object's.
    bad.triangles[2][1] = 1u << 30;
    CHECK_THAT(error_of(with_object(SceneObject{shared(bad), glm::dmat4(1.0), {}, {}, {}})),
               Catch::StartsWith("objects[1].mesh: triangle 2"));

    Scene both = with_object(SceneObject{sphere, glm::dmat4(1.0), {}, {}, {}});
    both.mesh = coloured_sphere();
    CHECK_THAT(error_of(both), Catch::StartsWith("mesh: a scene with objects must leave mesh empty"));
}
