// Whether back faces can be seen at all (internal header): only if the mesh
// has a boundary or the eye is inside it; defined in closed_mesh.cpp.
#ifndef PHONGRAST_SRC_CLOSED_MESH_HPP
#define PHONGRAST_SRC_CLOSED_MESH_HPP

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Which winding faces the eye when back faces are hidden.
enum class HiddenBackFaces {
    unknown,            ///< the mesh is open, or the eye is on or inside it: draw everything
    outward_oriented,   ///< closed, counter-clockwise seen from outside, eye outside
    inward_oriented,    ///< closed, clockwise seen from outside, eye outside
};

/// Detects, never assumes, that every back face is hidden: the mesh must be a
/// closed, consistently oriented surface (every directed edge a->b matched by
/// a b->a) and the eye must be outside the volume it encloses (winding number 0).
HiddenBackFaces find_hidden_back_faces(const Mesh& mesh, const glm::dvec3& eye);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_CLOSED_MESH_HPP
