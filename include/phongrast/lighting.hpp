// Phong lighting exactly as docs/scene-format.md ("Lighting") states it:
//
//   I = ka * Ia * c                                              (ambient)
//     + sum over lights of  Ip * kd * c * max(0, N.L)            (diffuse)
//     + sum over lights of  Ip * ks * max(0, R.V)^n  if N.L > 0  (specular)
//
// The functions are templates over the arithmetic type (float or double) so the
// renderer's float and double pipelines share one definition of the formula.
#ifndef PHONGRAST_LIGHTING_HPP
#define PHONGRAST_LIGHTING_HPP

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

namespace phongrast {

template <typename Real>
using Vec3 = glm::vec<3, Real, glm::defaultp>;

/// Per-channel Phong coefficients and the specular exponent n.
/// The defaults are the contract's example material (and the seed's values).
struct PhongMaterial {
    glm::vec3 ka{0.1f};
    glm::vec3 kd{0.8f};
    glm::vec3 ks{1.0f};
    float n = 1.0f;
};

/// A point light: world-space position and RGB intensity Ip.
struct PointLight {
    glm::dvec3 position{0.0};
    glm::vec3 intensity{1.0f};
};

/// Which terms of the formula are evaluated. `full` is all three.
struct Lighting {
    bool ambient = true;
    bool diffuse = true;
    bool specular = true;

    static constexpr Lighting full() { return {true, true, true}; }
    static constexpr Lighting only_ambient() { return {true, false, false}; }
    static constexpr Lighting only_diffuse() { return {false, true, false}; }
    static constexpr Lighting only_specular() { return {false, false, true}; }

