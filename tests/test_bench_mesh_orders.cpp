// The benchmarks' mesh orders (bench/mesh_orders.cpp): every order is the
// same mesh, triangle for triangle, so a benchmark row per order measures the
// order alone. A textured mesh's triangles carry their corners' texture
// coordinates, file normals and material with them; left behind, the mesh
// would split into other (and many more) render vertices.
#include <catch2/catch.hpp>

#include <map>
#include <tuple>

#include "mesh_orders.hpp"
#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

/// A sphere with per-corner texture coordinates that differ across a seam, per-corner
/// file normals and two materials: every per-triangle attribute of version 2.
Mesh attributed_sphere() {
    Mesh mesh = test_meshes::icosphere(6, 0.0);
    mesh.materials.resize(2);
    mesh.materials[0].name = "left";
    mesh.materials[1].name = "right";
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t base = static_cast<std::uint32_t>(mesh.texcoords.size());
        const std::uint32_t normal_base = static_cast<std::uint32_t>(mesh.file_normals.size());
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p = mesh.positions[mesh.triangles[t][k]];
            // Per face, not per vertex: a vertex's corners differ from face to face.
            mesh.texcoords.push_back(glm::vec2(float(t % 97) / 97.0f, float(k) / 3.0f));
            mesh.file_normals.push_back(glm::vec3(p) + glm::vec3(0.0f, 0.0f, float(t % 5)));
        }
        mesh.texcoord_triangles.push_back({base, base + 1, base + 2});
        mesh.file_normal_triangles.push_back({normal_base, normal_base + 1, normal_base + 2});
        mesh.face_materials.push_back(mesh.positions[mesh.triangles[t][0]].x < 0.0 ? 0u : 1u);
    }
    return mesh;
}

/// Each triangle as what its corners carry, in its own corner order: positions, texture
/// coordinates, file normals, and its material; counted, as a multiset of triangles.
using CornerValues = std::tuple<double, double, double, float, float, float, float, float>;
using TriangleValues = std::tuple<CornerValues, CornerValues, CornerValues, std::uint32_t>;

std::map<TriangleValues, int> triangles_by_value(const Mesh& mesh) {
    std::map<TriangleValues, int> counted;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        CornerValues corner[3];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p = mesh.positions[mesh.triangles[t][k]];
            const glm::vec2 st = mesh.texcoords[mesh.texcoord_triangles[t][k]];
            const glm::vec3 n = mesh.file_normals[mesh.file_normal_triangles[t][k]];
            corner[k] = {p.x, p.y, p.z, st.x, st.y, n.x, n.y, n.z};
        }
        ++counted[{corner[0], corner[1], corner[2], mesh.face_materials[t]}];
    }
    return counted;
}

}  // namespace

TEST_CASE("every mesh order keeps each triangle's texture coordinates, file normals and material") {
    const Mesh mesh = attributed_sphere();
    const std::map<TriangleValues, int> expected = triangles_by_value(mesh);
    for (const std::string& order : phongrast_bench::mesh_order_names()) {
        INFO(order);
        const Mesh ordered = phongrast_bench::in_mesh_order(mesh, order);
        REQUIRE(ordered.triangles.size() == mesh.triangles.size());
        REQUIRE(ordered.texcoord_triangles.size() == mesh.triangles.size());
        REQUIRE(ordered.file_normal_triangles.size() == mesh.triangles.size());
        REQUIRE(ordered.face_materials.size() == mesh.triangles.size());
        CHECK(triangles_by_value(ordered) == expected);
        if (order != "generator") CHECK(ordered.triangles != mesh.triangles);  // an order of its own
    }
}

TEST_CASE("every mesh order renders the same picture of a mesh with per-corner attributes") {
    Scene scene;
    scene.mesh = attributed_sphere();
    scene.normals = NormalSource::file;
    scene.camera.eye = {0.4, 0.5, 3.0};
    scene.image.rows = scene.image.columns = 64;
    scene.lights = {{{2.0, 3.0, 4.0}, glm::vec3(1.0f)}};
    RenderOptions options = RenderOptions::exact();
    options.aovs.uv = true;
    const RenderResult expected = render(scene, options);
    for (const std::string& order : phongrast_bench::mesh_order_names()) {
        INFO(order);
        Scene ordered = scene;
        ordered.mesh = phongrast_bench::in_mesh_order(scene.mesh, order);
        const RenderResult got = render(ordered, options);
        CHECK(got.image.pixels == expected.image.pixels);
        CHECK(got.aovs.uv == expected.aovs.uv);
    }
}
