// What a scene needs before any pixel is filled (internal header): the effect
// set, and whether back faces can be seen at all.
#ifndef PHONGRAST_SRC_SCENE_ANALYSIS_HPP
#define PHONGRAST_SRC_SCENE_ANALYSIS_HPP

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// The lighting selection intersected with what the scene makes non-zero.
EffectSet find_effects(const Scene& scene);

/// Which winding faces the eye when back faces are hidden.
enum class HiddenBackFaces {
    unknown,            ///< the mesh is open, or the eye is on or inside it: draw everything
    outward_oriented,   ///< closed, counter-clockwise seen from outside, eye outside
    inward_oriented,    ///< closed, clockwise seen from outside, eye outside
};

/// Detects, never assumes, that every back face is hidden: the mesh must be a
/// closed, consistently oriented surface (every directed edge a->b matched by
/// a b->a) and the eye must be outside the volume it encloses (winding number 0).
HiddenBackFaces find_hidden_back_faces(const Mesh& mesh, const glm::dvec3& eye);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SCENE_ANALYSIS_HPP
