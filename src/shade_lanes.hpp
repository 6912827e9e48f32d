// The specialised lighting formula for several points at once (internal header).
//
// shade_terms<Real, A, D, S> (shading.hpp) lights one point with scalar glm
// arithmetic; Gouraud lights a vertex (exact light vectors) or a triangle's
// three corners (the seed's centroid vectors) that way. Here
// the same operations, in the same order, run lane by lane over arrays the
// compiler vectorises, so each lane's result is shade_terms' bit for bit
// (the library builds with -ffp-contract=off: no lane fuses what the scalar
// code rounds twice). Only std::pow stays per lane, and is called only where
// the scalar code calls it and its result is not known to be +0.
#ifndef PHONGRAST_SRC_SHADE_LANES_HPP
#define PHONGRAST_SRC_SHADE_LANES_HPP

#include <cmath>
#include <cstddef>
#include <cstring>

#include "lanes_isa.hpp"
#include "normalize_lanes.hpp"
#include "shading.hpp"

namespace phongrast::detail {
inline namespace PHONGRAST_LANES_ISA {

/// Three coordinates of N points, one array per axis.
template <typename Real, std::size_t N>
struct AxisLanes {
    Real axis[3][N];

    void set(std::size_t lane, const Vec3<Real>& v) {
        axis[0][lane] = v.x;
        axis[1][lane] = v.y;
        axis[2][lane] = v.z;
    }
    Vec3<Real> get(std::size_t lane) const { return {axis[0][lane], axis[1][lane], axis[2][lane]}; }
};

/// What N points are lit from: the unit vectors to each active light and to
/// the eye (kEyeAtInfinity when the camera is orthographic), and each point's
/// normal and colour: LightVectorsAt and shade_with()'s arguments, in lanes.
template <typename Real, std::size_t N>
struct ShadeLanesInput {
    const AxisLanes<Real, N>* to_light = nullptr;  ///< one per active light
    const AxisLanes<Real, N>* to_eye = nullptr;    ///< read only with specular on
    AxisLanes<Real, N> normal;
    AxisLanes<Real, N> color;
};

/// LightVectorsAt::compute() for N points at once: the unit vectors from
/// lane l's point (`point_of(l)`, camera space) to each of `shader`'s active
/// lights into vectors[k], and with specular on to the eye into
/// vectors[lights] (kEyeAtInfinity for an orthographic camera), normalised by
/// safe_normalize_lanes(): the same bits. `vectors` has room for lights + 1.
template <typename Real, std::size_t N, typename PointOf>
void light_vectors_lanes(const PointShader<Real>& shader, const PointOf& point_of, AxisLanes<Real, N>* vectors) {
    const std::vector<CameraLight<Real>>& lights = shader.rig->active_lights;
    const bool eye_at_point = shader.effects.specular && !shader.rig->eye_at_infinity;
    // The points gathered into lanes once, not once per light: the differences
    // below then vectorise (a gather per light was most of the vertex lighting's loads).
    const std::size_t differences = lights.size() + (eye_at_point ? 1 : 0);
    Real point[3][N];
    for (std::size_t l = 0; l < N && differences > 0; ++l) {
        const Vec3<Real>& p = point_of(l);
        for (int c = 0; c < 3; ++c) point[c][l] = p[c];
    }
    for (std::size_t k = 0; k < differences; ++k) {
        // compute()'s differences: light - point, and -point for the eye at the origin.
        Real(&to)[3][N] = vectors[k].axis;
        if (k < lights.size()) {
            for (int c = 0; c < 3; ++c) {
                const Real light = lights[k].position[c];
                for (std::size_t l = 0; l < N; ++l) to[c][l] = light - point[c][l];
            }
        } else {
            for (int c = 0; c < 3; ++c) {
                for (std::size_t l = 0; l < N; ++l) to[c][l] = -point[c][l];
            }
        }
        safe_normalize_lanes(N, vectors[k].axis[0], vectors[k].axis[1], vectors[k].axis[2]);
    }
    if (shader.effects.specular && shader.rig->eye_at_infinity) {
        for (std::size_t l = 0; l < N; ++l) vectors[lights.size()].set(l, kEyeAtInfinity<Real>);  // V = -f
    }
}

/// shade_terms<Real, Ambient, Diffuse, Specular> of every lane into `out`.
template <typename Real, std::size_t N, bool Ambient, bool Diffuse, bool Specular>
void shade_terms_lanes(const LightRig<Real>& rig, const ShadeLanesInput<Real, N>& in, AxisLanes<Real, N>& out) {
    // shade_terms' `Vec3 result(0)` and its `+=`: starting from zero and adding
    // keeps the sign of a zero sum as the scalar code does. One loop with the
    // ambient term: an array zeroed alone became `rep stosq`, slow to start.
    for (int c = 0; c < 3; ++c) {
        if constexpr (Ambient) {
            const Real factor = rig.ambient_factor[c];
            for (std::size_t l = 0; l < N; ++l) out.axis[c][l] = Real(0) + factor * in.color.axis[c][l];
        } else {
            for (std::size_t l = 0; l < N; ++l) out.axis[c][l] = Real(0);
        }
    }
    if constexpr (Diffuse || Specular) {
        const Vec3<Real> kd(rig.material.kd), ks(rig.material.ks);
        const Real exponent = static_cast<Real>(rig.material.n);
        const Real threshold = grazing_threshold<Real>();
        const Real(&n)[3][N] = in.normal.axis;
        // A local copy of the colours: GCC reads an array in only some lanes (the
        // diffuse term's) only from one whose size it knows; else that loop would not vectorise.
        Real local_color[3][N];
        if constexpr (Diffuse) std::memcpy(local_color, in.color.axis, sizeof local_color);
        Real(&sum)[3][N] = out.axis;
        for (std::size_t k = 0; k < rig.active_lights.size(); ++k) {
            const Real(&to_light)[3][N] = in.to_light[k].axis;
            const Vec3<Real>& intensity = rig.active_lights[k].intensity;
            const Real intensity_kd[3] = {intensity[0] * kd[0], intensity[1] * kd[1], intensity[2] * kd[2]};
            Real n_dot_l[N], r_dot_v[N];
            Real facing[N];  // 1 where N.L passes the grazing threshold, else 0
            const Real(&eye)[3][N] = Specular ? in.to_eye->axis : in.normal.axis;  // unread without specular
            for (std::size_t l = 0; l < N; ++l) {
                // glm::dot: (x + y) + z.
                n_dot_l[l] = (n[0][l] * to_light[0][l] + n[1][l] * to_light[1][l]) + n[2][l] * to_light[2][l];
                facing[l] = n_dot_l[l] > threshold ? Real(1) : Real(0);
            }
            if constexpr (Diffuse) {  // diffuse_from_direction()
                for (std::size_t l = 0; l < N; ++l) {
                    const bool lights = facing[l] != Real(0);
                    sum[0][l] += lights ? intensity_kd[0] * local_color[0][l] * n_dot_l[l] : Real(0);
                    sum[1][l] += lights ? intensity_kd[1] * local_color[1][l] * n_dot_l[l] : Real(0);
                    sum[2][l] += lights ? intensity_kd[2] * local_color[2][l] * n_dot_l[l] : Real(0);
                }
            }
            if constexpr (Specular) {  // specular_from_direction()
                // The term is added only where it can differ from zero: where the scalar code
                // takes the power (N.L beyond the threshold, V not zero) and, for n > 0, R.V > 0
                // (0^n is +0: R.V is clamped to 0 on about half a lit surface; 0^0 is 1). Adding
                // the zero elsewhere changes no bit: the sums start at +0 (0 + ambient) and a sum
                // that starts at +0 is never -0, and x + (+-0) is x for every other x. (The term
                // skipped is Ip ks x 0, an exact zero: validation bounds Ip ks by kMaxLitValue.)
                const Real zero_power_below = exponent > Real(0) ? Real(0) : Real(-1);
                int takes_power[N];  // 0 or 1, set without a branch (a branch per lane mispredicts often)
                for (std::size_t l = 0; l < N; ++l) {
                    const Real eye_length2 = (eye[0][l] * eye[0][l] + eye[1][l] * eye[1][l]) + eye[2][l] * eye[2][l];
                    const Real rx = Real(2) * n[0][l] * n_dot_l[l] - to_light[0][l];
                    const Real ry = Real(2) * n[1][l] * n_dot_l[l] - to_light[1][l];
                    const Real rz = Real(2) * n[2][l] * n_dot_l[l] - to_light[2][l];
                    const Real d = (rx * eye[0][l] + ry * eye[1][l]) + rz * eye[2][l];
                    const Real at_least_zero = Real(0) < d ? d : Real(0);             // std::max(0, d)
                    r_dot_v[l] = at_least_zero < Real(1) ? at_least_zero : Real(1);  // std::min(1, .)
                    takes_power[l] = int(facing[l] != Real(0)) & int(eye_length2 != Real(0)) &
                                     int(r_dot_v[l] > zero_power_below);
                }
                const Real intensity_ks[3] = {intensity[0] * ks[0], intensity[1] * ks[1], intensity[2] * ks[2]};
                // Those lanes listed first, then powered and added one by one: they come and go at random.
                std::size_t power_lanes[N];
                std::size_t power_count = 0;
                for (std::size_t l = 0; l < N; ++l) {
                    power_lanes[power_count] = l;
                    power_count += static_cast<std::size_t>(takes_power[l]);
                }
                for (std::size_t i = 0; i < power_count; ++i) {
                    const std::size_t l = power_lanes[i];
                    const Real highlight = std::pow(r_dot_v[l], exponent);
                    sum[0][l] += intensity_ks[0] * highlight;
                    sum[1][l] += intensity_ks[1] * highlight;
                    sum[2][l] += intensity_ks[2] * highlight;
                }
            }
        }
    }
}

/// PointShader::shade_with() of every lane (a specialised shader).
template <typename Real, std::size_t N>
void shade_with_lanes(const PointShader<Real>& shader, const ShadeLanesInput<Real, N>& in, AxisLanes<Real, N>& out) {
    const EffectSet& effects = shader.effects;
    const LightRig<Real>& rig = *shader.rig;
    const int key = (effects.ambient ? 4 : 0) | (effects.diffuse ? 2 : 0) | (effects.specular ? 1 : 0);
    switch (key) {
        case 0: return shade_terms_lanes<Real, N, false, false, false>(rig, in, out);
        case 1: return shade_terms_lanes<Real, N, false, false, true>(rig, in, out);
        case 2: return shade_terms_lanes<Real, N, false, true, false>(rig, in, out);
        case 3: return shade_terms_lanes<Real, N, false, true, true>(rig, in, out);
        case 4: return shade_terms_lanes<Real, N, true, false, false>(rig, in, out);
        case 5: return shade_terms_lanes<Real, N, true, false, true>(rig, in, out);
        case 6: return shade_terms_lanes<Real, N, true, true, false>(rig, in, out);
        default: return shade_terms_lanes<Real, N, true, true, true>(rig, in, out);
    }
}

/// Active lights up to which points are lit in lanes (their vectors live on
/// the stack); with more, the callers light point by point.
constexpr std::size_t kMaxLaneLights = 8;

}  // namespace PHONGRAST_LANES_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SHADE_LANES_HPP
