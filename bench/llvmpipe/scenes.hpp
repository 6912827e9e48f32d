// The scenes the llvmpipe comparison renders: generated icospheres (the issue's
// 10k-triangle 512x512 and 1.3M-triangle 1024x1024 scenes) and helpers to light
// any mesh the same way. Both renderers receive the same phongrast::Scene, with
// vertex normals already computed by phongrast::calculate_normals, so neither
// side's timing includes the normals and both shade with identical normals.
#ifndef PHONGRAST_BENCH_LLVMPIPE_SCENES_HPP
#define PHONGRAST_BENCH_LLVMPIPE_SCENES_HPP

#include <string>
#include <vector>

#include "phongrast/phongrast.hpp"

namespace llvmpipe_compare {

struct NamedScene {
    std::string name;
    phongrast::Scene scene;
};

/// A geodesic sphere: each icosahedron face cut into frequency^2 triangles
/// (20 * frequency^2 in all), vertices shared along the icosahedron's edges,
/// pushed out to radius 1 + bump * (a smooth wave), counter-clockwise seen from
/// outside, with a smooth per-vertex colour. bump > 0 makes concave dents, so
/// painter's order really decides some pixels.
phongrast::Mesh colored_icosphere(int frequency, double bump);

/// Three point lights, ambient, material and a dark background for a mesh whose
/// bounding box has this centre and diagonal; the camera is left alone.
void light_scene(phongrast::Scene& scene, const glm::dvec3& centre, double diagonal);

/// An icosphere scene at rows x rows pixels, camera on +z looking at the origin.
NamedScene icosphere_scene(const std::string& name, int frequency, int rows);

/// Fills scene.mesh.normals with phongrast::calculate_normals.
void compute_normals(phongrast::Scene& scene);

}  // namespace llvmpipe_compare

#endif  // PHONGRAST_BENCH_LLVMPIPE_SCENES_HPP
