// A textured quad, and a camera that sees it as the whole image, for the texture tests: one definition for
// test_texture_render.cpp and test_texture_trilinear.cpp.
#ifndef PHONGRAST_TESTS_TEXTURED_QUAD_HPP
#define PHONGRAST_TESTS_TEXTURED_QUAD_HPP

#include "phongrast/mesh.hpp"
#include "phongrast/render.hpp"
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

/// The camera sees the plane z = 0, [-0.5, 0.5]^2, as exactly the whole
/// size x size image; only ambient light of 1 on ka = 1, so each pixel is
/// 1 x 1 x (c = 1) x T: the texel itself.
inline phongrast::Scene textured_quad_scene(const phongrast::Mesh& quad, int size) {
    phongrast::Scene scene;
    scene.camera.eye = glm::dvec3(0.0, 0.0, 1.0);
    scene.camera.lookat = glm::dvec3(0.0);
    scene.image.rows = scene.image.columns = size;
    scene.image.background = glm::vec3(-1.0f);
    scene.material = phongrast::PhongMaterial{glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
    scene.ambient = glm::vec3(1.0f);
    scene.lighting = phongrast::Lighting::only_ambient();
    scene.mesh = quad;
    scene.shader = phongrast::Shader::phong;
    return scene;
}

#endif  // PHONGRAST_TESTS_TEXTURED_QUAD_HPP
