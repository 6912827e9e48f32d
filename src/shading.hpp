// Per-point lighting in camera space (internal header).
//
// The renderer lights in camera space: the eye is the origin, and every
// position is relative to it. Subtracting the eye once, in double, before any
// float arithmetic is what keeps a mesh translated by 1e7 or seen from 15000
// units away as sharp as one at the origin. The formula itself is the one in
// phongrast/lighting.hpp; dot products do not change under the camera's
// rotation, so the result is the world-space result.
//
// Two evaluators give bit-identical results:
//   * shade_general asks at run time which terms are selected and loops over
//     every light, as a straightforward implementation would;
//   * shade_terms<A, D, S> is compiled for one effect set and loops over the
//     lights with non-zero intensity only. Skipped work only ever added an
//     exact zero, and the additions happen in the same order, so the sums match.
#ifndef PHONGRAST_SRC_SHADING_HPP
#define PHONGRAST_SRC_SHADING_HPP

#include <vector>

#include "phongrast/lighting.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

template <typename Real>
struct CameraLight {
    Vec3<Real> position;  ///< camera space
    Vec3<Real> intensity;
};

/// What the lighting formula needs besides the surface.
template <typename Real>
struct LightRig {
    std::vector<CameraLight<Real>> lights;         ///< every light, for the general evaluator
    std::vector<CameraLight<Real>> active_lights;  ///< non-zero intensity only, for the specialised ones
    Vec3<Real> ambient_factor{Real(0)};            ///< ka * Ia, the same product ambient_term forms
    PhongMaterial material;
    Lighting lighting;
    /// An orthographic camera's viewer is at infinity: V = -f, (0, 0, -1) in
    /// camera space, at every point (docs/scene-format.md, "Orthographic").
    bool eye_at_infinity = false;
};

/// V of an orthographic camera, in camera space.
template <typename Real>
inline const Vec3<Real> kEyeAtInfinity{Real(0), Real(0), Real(-1)};

/// Unit vectors from a point to each light and to the eye.
template <typename Real>
struct LightVectorsAt {
    std::vector<Vec3<Real>> to_light;
    Vec3<Real> to_eye{Real(0)};

    void compute(const std::vector<CameraLight<Real>>& lights, const Vec3<Real>& point, bool need_eye,
                 bool eye_at_infinity) {
        to_light.resize(lights.size());
        for (std::size_t k = 0; k < lights.size(); ++k) {
            to_light[k] = safe_normalize<Real>(lights[k].position - point);
        }
        if (need_eye) {
            // The eye is the camera-space origin, or at infinity behind it.
            to_eye = eye_at_infinity ? kEyeAtInfinity<Real> : safe_normalize<Real>(-point);
        }
    }
};

/// The contract's formula, asking per call which terms are on; every light.
template <typename Real>
Vec3<Real> shade_general(const LightRig<Real>& rig, const LightVectorsAt<Real>& vectors,
                         const Vec3<Real>& normal, const Vec3<Real>& color) {
    Vec3<Real> result(Real(0));
    if (rig.lighting.ambient) result += rig.ambient_factor * color;
    if (rig.lighting.diffuse || rig.lighting.specular) {
        for (std::size_t k = 0; k < rig.lights.size(); ++k) {
            if (rig.lighting.diffuse) {
                result += diffuse_from_direction<Real>(normal, color, vectors.to_light[k], rig.material,
                                                       rig.lights[k].intensity);
            }
            if (rig.lighting.specular) {
                result += specular_from_direction<Real>(normal, vectors.to_light[k], vectors.to_eye,
                                                        rig.material, rig.lights[k].intensity);
            }
        }
    }
    return result;
}

