// Scenes generated in code, shared by the tests and the benchmarks.
//
// The accuracy report's scenes, each built so that one accuracy option matters:
//   sphere   a coloured icosphere: smooth, everything inside the image
//   floor    a close-up floor of large triangles seen at a low angle: perspective
//            and the image border matter
//   shiny    a gently curved sheet, Phong exponent 150, a light at a grazing angle
//   overlap  two quads that pass through each other: painter's order is wrong on one side
// The llvmpipe comparison's and the scaling benchmark's dented icosphere, and
// two light rigs for any framed mesh.
#ifndef PHONGRAST_SUPPORT_SCENES_HPP
#define PHONGRAST_SUPPORT_SCENES_HPP

#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast::support {

struct NamedScene {
    std::string name;
    std::string description;
    Scene scene;
};

NamedScene sphere_scene(int size);
NamedScene floor_scene(int size);
NamedScene shiny_scene(int size);
NamedScene overlap_scene(int size);
/// The four above, in that order, at size x size pixels.
std::vector<NamedScene> generated_scenes(int size);

/// The dented (bump 0.08) icosphere of 20 * frequency^2 triangles at rows x rows
/// pixels, camera on +z looking at the origin, three_lights(); vertex normals
/// already computed, so a renderer timed on it does not include them.
NamedScene icosphere_scene(const std::string& name, int frequency, int rows);

/// Three point lights of different colours (a warm key light up-right-front, a
/// blue fill from the left, a dim red rim light from below-behind, so a mistake
/// in one light's term shows up as a hue shift), ambient, material and a dark
/// background for a mesh whose bounding box has this centre and diagonal.
void three_lights(Scene& scene, const glm::dvec3& centre, double diagonal);

/// `count` white-ish lights on a cone around the view direction at 0.8 eye
/// distances from the lookat point, all with non-zero intensity, always the same.
std::vector<PointLight> lights_around(const Scene& scene, int count);

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_SCENES_HPP
