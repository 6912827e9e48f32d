// The generated icosphere the tests and the speed benchmarks share
// (tests/support/meshes.hpp): welded into one closed surface, outward faces,
// the promised counts, at frequencies whose faces share edge points in every way.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "support/meshes.hpp"

using namespace phongrast;

namespace {

/// Every directed edge of the mesh and how often it occurs.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    }
    return edges;
}

}  // namespace

TEST_CASE("icosphere: 10 f^2 + 2 vertices, 20 f^2 triangles, one closed surface with outward faces") {
    for (int frequency : {1, 2, 3, 8, 33}) {
        CAPTURE(frequency);
        const Mesh mesh = support::icosphere(frequency);
        const std::size_t f2 = std::size_t(frequency) * std::size_t(frequency);
        REQUIRE(mesh.positions.size() == 10 * f2 + 2);
        REQUIRE(mesh.colors.size() == mesh.positions.size());
        REQUIRE(mesh.triangles.size() == 20 * f2);
        // Welded and closed: each directed edge once, and its reverse once (an unwelded
        // seam along an icosahedron edge would leave edges without a twin).
        const auto edges = directed_edges(mesh);
        REQUIRE(edges.size() == 3 * mesh.triangles.size());
        for (const auto& [edge, count] : edges) {
            REQUIRE(count == 1);
            REQUIRE(edges.count({edge.second, edge.first}) == 1);
        }
        for (const glm::dvec3& p : mesh.positions) REQUIRE(glm::length(p) == Approx(1.0).epsilon(1e-12));
        // Outward: each face's normal points away from the centre.
        for (const Triangle& t : mesh.triangles) {
            const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
            REQUIRE(glm::dot(glm::cross(b - a, c - a), a + b + c) > 0.0);
        }
    }
}

TEST_CASE("icosphere: every vertex is used, no two vertices coincide") {
    const Mesh mesh = support::icosphere(12, 0.08);
    std::vector<bool> used(mesh.positions.size(), false);
    for (const Triangle& t : mesh.triangles) {
        for (std::uint32_t v : t) used.at(v) = true;
    }
    REQUIRE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
    std::vector<glm::dvec3> sorted = mesh.positions;
    std::sort(sorted.begin(), sorted.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
        return std::make_tuple(a.x, a.y, a.z) < std::make_tuple(b.x, b.y, b.z);
    });
    for (std::size_t i = 1; i < sorted.size(); ++i) REQUIRE(glm::length(sorted[i] - sorted[i - 1]) > 1e-6);
}
