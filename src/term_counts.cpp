// How many times each lighting term is evaluated: the RenderStats counts of lit points.
#include "term_counts.hpp"

namespace phongrast {
namespace detail {

void count_term_evaluations(const Scene& scene, const RenderOptions& options, const EffectSet& effects,
                            std::uint64_t points, LitPoints kind, RenderStats& stats) {
    const bool phong_samples = kind == LitPoints::phong_samples;
    if (options.specialize_effects) {
        if (effects.ambient) stats.ambient_evaluations += points;
        if (effects.diffuse) stats.diffuse_evaluations += points * effects.active_lights;
        if (effects.specular) stats.specular_evaluations += points * effects.active_lights;
        if (phong_samples && effects.normals) stats.normal_interpolations += points;
    } else {
        if (scene.lighting.ambient) stats.ambient_evaluations += points;
        if (scene.lighting.diffuse) stats.diffuse_evaluations += points * scene.lights.size();
        if (scene.lighting.specular) stats.specular_evaluations += points * scene.lights.size();
        if (phong_samples) stats.normal_interpolations += points;
    }
}

}  // namespace detail
}  // namespace phongrast
