// A textured quad for the texture tests: one definition for
// test_texture_render.cpp and test_texture_trilinear.cpp.
#ifndef PHONGRAST_TESTS_TEXTURED_QUAD_HPP
#define PHONGRAST_TESTS_TEXTURED_QUAD_HPP

#include "phongrast/mesh.hpp"
#include "phongrast/texture.hpp"

/// Two triangles over `corners` (counter-clockwise seen from +z) with (s, t)
/// `st` at them, one material textured by `map`.
inline phongrast::Mesh textured_quad_mesh(const glm::dvec3 (&corners)[4], const glm::vec2 (&st)[4],
                                          const phongrast::TextureMap& map) {
    phongrast::Mesh mesh;
    for (int k = 0; k < 4; ++k) {
        mesh.positions.push_back(corners[k]);
        mesh.texcoords.push_back(st[k]);
    }
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.texcoord_triangles = mesh.triangles;
    phongrast::FaceMaterial material;
    material.name = "textured";
    material.texture = map;
    mesh.materials = {material};
    mesh.face_materials = {0, 0};
    return mesh;
}

#endif  // PHONGRAST_TESTS_TEXTURED_QUAD_HPP
