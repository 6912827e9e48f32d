// A triangle mesh as the seed used it: positions, per-vertex colours, faces as
// 0-based index triples, and (optionally) per-vertex normals.
#ifndef PHONGRAST_MESH_HPP
#define PHONGRAST_MESH_HPP

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace phongrast {

using Triangle = std::array<std::uint32_t, 3>;

struct Mesh {
    /// World positions, in double so that meshes far from the origin (1e7) keep their detail.
    std::vector<glm::dvec3> positions;
    /// RGB per vertex; empty means every vertex is white.
    std::vector<glm::vec3> colors;
    /// Counter-clockwise seen from outside gives outward right-hand normals.
    std::vector<Triangle> triangles;
    /// Unit normal per vertex; empty means "compute with calculate_normals".
    std::vector<glm::vec3> normals;
};

/// Area-weighted vertex normals: each face adds its right-hand-rule cross
/// product (|cross| = twice its area) to its three vertices, and each sum is
/// normalised.
///
/// Fallback, on purpose and never NaN: a vertex whose sum is zero or not
/// finite (its faces cancel, as on a two-sided sheet, or are all degenerate)
/// takes the unit normal of its largest adjacent non-degenerate face; a vertex
/// with no such face (unreferenced, or only zero-area faces) gets the zero
/// vector, which the renderer lights with the ambient term only.
std::vector<glm::vec3> calculate_normals(const std::vector<glm::dvec3>& positions,
                                         const std::vector<Triangle>& triangles);
std::vector<glm::vec3> calculate_normals(const Mesh& mesh);

/// Throws std::invalid_argument when an index is out of range, a position is
/// not finite, or colours/normals are present but not one per vertex.
void validate_mesh(const Mesh& mesh);

}  // namespace phongrast

#endif  // PHONGRAST_MESH_HPP
