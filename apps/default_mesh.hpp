// The project's own default mesh: a (2,3) torus knot tube with a rainbow of
// vertex colours along its length, made here so that the default scene needs
// no downloaded model.
#ifndef PHONGRAST_APPS_DEFAULT_MESH_HPP
#define PHONGRAST_APPS_DEFAULT_MESH_HPP

#include "phongrast/mesh.hpp"

namespace phongrast::cli {

/// A closed tube of `segments` rings of `sides` vertices along the knot, faces
/// counter-clockwise seen from outside. Centred on the origin, about 6.8 wide
/// in x and y and 2.5 deep in z.
Mesh make_torus_knot(int segments, int sides);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_DEFAULT_MESH_HPP
