// Back faces (internal header): whether this frame may skip them, and which
// triangles are back faces. Skipping is only ever invisible, never assumed:
// see find_hidden_back_faces() (closed_mesh.cpp) for the mesh and the eye.
#ifndef PHONGRAST_SRC_BACK_FACES_HPP
#define PHONGRAST_SRC_BACK_FACES_HPP

#include "phongrast/render.hpp"
#include "closed_mesh.hpp"
#include "vertex_stage.hpp"

namespace phongrast::detail {

/// Which winding this frame culls: unknown (cull nothing) unless the options
/// ask for culling, the mesh is closed with the eye outside, and every front
/// face is drawn whole (none dropped by the seed's border rule or cut by the
/// near plane, either of which would open a hole onto a back face).
template <typename Real>
HiddenBackFaces back_faces_to_cull(const Scene& scene, const RenderOptions& options, const View& view,
                                   const TransformedVertices<Real>& vertices);

/// Whether `triangle` faces away from the eye (for a mesh with that
/// orientation), decided in double in world space.
bool faces_away(const Mesh& mesh, const glm::dvec3& eye, HiddenBackFaces orientation, const Triangle& triangle);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_BACK_FACES_HPP
