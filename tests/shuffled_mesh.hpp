// A mesh's faces and vertices put in a random order, for the tests of code
// whose result must not depend on the order a file lists them in.
#ifndef PHONGRAST_TESTS_SHUFFLED_MESH_HPP
#define PHONGRAST_TESTS_SHUFFLED_MESH_HPP

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <glm/vec3.hpp>

#include "phongrast/mesh.hpp"

namespace test_meshes_order {

/// Shuffles the triangles, then renumbers the vertices at random (positions
/// moved, indices rewritten): the same surface, listed in a cache-hostile
/// order. Only positions move: per-vertex colours or normals, if any, no
/// longer belong to their vertices (callers clear them or do not read them).
inline void shuffle_faces_and_vertices(phongrast::Mesh& mesh, std::mt19937& random) {
    std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), random);
    std::vector<std::uint32_t> target(mesh.positions.size());
    std::iota(target.begin(), target.end(), 0u);
    std::shuffle(target.begin(), target.end(), random);
    std::vector<glm::dvec3> positions(mesh.positions.size());
    for (std::size_t v = 0; v < target.size(); ++v) positions[target[v]] = mesh.positions[v];
    mesh.positions = positions;
    for (phongrast::Triangle& triangle : mesh.triangles) {
        for (std::uint32_t& index : triangle) index = target[index];
    }
}

}  // namespace test_meshes_order

#endif  // PHONGRAST_TESTS_SHUFFLED_MESH_HPP
