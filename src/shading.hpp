// Per-sample lighting in camera space (internal header).
//
// The renderer lights in camera space: the eye is the origin, and every
// position is relative to it. Subtracting the eye once, in double, before any
// float arithmetic is what keeps a mesh translated by 1e7 or seen from 15000
// units away as sharp as one at the origin. The formula itself is the one in
// phongrast/lighting.hpp; dot products do not change under the camera's
// rotation, so the result is the world-space result.
#ifndef PHONGRAST_SRC_SHADING_HPP
#define PHONGRAST_SRC_SHADING_HPP

#include <vector>

#include "phongrast/lighting.hpp"

namespace phongrast::detail {

template <typename Real>
struct CameraLight {
    Vec3<Real> position;  ///< camera space
    Vec3<Real> intensity;
};

/// What the lighting formula needs besides the surface: lights, Ia, material, terms.
template <typename Real>
struct LightRig {
    std::vector<CameraLight<Real>> lights;
    Vec3<Real> ambient{Real(0)};
    PhongMaterial material;
    Lighting lighting;
};

/// Unit vectors from a point to each light and to the eye.
template <typename Real>
struct LightVectorsAt {
    std::vector<Vec3<Real>> to_light;
    Vec3<Real> to_eye{Real(0)};

    void compute(const LightRig<Real>& rig, const Vec3<Real>& point) {
        to_light.resize(rig.lights.size());
        for (std::size_t k = 0; k < rig.lights.size(); ++k) {
            to_light[k] = safe_normalize<Real>(rig.lights[k].position - point);
        }
        to_eye = safe_normalize<Real>(-point);  // the eye is the camera-space origin
    }
};

/// The contract's formula with precomputed unit L and V; `normal` must be unit or zero.
template <typename Real>
Vec3<Real> shade(const LightRig<Real>& rig, const LightVectorsAt<Real>& vectors,
                 const Vec3<Real>& normal, const Vec3<Real>& color) {
    Vec3<Real> result(Real(0));
    if (rig.lighting.ambient) result += ambient_term<Real>(color, rig.material, rig.ambient);
    if (rig.lighting.diffuse || rig.lighting.specular) {
        for (std::size_t k = 0; k < rig.lights.size(); ++k) {
            const Vec3<Real>& to_light = vectors.to_light[k];
            if (rig.lighting.diffuse) {
                result += diffuse_from_direction<Real>(normal, color, to_light, rig.material,
                                                       rig.lights[k].intensity);
            }
            if (rig.lighting.specular) {
                result += specular_from_direction<Real>(normal, to_light, vectors.to_eye,
                                                        rig.material, rig.lights[k].intensity);
            }
        }
    }
    return result;
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SHADING_HPP
