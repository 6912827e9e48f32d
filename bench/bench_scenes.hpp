// Scenes for the effect-set benchmarks: the look every measured mesh gets, and
// the effect-set variants the benchmark sweeps.
#ifndef PHONGRAST_BENCH_BENCH_SCENES_HPP
#define PHONGRAST_BENCH_BENCH_SCENES_HPP

#include <string>
#include <vector>

#include "phongrast/render.hpp"
#include "support/shared_scenes.hpp"

namespace phongrast_bench {

/// The effect benchmark's look for any mesh: framed by support::framed_scene
/// (io::frame_mesh) at rows x columns, a dark background, ambient 0.2, the
/// contract's example material with n = 16 (a visible highlight; pow() costs
/// the same for any n), two lights around the view, Phong, full lighting.
phongrast::Scene effect_scene(phongrast::Mesh mesh, int rows, int columns,
                              phongrast::support::ViewAxis axis = phongrast::support::ViewAxis::plus_z);

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