    bool any() const { return ambient || diffuse || specular; }
    friend bool operator==(const Lighting& a, const Lighting& b) {
        return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular;
    }
    friend bool operator!=(const Lighting& a, const Lighting& b) { return !(a == b); }
};

/// Parses "ambient", "diffuse" (or "diffusion"), "specular", "full", or several
/// joined with '+'. Throws std::invalid_argument naming the bad part and the valid names.
Lighting parse_lighting(std::string_view text);
/// The canonical name: "full", or the selected terms joined with '+'.
std::string to_string(const Lighting& lighting);

/// Unit vector along v, or the zero vector when v has zero or non-finite length.
/// Scales by the largest component first so tiny (1e-30) vectors do not
/// underflow to zero length and huge (1e30) ones do not overflow.
template <typename Real>
Vec3<Real> safe_normalize(const Vec3<Real>& v) {
    const Real largest = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
    if (!(largest > Real(0)) || !std::isfinite(largest)) return Vec3<Real>(Real(0));
    const Vec3<Real> scaled = v / largest;
    return scaled / std::sqrt(glm::dot(scaled, scaled));
}

/// ka * Ia * c.
template <typename Real>
Vec3<Real> ambient_term(const Vec3<Real>& color, const PhongMaterial& material,
                        const Vec3<Real>& ambient_intensity) {
    return Vec3<Real>(material.ka) * ambient_intensity * color;
}

/// N.L at or below this counts as 0: the light lies in the surface's plane to
/// within rounding. Per-pixel points are interpolated, so they sit off the true
/// surface by a few ulps of their distance to the eye; that tilts L by a few
/// ulps times (distance to the eye / distance to the light), and without a
/// margin the contract's "specular if N.L > 0" would switch a full highlight on
/// at random pixels of a flat surface whose plane contains the light. 64
/// machine epsilons (7.6e-6 in float, 1.4e-14 in double) cover that noise for
/// lights farther than 1/20 of the eye's distance; what the margin removes is
/// a diffuse term below kd * Ip * 7.6e-6, invisible at 8 bits.
template <typename Real>
constexpr Real grazing_threshold() {
    return Real(64) * std::numeric_limits<Real>::epsilon();
}

/// Ip * kd * c * max(0, N.L) for one light, with L already a unit vector (or zero).
/// N.L within grazing_threshold() of zero counts as zero.
template <typename Real>
Vec3<Real> diffuse_from_direction(const Vec3<Real>& normal, const Vec3<Real>& color,
                                  const Vec3<Real>& to_light, const PhongMaterial& material,
                                  const Vec3<Real>& intensity) {
    const Real n_dot_l = glm::dot(normal, to_light);
    if (!(n_dot_l > grazing_threshold<Real>())) return Vec3<Real>(Real(0));
    return intensity * Vec3<Real>(material.kd) * color * n_dot_l;
}

/// Ip * ks * max(0, R.V)^n if N.L > 0 (beyond grazing_threshold()), with L and V
/// already unit vectors (or zero). R.V is clamped to at most 1: for unit vectors
/// it cannot exceed 1, and rounding that pushes it above would be amplified by a large n.
template <typename Real>
Vec3<Real> specular_from_direction(const Vec3<Real>& normal, const Vec3<Real>& to_light,
                                   const Vec3<Real>& to_eye, const PhongMaterial& material,
                                   const Vec3<Real>& intensity) {
    const Real n_dot_l = glm::dot(normal, to_light);
    if (!(n_dot_l > grazing_threshold<Real>())) return Vec3<Real>(Real(0));
    // A zero V (eye exactly at the point) contributes nothing, as the contract says.
    if (glm::dot(to_eye, to_eye) == Real(0)) return Vec3<Real>(Real(0));
    const Vec3<Real> reflected = Real(2) * normal * n_dot_l - to_light;
    const Real r_dot_v = std::min(Real(1), std::max(Real(0), glm::dot(reflected, to_eye)));
    // std::pow(0, 0) == 1, which is the contract's 0^0 = 1 for n = 0.
    const Real highlight = std::pow(r_dot_v, static_cast<Real>(material.n));
    return intensity * Vec3<Real>(material.ks) * highlight;
}

/// Sum over lights of the diffuse term at `point`.
template <typename Real>
Vec3<Real> diffuse_term(const Vec3<Real>& point, const Vec3<Real>& normal, const Vec3<Real>& color,
                        const PhongMaterial& material, const std::vector<PointLight>& lights) {
    Vec3<Real> sum(Real(0));
    for (const PointLight& light : lights) {
        const Vec3<Real> to_light = safe_normalize<Real>(Vec3<Real>(light.position) - point);
        sum += diffuse_from_direction<Real>(normal, color, to_light, material,
                                            Vec3<Real>(light.intensity));
    }
    return sum;
}

/// Sum over lights of the specular term at `point` seen from `eye`.
template <typename Real>
Vec3<Real> specular_term(const Vec3<Real>& point, const Vec3<Real>& normal, const Vec3<Real>& eye,
                         const PhongMaterial& material, const std::vector<PointLight>& lights) {
    const Vec3<Real> to_eye = safe_normalize<Real>(eye - point);
    Vec3<Real> sum(Real(0));
    for (const PointLight& light : lights) {
        const Vec3<Real> to_light = safe_normalize<Real>(Vec3<Real>(light.position) - point);
        sum += specular_from_direction<Real>(normal, to_light, to_eye, material,
                                             Vec3<Real>(light.intensity));
    }
    return sum;
}

/// The whole formula at one point. `normal` is normalised here (a zero normal
/// receives ambient light only).
template <typename Real>
Vec3<Real> light(const Vec3<Real>& point, const Vec3<Real>& normal, const Vec3<Real>& color,
                 const Vec3<Real>& eye, const PhongMaterial& material,
                 const std::vector<PointLight>& lights, const Vec3<Real>& ambient_intensity,
                 const Lighting& lighting) {
    const Vec3<Real> unit_normal = safe_normalize<Real>(normal);
    Vec3<Real> result(Real(0));
    if (lighting.ambient) result += ambient_term<Real>(color, material, ambient_intensity);
    if (lighting.diffuse) result += diffuse_term<Real>(point, unit_normal, color, material, lights);
    if (lighting.specular) result += specular_term<Real>(point, unit_normal, eye, material, lights);
    return result;
}

/// Convenience overload for the common float case: light(glm::vec3, ...).
inline glm::vec3 light(const glm::vec3& point, const glm::vec3& normal, const glm::vec3& color,
                       const glm::vec3& eye, const PhongMaterial& material,
                       const std::vector<PointLight>& lights, const glm::vec3& ambient_intensity,
                       const Lighting& lighting) {
    return light<float>(point, normal, color, eye, material, lights, ambient_intensity, lighting);
}

}  // namespace phongrast

#endif  // PHONGRAST_LIGHTING_HPP
