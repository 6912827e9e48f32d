// The vertex stage's per-vertex output (internal header): what is
// interpolated across a triangle. The vertex stage makes them; clipping
// interpolates new ones; set-up and the fill read them.
#ifndef PHONGRAST_SRC_VARYINGS_HPP
#define PHONGRAST_SRC_VARYINGS_HPP

#include "phongrast/lighting.hpp"

namespace phongrast::detail {

/// What is interpolated across a triangle, per vertex.
template <typename Real>
struct Varyings {
    Vec3<Real> position;  ///< camera space (the eye is the origin)
    Vec3<Real> normal;    ///< camera space, not necessarily unit after interpolation
    Vec3<Real> color;     ///< surface colour c
    Vec3<Real> lit;       ///< Gouraud: the lit vertex colour; flat: the triangle's colour
};

template <typename Real>
Varyings<Real> lerp(const Varyings<Real>& a, const Varyings<Real>& b, Real t) {
    return {a.position + (b.position - a.position) * t, a.normal + (b.normal - a.normal) * t,
            a.color + (b.color - a.color) * t, a.lit + (b.lit - a.lit) * t};
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VARYINGS_HPP
