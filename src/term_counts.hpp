// How many times each lighting term is evaluated (internal header): the one
// place that turns "this many points were lit" into RenderStats counts.
#ifndef PHONGRAST_SRC_TERM_COUNTS_HPP
#define PHONGRAST_SRC_TERM_COUNTS_HPP

#include <cstdint>

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Where lit points come from: their shading also interpolates a normal per
/// point only when they are samples of a Phong fill.
enum class LitPoints {
    outside_the_fill,  ///< vertices (Gouraud), corners (Gouraud, seed vectors), centroids (flat)
    phong_samples,     ///< samples shaded by a Phong fill kernel
};

/// Adds the term evaluations of `points` lit points to `stats`: the
/// specialised path evaluates the effects the scene has (active lights only),
/// the general one every selected term for every light.
void count_term_evaluations(const Scene& scene, const RenderOptions& options, const EffectSet& effects,
                            std::uint64_t points, LitPoints kind, RenderStats& stats);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_TERM_COUNTS_HPP
