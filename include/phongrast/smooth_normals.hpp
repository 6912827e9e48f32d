// Vertex normals shared by position and split at creases: for meshes that
// repeat a vertex along a seam (the patches of the Utah teapot, UV seams,
// STL-like soups), where the contract's per-vertex-index normals leave a
// visible seam, and for hard-edged models (a cube) that must stay faceted.
#ifndef PHONGRAST_SMOOTH_NORMALS_HPP
#define PHONGRAST_SMOOTH_NORMALS_HPP

#include "phongrast/mesh.hpp"

namespace phongrast {

/// Which corners of the mesh pool their faces into one normal.
enum class NormalSharing {
    vertex_index,  ///< the contract (calculate_normals): the faces that use a vertex index
    position,      ///< the faces that touch a position, whatever index they use for it
};

struct NormalOptions {
    NormalSharing sharing = NormalSharing::vertex_index;
    /// A face pools only the faces of its corner's group whose face normal is
    /// within this angle of its own (in degrees, in [0, 180]); sharper edges
    /// keep one normal per side. 180 pools every face of the group.
    double crease_degrees = 180.0;

    /// The contract's normals: what the renderer computes when Mesh::normals is empty.
    bool is_contract() const { return sharing == NormalSharing::vertex_index && crease_degrees >= 180.0; }
};

/// The mesh with Mesh::normals filled as `options` say (existing normals are
/// replaced). Each normal is the normalised sum of its pooled faces' cross
/// products (area-weighted), computed in double.
///
/// A vertex whose corners get different normals (a crease runs through it)
/// is split: the first normal keeps the vertex's index, each further one is a
/// copy of the vertex (position and colour) appended after the original
/// vertices, and the faces are re-pointed. Triangle order and count never
/// change, so painter's order and triangle indices are those of `mesh`.
///
/// Degenerate input, on purpose: positions are equal when their coordinates
/// are (0.0 and -0.0 count as equal); a zero-area face adds nothing and, not
/// having a direction of its own, pools every face of its group; a group
/// whose pooled sum cancels (a two-sided sheet) takes the unit normal of its
/// largest pooled face, as calculate_normals does; with none, the zero vector
/// (lit by the ambient term only). Never NaN.
///
/// Throws std::invalid_argument (naming the field) for a crease angle that is
/// not a number in [0, 180], or an invalid mesh (validate_mesh).
Mesh with_normals(const Mesh& mesh, const NormalOptions& options);

}  // namespace phongrast

#endif  // PHONGRAST_SMOOTH_NORMALS_HPP
