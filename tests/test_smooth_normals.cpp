// with_normals(): normals shared by position (seams vanish) and split at creases (a cube stays a cube).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

#include "phongrast/io/obj_file.hpp"
#include "phongrast/render.hpp"
#include "phongrast/smooth_normals.hpp"
#include "test_meshes.hpp"

using phongrast::Mesh;
using phongrast::NormalOptions;
using phongrast::NormalSharing;
using phongrast::with_normals;

namespace {

NormalOptions by_position(double crease = 180.0) { return {NormalSharing::position, crease}; }

// The latitude-longitude sphere with a texture-style seam: the last column of
// faces uses its own copies of the first column's vertices (same positions,
// other indices), as meshes exported with UV seams do. Returns the copies.
Mesh seamed_sphere(int stacks, int slices, std::map<std::uint32_t, std::uint32_t>& copy_of) {
    Mesh mesh = test_meshes::uv_sphere(stacks, slices, 1.0);
    for (int i = 1; i < stacks; ++i) {
        const auto vertex = std::uint32_t(1 + (i - 1) * slices);  // column 0 of ring i
        copy_of[vertex] = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(mesh.positions[vertex]);
    }
    // uv_sphere emits 2 * stacks - 2 faces per column, column after column.
    const std::size_t last_column = mesh.triangles.size() - std::size_t(2 * stacks - 2);
    for (std::size_t t = last_column; t < mesh.triangles.size(); ++t) {
        for (std::uint32_t& index : mesh.triangles[t]) {
            const auto copy = copy_of.find(index);
            if (copy != copy_of.end()) index = copy->second;
        }
    }
    return mesh;
}

double degrees_between(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::min(1.0, double(glm::dot(a, b)))) * 180.0 / 3.14159265358979323846;
}

// Each face's three corner normals, by (face, corner).
std::vector<glm::vec3> corner_normals(const Mesh& mesh) {
    std::vector<glm::vec3> corners;
    for (const phongrast::Triangle& t : mesh.triangles) {
        for (std::uint32_t v : t) corners.push_back(mesh.normals[v]);
    }
    return corners;
}

}  // namespace

TEST_CASE("by vertex index (the default) is calculate_normals exactly") {
    const Mesh cube = test_meshes::unit_cube();
    const Mesh result = with_normals(cube, NormalOptions{});
    CHECK(result.normals == phongrast::calculate_normals(cube));
    CHECK(result.triangles == cube.triangles);
    CHECK(result.positions == cube.positions);
}

TEST_CASE("a seam of repeated vertices: by index the two sides differ, by position they share one normal") {
    std::map<std::uint32_t, std::uint32_t> copy_of;
    const Mesh seamed = seamed_sphere(12, 16, copy_of);
    const std::vector<glm::vec3> by_index = phongrast::calculate_normals(seamed);
    for (const auto& [vertex, copy] : copy_of) {
        INFO("seam vertex " << vertex);
        CHECK(degrees_between(by_index[vertex], by_index[copy]) > 5.0);  // the seam the issue shows
    }

    const Mesh smooth = with_normals(seamed, by_position());
    REQUIRE(smooth.positions.size() == seamed.positions.size());  // nothing to split without a crease
    CHECK(smooth.triangles == seamed.triangles);
    // Both sides equal the normals of the same sphere without a seam, bit for bit:
    // the same faces summed in the same order.
    const std::vector<glm::vec3> welded = phongrast::calculate_normals(test_meshes::uv_sphere(12, 16, 1.0));
    for (const auto& [vertex, copy] : copy_of) {
        INFO("seam vertex " << vertex);
        CHECK(smooth.normals[vertex] == smooth.normals[copy]);
        CHECK(smooth.normals[vertex] == welded[vertex]);
    }
    for (std::size_t v = 0; v < smooth.positions.size(); ++v) {
        CHECK(glm::dot(glm::dvec3(smooth.normals[v]), smooth.positions[v]) > 0.98);  // away from the centre
    }
}

TEST_CASE("a mesh without shared positions gets the same normals by position as by index") {
    const Mesh torus = test_meshes::torus(24, 12, 2.0, 0.5);
    CHECK(with_normals(torus, by_position()).normals == phongrast::calculate_normals(torus));
}

TEST_CASE("a cube with a 30-degree crease keeps its flat faces, without a crease its corners are rounded") {
    Mesh cube = test_meshes::unit_cube();
    cube.colors.resize(cube.positions.size());
    for (std::size_t v = 0; v < cube.colors.size(); ++v) cube.colors[v] = glm::vec3(float(v) / 8.0f, 0.5f, 1.0f);

    const Mesh creased = with_normals(cube, by_position(30.0));
    // Each corner of the cube touches three faces at 90 degrees: three normals, three vertices.
    CHECK(creased.positions.size() == 24);
    REQUIRE(creased.triangles.size() == cube.triangles.size());
    REQUIRE(creased.colors.size() == creased.positions.size());
    const std::vector<glm::vec3> corners = corner_normals(creased);
    for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
        const phongrast::Triangle& old_face = cube.triangles[t];
        const phongrast::Triangle& new_face = creased.triangles[t];
        const glm::dvec3 a = cube.positions[old_face[0]];
        const glm::vec3 face_normal(glm::normalize(
            glm::cross(cube.positions[old_face[1]] - a, cube.positions[old_face[2]] - a)));
        for (int k = 0; k < 3; ++k) {
            INFO("face " << t << " corner " << k);
            CHECK(corners[3 * t + k] == face_normal);  // exactly the axis: the face stays flat
            CHECK(creased.positions[new_face[k]] == cube.positions[old_face[k]]);
            CHECK(creased.colors[new_face[k]] == cube.colors[old_face[k]]);
        }
    }

    // A crease wider than the cube's edges pools all three faces at each corner
    // (on the cube whose corners see each face through two equal triangles).
    const Mesh symmetric = test_meshes::symmetric_cube();
    const Mesh rounded = with_normals(symmetric, by_position(100.0));
    CHECK(rounded.positions.size() == symmetric.positions.size());
    for (std::size_t v = 0; v < 8; ++v) {
        const glm::dvec3 outward = glm::normalize(symmetric.positions[v] - glm::dvec3(0.5));
        CHECK(glm::dot(glm::dvec3(rounded.normals[v]), outward) > 0.999);
    }
}

