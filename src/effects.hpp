// What a scene needs lit (internal header): the effect set, defined in
// effects.cpp.
#ifndef PHONGRAST_SRC_EFFECTS_HPP
#define PHONGRAST_SRC_EFFECTS_HPP

#include <vector>

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// The lighting selection intersected with what the scene makes non-zero.
EffectSet find_effects(const Scene& scene);
/// The same with the vertices' colours `colors` instead of the scene mesh's
/// (a reordered copy's are the caller's: CallerVertices).
EffectSet find_effects(const Scene& scene, const std::vector<glm::vec3>& colors);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_EFFECTS_HPP