/// The same formula compiled for one effect set; `vectors` holds the active lights only.
template <typename Real, bool Ambient, bool Diffuse, bool Specular>
Vec3<Real> shade_terms(const LightRig<Real>& rig, const LightVectorsAt<Real>& vectors,
                       const Vec3<Real>& normal, const Vec3<Real>& color) {
    Vec3<Real> result(Real(0));
    if constexpr (Ambient) result += rig.ambient_factor * color;
    if constexpr (Diffuse || Specular) {
        for (std::size_t k = 0; k < rig.active_lights.size(); ++k) {
            if constexpr (Diffuse) {
                result += diffuse_from_direction<Real>(normal, color, vectors.to_light[k], rig.material,
                                                       rig.active_lights[k].intensity);
            }
            if constexpr (Specular) {
                result += specular_from_direction<Real>(normal, vectors.to_light[k], vectors.to_eye,
                                                        rig.material, rig.active_lights[k].intensity);
            }
        }
    }
    return result;
}

/// Lights one point (a vertex, a triangle centroid): computes its vectors and
/// evaluates either path. Used where a branch per point is negligible.
template <typename Real>
struct PointShader {
    const LightRig<Real>* rig = nullptr;
    EffectSet effects;
    bool specialized = true;

    Vec3<Real> operator()(LightVectorsAt<Real>& vectors, const Vec3<Real>& vector_origin,
                          const Vec3<Real>& normal, const Vec3<Real>& color) const {
        compute_vectors(vectors, vector_origin);
        return shade_prepared(vectors, normal, color);
    }

    /// Whether the result depends on the point's position and normal: not
    /// for a specialised shader without diffuse or specular (ambient only, or
    /// black), whose callers may then skip forming them (the same bits:
    /// compute_vectors() and shade_terms() do not read them).
    bool reads_position_and_normal() const { return !specialized || effects.normals; }

    /// The vectors operator() computes at `vector_origin`: computed once,
    /// they light several points there (a triangle's corners lit at its centroid).
    void compute_vectors(LightVectorsAt<Real>& vectors, const Vec3<Real>& vector_origin) const {
        if (!specialized) {
            vectors.compute(rig->lights, vector_origin, true, rig->eye_at_infinity);
        } else if (effects.normals) {
            vectors.compute(rig->active_lights, vector_origin, effects.specular, rig->eye_at_infinity);
        }
    }

    /// operator() with the vectors compute_vectors() computed.
    Vec3<Real> shade_prepared(const LightVectorsAt<Real>& vectors, const Vec3<Real>& normal,
                              const Vec3<Real>& color) const {
        return specialized ? shade_with(vectors, normal, color) : shade_general(*rig, vectors, normal, color);
    }

    /// shade_prepared() for a shader that reads no position or normal
    /// (!reads_position_and_normal(): specialised, neither diffuse nor
    /// specular): shade_with()'s ambient-only or black case, inline, for the
    /// callers that light a point per triangle or corner.
    Vec3<Real> shade_unlit(const LightVectorsAt<Real>& unread_vectors, const Vec3<Real>& color) const {
        const Vec3<Real> no_normal(Real(0));
        return effects.ambient ? shade_terms<Real, true, false, false>(*rig, unread_vectors, no_normal, color)
                               : shade_terms<Real, false, false, false>(*rig, unread_vectors, no_normal, color);
    }

    /// The specialised path with `vectors` already computed for the active
    /// lights (and the eye when specular is on).
    Vec3<Real> shade_with(const LightVectorsAt<Real>& vectors, const Vec3<Real>& normal,
                          const Vec3<Real>& color) const {
        const int key = (effects.ambient ? 4 : 0) | (effects.diffuse ? 2 : 0) | (effects.specular ? 1 : 0);
        switch (key) {
            case 0: return shade_terms<Real, false, false, false>(*rig, vectors, normal, color);
            case 1: return shade_terms<Real, false, false, true>(*rig, vectors, normal, color);
            case 2: return shade_terms<Real, false, true, false>(*rig, vectors, normal, color);
            case 3: return shade_terms<Real, false, true, true>(*rig, vectors, normal, color);
            case 4: return shade_terms<Real, true, false, false>(*rig, vectors, normal, color);
            case 5: return shade_terms<Real, true, false, true>(*rig, vectors, normal, color);
            case 6: return shade_terms<Real, true, true, false>(*rig, vectors, normal, color);
            default: return shade_terms<Real, true, true, true>(*rig, vectors, normal, color);
        }
    }
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SHADING_HPP
