// calculate_normals in parallel gives the bits of one pass over the
// triangles in order (the algorithm as it was before it ran in parallel,
// copied below as the reference), whatever the number of threads and the
// mesh's order, on the cases its fallback exists for.
#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <tbb/task_arena.h>

#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"
#include "shuffled_mesh.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

/// The serial algorithm: each face in order adds to its corners.
std::vector<glm::vec3> serial_normals(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles) {
    std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0)), largest_face(positions.size(), glm::dvec3(0.0));
    std::vector<double> largest_area(positions.size(), 0.0);
    for (const Triangle& triangle : triangles) {
        const glm::dvec3& a = positions[triangle[0]];
        const glm::dvec3& b = positions[triangle[1]];
        const glm::dvec3& c = positions[triangle[2]];
        const glm::dvec3 face = glm::cross(b - a, c - a);
        if (!std::isfinite(face.x) || !std::isfinite(face.y) || !std::isfinite(face.z)) continue;
        const double twice_area = glm::length(face);
        for (std::uint32_t vertex : triangle) {
            sums[vertex] += face;
            if (twice_area > largest_area[vertex]) {
                largest_area[vertex] = twice_area;
                largest_face[vertex] = face;
            }
        }
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t vertex = 0; vertex < positions.size(); ++vertex) {
        glm::dvec3 normal = safe_normalize<double>(sums[vertex]);
        const double sum_length = glm::length(sums[vertex]);
        if (normal == glm::dvec3(0.0) || !(sum_length > 1e-12 * largest_area[vertex])) {
            normal = safe_normalize<double>(largest_face[vertex]);
        }
        normals[vertex] = glm::vec3(normal);
    }
    return normals;
}

bool same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    // memcmp of two empty vectors would pass null pointers (undefined behaviour): compare sizes first.
    if (a.size() != b.size()) return false;
    return a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
}

/// An icosphere (72,000 triangles: several parallel ranges) with its faces and vertices shuffled,
/// plus the fallback's cases: a two-sided sheet, degenerate and repeated-corner triangles, a face
/// whose cross product overflows, unreferenced vertices.
Mesh awkward_mesh() {
    Mesh mesh = test_meshes::icosphere(60, 0.08);
    std::mt19937 random(3);
    test_meshes_order::shuffle_faces_and_vertices(mesh, random);
    const auto add = [&](glm::dvec3 p) {
        mesh.positions.push_back(p);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    const std::uint32_t a = add({5, 0, 0}), b = add({6, 0, 0}), c = add({5, 1, 0});
    mesh.triangles.push_back({a, b, c});  // two-sided sheet: the sums cancel
    mesh.triangles.push_back({a, c, b});
    mesh.triangles.push_back({a, a, b});  // repeated corner: a zero face added twice
    const std::uint32_t d = add({7, 7, 7});
    mesh.triangles.push_back({d, d, d});  // a point
    const std::uint32_t e = add({1e200, 0, 0}), f = add({0, 1e200, 0}), g = add({0, 0, 1e200});
    mesh.triangles.push_back({e, f, g});  // cross product overflows: skipped
    mesh.triangles.push_back({e, f, mesh.triangles[0][0]});
    // A vertex whose faces lie far apart in the list.
    const std::uint32_t h = add({0.5, 0.5, 2.0});
    mesh.triangles.insert(mesh.triangles.begin() + 10, {mesh.triangles[5000][0], mesh.triangles[7000][1], h});
    mesh.triangles.push_back({h, mesh.triangles[9000][1], mesh.triangles[9000][2]});
    add({9, 9, 9});  // unreferenced
    return mesh;
}

}  // namespace

TEST_CASE("parallel normals give the serial pass's bits at every thread count") {
    const Mesh mesh = awkward_mesh();
    const std::vector<glm::vec3> expected = serial_normals(mesh.positions, mesh.triangles);
    for (int threads : {1, 2, 3, 4, 7}) {
        tbb::task_arena arena(threads);
        std::vector<glm::vec3> got;
        arena.execute([&] { got = calculate_normals(mesh); });
        INFO(threads << " threads");
        CHECK(same_bits(got, expected));
    }
    // The fallback cases really are in the mesh: the sheet gets its face's normal, the point zero.
    const std::vector<glm::vec3> normals = calculate_normals(mesh);
    const std::size_t sheet = mesh.positions.size() - 9;
    CHECK(std::abs(normals[sheet].z) == 1.0f);
    CHECK(normals[sheet + 3] == glm::vec3(0.0f));
    CHECK(normals.back() == glm::vec3(0.0f));
}

TEST_CASE("parallel normals of small and empty meshes") {
    for (const Mesh& mesh : {test_meshes::unit_cube(), test_meshes::symmetric_cube(), Mesh{}}) {
        CHECK(same_bits(calculate_normals(mesh), serial_normals(mesh.positions, mesh.triangles)));
    }
}
