// A scene for a mesh and nothing else, following the camera recipe of
// ../shared/assets/README.md ("Cameras"): lookat = bounding-box centre,
// eye = centre + 2.5 x diagonal along +z, up = +y, focal = eye distance, and
// a sensor that fits every vertex with a 10% margin. Three white-ish lights
// (key, fill, rim) placed relative to the box, and a neutral grey-white material.
#ifndef PHONGRAST_IO_AUTO_SCENE_HPP
#define PHONGRAST_IO_AUTO_SCENE_HPP

#include "phongrast/render.hpp"

namespace phongrast::io {

/// Frames `mesh` (positions must be finite and non-empty) for an image of
/// rows x columns: fills camera, image, material, ambient and lights, keeps
/// the mesh, Phong shader and full lighting.
Scene frame_mesh(Mesh mesh, int rows, int columns);

/// The same recipe for a scene already built (one mesh or several objects):
/// frames every vertex of every object in world space (after its model
/// matrix), and sets the camera, image size, ambient, lights and base
/// material as frame_mesh does; keeps the meshes, objects, shader and
/// lighting. Throws std::invalid_argument for a scene without vertices or
/// with a non-finite one.
void frame_scene(Scene& scene, int rows, int columns);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_AUTO_SCENE_HPP
