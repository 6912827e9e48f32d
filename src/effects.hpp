// What a scene needs lit (internal header): the effect set, defined in
// effects.cpp.
#ifndef PHONGRAST_SRC_EFFECTS_HPP
#define PHONGRAST_SRC_EFFECTS_HPP

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// The lighting selection intersected with what the scene makes non-zero.
EffectSet find_effects(const Scene& scene);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_EFFECTS_HPP
