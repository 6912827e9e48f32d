// A triangle mesh as the seed used it: positions, per-vertex colours, faces as
// 0-based index triples, and (optionally) per-vertex normals.
#ifndef PHONGRAST_MESH_HPP
#define PHONGRAST_MESH_HPP

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "phongrast/material.hpp"

namespace phongrast {

using Triangle = std::array<std::uint32_t, 3>;

/// In a per-corner index triple (Mesh::texcoord_triangles,
/// Mesh::file_normal_triangles) or Mesh::face_materials: this corner or face
/// has no such attribute.
constexpr std::uint32_t kNoIndex = 0xffffffffu;

struct Mesh {
    /// World positions, in double so that meshes far from the origin (1e7) keep their detail.
    std::vector<glm::dvec3> positions;
    /// RGB per vertex; empty means every vertex is white.
    std::vector<glm::vec3> colors;
    /// Counter-clockwise seen from outside gives outward right-hand normals.
    std::vector<Triangle> triangles;
    /// Normal per vertex; empty means "compute with calculate_normals". Need
    /// not be unit length (the renderer normalises); an exactly zero one takes
    /// the computed normal; a non-finite one is an error (std::invalid_argument).
    std::vector<glm::vec3> normals;

    // What contract version 2 reads from mesh files besides the above. All
    // are optional (empty: none), and a mesh with none of them renders as a
    // version-1 mesh. Per-corner attributes are indexed as OBJ indexes them:
    // their own value array, and per triangle three indices into it (kNoIndex
    // for a corner without one), so one position can carry different values
    // on different faces (texture seams, hard edges) while computed normals
    // still follow the position indices in `triangles`.

    /// Texture coordinates (s, t), t = 0 at the texture's bottom row (OBJ
    /// `vt u v` is (u, v); glTF (u, v) is (u, 1 - v)).
    std::vector<glm::vec2> texcoords;
    /// Per triangle, its corners' indices into `texcoords` (or kNoIndex).
    std::vector<Triangle> texcoord_triangles;
    /// Normals the file gives (OBJ `vn`, glTF NORMAL, PLY nx ny nz), used with
    /// "normals": "file" (Scene::normals, SceneObject::normals).
    std::vector<glm::vec3> file_normals;
    /// Per triangle, its corners' indices into `file_normals` (or kNoIndex).
    std::vector<Triangle> file_normal_triangles;
    /// The materials the file gives its faces (OBJ usemtl/MTL, glTF primitives).
    std::vector<FaceMaterial> materials;
    /// Per triangle, its index into `materials`, or kNoIndex for none.
    std::vector<std::uint32_t> face_materials;
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
/// Throws std::out_of_range naming the triangle and corner when an index is
/// not below positions.size().
std::vector<glm::vec3> calculate_normals(const std::vector<glm::dvec3>& positions,
                                         const std::vector<Triangle>& triangles);
std::vector<glm::vec3> calculate_normals(const Mesh& mesh);

/// Throws std::invalid_argument when an index is out of range, a position is
/// not finite, or colours/normals are present but not one per vertex.
void validate_mesh(const Mesh& mesh);

}  // namespace phongrast

#endif  // PHONGRAST_MESH_HPP
