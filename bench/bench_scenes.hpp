// Scenes for the effect-set benchmarks (issue 6): meshes generated in code,
// a camera that frames any mesh, deterministic lights, and the effect-set
// variants the benchmark sweeps.
#ifndef PHONGRAST_BENCH_BENCH_SCENES_HPP
#define PHONGRAST_BENCH_BENCH_SCENES_HPP

#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast_bench {

/// Icosahedron subdivided `levels` times and pushed onto the unit sphere:
/// 20 * 4^levels triangles, closed, counter-clockwise seen from outside,
/// with a smoothly varying colour per vertex (so colours must be interpolated).
phongrast::Mesh icosphere(int levels);

/// Torus around the y axis, closed and outward: seen from above at an angle,
/// painter's order draws some of its inner back faces over front faces.
phongrast::Mesh torus(int rings, int sides, double major, double minor);

/// Where the eye sits relative to the mesh's bounding box centre.
enum class ViewAxis { plus_z, minus_z };

/// A scene showing the whole mesh in a rows x columns image: lookat at the
/// bounding-box centre, eye 2.5 box diagonals away along `axis` (the recipe
/// of ../shared/assets/README.md), slightly raised, +y up.
phongrast::Scene framed_scene(phongrast::Mesh mesh, int rows, int columns, ViewAxis axis = ViewAxis::plus_z);

/// `count` white-ish lights spread around the view direction at two box
/// diagonals from the centre, all with non-zero intensity, always the same.
std::vector<phongrast::PointLight> lights_around(const phongrast::Scene& scene, int count);

/// One column of the effect table: a lighting selection plus which material
/// coefficients are zeroed.
struct EffectVariant {
    std::string name;  ///< ambient, diffuse, specular, full, full-kd0, full-ks0
    phongrast::Lighting lighting;
    bool zero_kd = false;
    bool zero_ks = false;
};
std::vector<EffectVariant> effect_variants();

/// `scene` with the variant's lighting and coefficients applied.
phongrast::Scene with_effect(phongrast::Scene scene, const EffectVariant& variant);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_BENCH_SCENES_HPP