TEST_CASE("the creased cube renders exactly like a cube built with separate vertices per face") {
    const Mesh shared = test_meshes::unit_cube();
    Mesh separate;  // every face its own four vertices: per-index normals are the face normals
    for (const phongrast::Triangle& t : shared.triangles) {
        const auto base = std::uint32_t(separate.positions.size());
        for (std::uint32_t v : t) separate.positions.push_back(shared.positions[v]);
        separate.triangles.push_back({base, base + 1, base + 2});
    }
    phongrast::Scene scene;
    scene.camera.eye = {2.5, 1.8, 3.1};
    scene.camera.lookat = {0.5, 0.5, 0.5};
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 1.0;
    scene.camera.sensor_height = scene.camera.sensor_width = 0.9;
    scene.image.rows = scene.image.columns = 64;
    scene.lights = {{{3.0, 4.0, 2.0}, glm::vec3(1.0f)}};
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        INFO(phongrast::to_string(shader));
        scene.shader = shader;
        scene.mesh = with_normals(shared, by_position(30.0));
        const phongrast::Image creased = phongrast::render(scene).image;
        scene.mesh = separate;
        const phongrast::Image faceted = phongrast::render(scene).image;
        CHECK(creased.pixels == faceted.pixels);
        scene.mesh = shared;
        CHECK(phongrast::render(scene).image.pixels != faceted.pixels);  // the contract's normals round the corners
    }
}

TEST_CASE("degenerate input: zero-area faces, two-sided sheets, positions 0.0 and -0.0, bad crease angles") {
    SECTION("a zero-area face neither adds to its neighbours nor gets a NaN") {
        Mesh mesh;
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
        mesh.triangles = {{0, 1, 2}, {0, 1, 3}};  // the second is a line
        for (double crease : {180.0, 30.0}) {
            const Mesh result = with_normals(mesh, by_position(crease));
            for (const glm::vec3& n : result.normals) CHECK(std::isfinite(n.x + n.y + n.z));
            CHECK(result.normals[0] == glm::vec3(0, 0, 1));
        }
    }
    SECTION("a two-sided sheet (faces cancel) takes its largest face's normal, as by index") {
        Mesh mesh;
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        mesh.triangles = {{0, 1, 2}, {3, 5, 4}};
        const Mesh result = with_normals(mesh, by_position());
        for (const glm::vec3& n : result.normals) CHECK(std::abs(n.z) == 1.0f);
        // With any crease below 180 the sides do not pool: each keeps its own.
        const Mesh creased = with_normals(mesh, by_position(179.0));
        CHECK(creased.normals[0] == glm::vec3(0, 0, 1));
        CHECK(creased.normals[3] == glm::vec3(0, 0, -1));
    }
    SECTION("0.0 and -0.0 are one position") {
        Mesh mesh;
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0, -0.0, -0.0}, {0, 0, 1}};
        mesh.triangles = {{0, 1, 2}, {3, 4, 1}};
        const Mesh result = with_normals(mesh, by_position());
        CHECK(result.normals[0] == result.normals[3]);
    }
    SECTION("crease angles outside [0, 180] are refused, naming the field") {
        const Mesh cube = test_meshes::unit_cube();
        for (double crease : {-1.0, 180.5, std::nan("")}) {
            CHECK_THROWS_WITH(with_normals(cube, by_position(crease)), Catch::Contains("crease angle"));
        }
    }
}

TEST_CASE("the teapot by position has no seam") {
    const std::string path = std::string(PHONGRAST_SHARED_ASSETS_DIR) + "/teapot.obj";
    if (!std::filesystem::exists(path)) {
        WARN("skipped: " << path << " is not there (the shared test meshes are absent)");
        return;
    }
    const Mesh teapot = phongrast::io::read_obj(path).mesh;
    std::map<std::tuple<double, double, double>, std::vector<std::uint32_t>> at_position;
    for (std::uint32_t v = 0; v < teapot.positions.size(); ++v) {
        const glm::dvec3& p = teapot.positions[v];
        at_position[{p.x, p.y, p.z}].push_back(v);
    }
    const std::vector<glm::vec3> by_index = phongrast::calculate_normals(teapot);
    const Mesh smooth = with_normals(teapot, by_position());
    std::size_t seam_vertices = 0;
    double widest_seam_by_index = 0.0;
    for (const auto& entry : at_position) {
        const std::vector<std::uint32_t>& vertices = entry.second;
        for (std::size_t k = 1; k < vertices.size(); ++k) {
            ++seam_vertices;
            widest_seam_by_index =
                std::max(widest_seam_by_index, degrees_between(by_index[vertices[0]], by_index[vertices[k]]));
            CHECK(smooth.normals[vertices[0]] == smooth.normals[vertices[k]]);
        }
    }
    INFO(seam_vertices << " repeated vertices; widest seam by index " << widest_seam_by_index << " degrees");
    CHECK(seam_vertices > 100);
    CHECK(widest_seam_by_index > 10.0);
}
