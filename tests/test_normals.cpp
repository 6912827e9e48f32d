// calculate_normals: area-weighted, right-hand rule, and a documented fallback.
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "phongrast/mesh.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

TEST_CASE("cube corners get the normalised sum of their three faces") {
    const Mesh cube = test_meshes::unit_cube();
    const std::vector<glm::vec3> normals = calculate_normals(cube);
    REQUIRE(normals.size() == 8);
    for (std::size_t i = 0; i < cube.positions.size(); ++i) {
        // Every face adds the same area to each of its corners (two triangles
        // of a face touch a corner with total weight equal to the face's area
        // or half of it, symmetrically), so each normal points from the centre
        // along the corner's diagonal.
        const glm::dvec3 diagonal = glm::normalize(cube.positions[i] - glm::dvec3(0.5));
        INFO("vertex " << i);
        CHECK(glm::dot(glm::dvec3(normals[i]), diagonal) > 0.5);
        CHECK(glm::length(normals[i]) == Approx(1.0f).epsilon(1e-6));
    }
}

TEST_CASE("cube normals point outward along the diagonal when the split is symmetric") {
    // A cube whose faces are split into 4 triangles around a centre vertex, so
    // every corner touches each of its three faces with equal area.
    const Mesh cube = test_meshes::symmetric_cube();
    const std::vector<glm::vec3> normals = calculate_normals(cube);
    for (std::size_t i = 0; i < 8; ++i) {
        const glm::dvec3 diagonal = glm::normalize(cube.positions[i] - glm::dvec3(0.5));
        INFO("corner " << i);
        CHECK(normals[i].x == Approx(diagonal.x).margin(1e-6));
        CHECK(normals[i].y == Approx(diagonal.y).margin(1e-6));
        CHECK(normals[i].z == Approx(diagonal.z).margin(1e-6));
    }
    // Face centres get exactly their face's normal.
    for (std::size_t i = 8; i < cube.positions.size(); ++i) {
        const glm::dvec3 outward = cube.positions[i] - glm::dvec3(0.5);
        CHECK(glm::dot(glm::dvec3(normals[i]), outward * 2.0) == Approx(1.0).margin(1e-6));
    }
}

TEST_CASE("sphere normals are close to radial") {
    const Mesh sphere = test_meshes::uv_sphere(32, 64, 2.0);
    const std::vector<glm::vec3> normals = calculate_normals(sphere);
    double worst = 1.0;
    for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
        const glm::dvec3 radial = glm::normalize(sphere.positions[i]);
        worst = std::min(worst, glm::dot(glm::dvec3(normals[i]), radial));
    }
    // Within about 1 degree of the radial direction on a 32 x 64 sphere.
    CHECK(worst > std::cos(1.0 * M_PI / 180.0));
}

TEST_CASE("a degenerate face adds nothing and its lone vertex gets a zero normal") {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {5, 5, 5}};
    // Face 0 is a proper triangle facing +z; face 1 is collinear (0, 1, 3);
    // face 2 repeats a vertex (1, 1, 4).
    mesh.triangles = {{0, 1, 2}, {0, 1, 3}, {1, 1, 4}};
    const std::vector<glm::vec3> normals = calculate_normals(mesh);
    for (int i : {0, 1, 2}) {
        CHECK(normals[i].z == Approx(1.0f));
        CHECK(std::isfinite(normals[i].x));
    }
    // Vertices 3 and 4 touch only zero-area faces: the documented fallback is zero.
    CHECK(normals[3] == glm::vec3(0.0f));
    CHECK(normals[4] == glm::vec3(0.0f));
}

TEST_CASE("cancelling faces fall back to the largest adjacent face, never NaN") {
    // A two-sided sheet: the same triangle listed in both windings.
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
    const std::vector<glm::vec3> normals = calculate_normals(mesh);
    for (const glm::vec3& n : normals) {
        CHECK(std::abs(n.z) == Approx(1.0f));
        CHECK(n.x == 0.0f);
        CHECK(n.y == 0.0f);
    }
}

TEST_CASE("normals of a mesh far from the origin match the same mesh at the origin") {
    Mesh near_origin = test_meshes::uv_sphere(8, 16, 1.0);
    Mesh far_away = near_origin;
    for (glm::dvec3& p : far_away.positions) p += glm::dvec3(1e7, -1e7, 1e7);
    const auto a = calculate_normals(near_origin), b = calculate_normals(far_away);
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(glm::dot(a[i], b[i]) > 0.99999f);
    }
}
