// Meshes generated in code, shared by the tests and the benchmarks: one
// definition of each shape. Every generator writes outward faces
// (counter-clockwise seen from outside).
#ifndef PHONGRAST_SUPPORT_MESHES_HPP
#define PHONGRAST_SUPPORT_MESHES_HPP

#include "phongrast/mesh.hpp"

namespace phongrast::support {

/// Unit cube [0,1]^3, 8 vertices, 12 triangles, no colours.
Mesh unit_cube();

/// Unit cube with a centre vertex on each face (vertices 8..13) and each face
/// split into four triangles around it: every corner sees its three faces equally.
Mesh symmetric_cube();

/// Latitude-longitude sphere of the given radius around the origin, no colours.
Mesh uv_sphere(int stacks, int slices, double radius);

/// Torus around the y axis (major radius R, minor r): closed, genus 1, no colours.
Mesh torus(int rings, int sides, double major, double minor);

/// Geodesic sphere: each icosahedron face cut into frequency^2 triangles
/// (20 * frequency^2 in all: frequency 8 gives 1,280, 64 gives 81,920),
/// vertices shared along the icosahedron's edges, pushed out to radius
/// 1 + bump * (a smooth wave) so that bump > 0 makes concave dents, with a
/// smoothly varying colour per vertex (so colours must be interpolated).
/// Throws std::invalid_argument unless 1 <= frequency <= 1023.
Mesh icosphere(int frequency, double bump = 0.0);

/// A plane over [-1, 1]^2 in x and y at z = dz_dx x + dz_dy y, cut into
/// quads x quads squares of two triangles each, facing +z: vertex
/// j (quads + 1) + i at x = -1 + 2 i / quads, y = -1 + 2 j / quads. No colours.
Mesh grid_plane(int quads, double dz_dx, double dz_dy);

/// Colours every vertex from its position in the bounding box (a smooth
/// rainbow), replacing any colours the mesh had.
void color_by_position(Mesh& mesh);

/// The mesh turned by `degrees` about the x axis (right-handed), e.g. to
/// show a torus from above at an angle.
Mesh rotated_about_x(Mesh mesh, double degrees);

/// A face material (Mesh::materials) with these diffuse and specular
/// coefficients and exponent, the rest left at the defaults.
inline FaceMaterial face_material(const char* name, glm::vec3 kd, glm::vec3 ks, float n) {
    FaceMaterial m;
    m.name = name;
    m.coefficients.kd = kd;
    m.coefficients.ks = ks;
    m.coefficients.n = n;
    return m;
}

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_MESHES_HPP
