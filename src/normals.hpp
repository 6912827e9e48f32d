// calculate_normals() into caller-owned memory (internal header), so that a
// Renderer computes a mesh's normals frame after frame without allocating.
#ifndef PHONGRAST_SRC_NORMALS_HPP
#define PHONGRAST_SRC_NORMALS_HPP

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "huge_page_pool.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast::detail {

/// calculate_normals()'s working memory (on huge pages: huge_page_pool.hpp).
struct NormalsScratch {
    FrameVector<glm::dvec3> sums;
    FrameVector<double> largest_area;
    FrameVector<glm::dvec3> largest_face_normal;
    FrameVector<glm::dvec4> faces;  ///< per triangle: its cross product and length (-1: not finite)
};

/// calculate_normals(positions, triangles), written into `normals`, in
/// parallel with the bits of one pass in order. `poll`, if given, is called
/// on the calling thread between the passes (the renderer's progress reports).
void calculate_normals_into(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles,
                            NormalsScratch& scratch, std::vector<glm::vec3>& normals,
                            const std::function<void()>& poll = nullptr);

/// Each vertex's corners, listed in the order in which calculate_normals_into()
/// on another numbering of the same mesh (the caller's) adds its faces to the
/// vertex's sum: ascending original triangle, then corner. With it, the
/// normals of a reordered copy are computed locally (each vertex gathers its
/// faces) and have the bits of the caller's order (mesh_order.cpp).
struct VertexCorners {
    /// Per vertex, where its corners start in `corners`; then their end.
    std::vector<std::uint32_t> first;
    /// (triangle << 2) | corner, triangles numbered as the copy numbers them.
    std::vector<std::uint32_t> corners;
};

/// Triangles a VertexCorners can name (two bits of each entry are the corner).
constexpr std::size_t kVertexCornersMaxTriangles = std::size_t(1) << 30;

/// calculate_normals_into() of the mesh of which (positions, triangles) is a
/// renumbering that `corners` describes, in the renumbered order: each
/// vertex sums its faces in `corners`' order, in parallel over vertices (reads
/// stay local when the renumbering is). `corners` must list exactly these
/// triangles' corners (MeshOrder makes it again after an edit in place);
/// false, and `normals` unspecified, when its sizes do not fit them.
bool calculate_normals_by_corners(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles,
                                  const VertexCorners& corners, NormalsScratch& scratch,
                                  std::vector<glm::vec3>& normals, const std::function<void()>& poll = nullptr);

/// The positions and triangles a frame's computed normals were made from, so
/// that the next frame of the same mesh reuses them: a Renderer's frames,
/// and render()'s and render_object()'s calls, which keep their memory, on a
/// mesh without normals. Compared in full every frame, not by address: a
/// mesh edited in place, or another mesh at the same address, is computed
/// anew. Meshes of at most kReusedNormalsMaxTriangles triangles only (the
/// copy costs 24 bytes per vertex and 12 per triangle).
struct ComputedNormalsSource {
    std::vector<glm::dvec3> positions;
    std::vector<Triangle> triangles;
    bool valid = false;

    /// Whether normals computed from `mesh` now would be the remembered ones:
    /// the same positions and triangles, bit for bit.
    bool matches(const Mesh& mesh) const;
    /// Remembers `mesh` as the source of the normals just computed (or
    /// nothing, for a mesh over the limit).
    void remember(const Mesh& mesh);
};
constexpr std::size_t kReusedNormalsMaxTriangles = std::size_t{1} << 18;

/// Whether some user normal (Mesh::normals) is exactly zero: "no normal here".
bool has_zero_normal(const std::vector<glm::vec3>& normals);
/// computed[i] = given[i] wherever given[i] is not zero: a zero user normal
/// takes the computed one (as a zero file normal does in the contract).
void keep_given_normals(const std::vector<glm::vec3>& given, std::vector<glm::vec3>& computed);
/// The same for a reordered copy: computed[v] = given[source[v]] wherever
/// that is not zero (mesh_order.cpp: `source` maps the copy's vertices to
/// the caller's), in parallel.
void keep_given_normals(const std::vector<glm::vec3>& given, const std::vector<std::uint32_t>& source,
                        std::vector<glm::vec3>& computed);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_NORMALS_HPP
