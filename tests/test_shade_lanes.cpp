// Gouraud with exact light vectors lights its vertices 64 at a time
// (shade_with_lanes(), src/shade_lanes.hpp): each lane must be bit for bit
// what PointShader::shade_with() gives that vertex alone, for every effect
// set, and in the edge cases the scalar formula decides by a branch: N.L at
// and around the grazing threshold, a zero vector to the eye, R.V rounded
// past 1 or below 0, exponent 0 and fractional exponents, signed zeros.
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "phongrast/lighting.hpp"
#include "shade_lanes.hpp"

using namespace phongrast;
using namespace phongrast::detail;

namespace {

template <typename Real>
bool same_bits(const Vec3<Real>& a, const Vec3<Real>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

template <typename Real>
Vec3<Real> unit(std::mt19937& random) {
    std::normal_distribution<double> gauss;
    const glm::dvec3 v(gauss(random), gauss(random), gauss(random));
    return Vec3<Real>(v / glm::length(v));
}

/// Lights `points` scalar and in lanes with a rig of `lights` lights, the
/// given effects and exponent; returns how many lanes differ in any bit.
template <typename Real>
int lanes_differing(std::size_t lights, const EffectSet& effects, float exponent, std::mt19937& random) {
    constexpr std::size_t N = 64;
    LightRig<Real> rig;
    rig.material.kd = glm::vec3(0.7f, 0.5f, 0.25f);
    rig.material.ks = glm::vec3(1.0f, 0.9f, 0.3f);
    rig.material.n = exponent;
    rig.ambient_factor = Vec3<Real>(Real(0.1), Real(0.2), Real(0.05));
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::size_t k = 0; k < lights; ++k) {
        // Positions are not read: the vectors below stand for them.
        rig.active_lights.push_back({Vec3<Real>(Real(0)), Vec3<Real>(Real(uniform(random)), Real(0.5), Real(2))});
    }
    PointShader<Real> shader;
    shader.rig = &rig;
    shader.effects = effects;

    const Real threshold = grazing_threshold<Real>();
    std::vector<AxisLanes<Real, N>> to_light(lights);
    AxisLanes<Real, N> to_eye;
    ShadeLanesInput<Real, N> in;
    std::vector<LightVectorsAt<Real>> scalar(N);
    for (std::size_t l = 0; l < N; ++l) {
        const Vec3<Real> normal = unit<Real>(random);
        Vec3<Real> eye = unit<Real>(random);
        Vec3<Real> color(Real(uniform(random)), Real(uniform(random)), Real(uniform(random)));
        if (l % 16 == 7) color = Vec3<Real>(Real(-0.0), Real(0), Real(-0.0));  // signed zeros through the sums
        scalar[l].to_light.resize(lights);
        for (std::size_t k = 0; k < lights; ++k) {
            Vec3<Real> light = unit<Real>(random);
            switch ((l + k) % 8) {
                case 1: light = Vec3<Real>(Real(0)); break;  // a light at the point
                case 2: {
                    // N.L exactly at, just above, just below the threshold: an L along the
                    // normal scaled to it (not a unit vector; the formula does not care).
                    const Real scale = threshold * Real(k % 3 == 0 ? 1 : (k % 3 == 1 ? 1.0001 : 0.9999));
                    light = normal * scale;
                    break;
                }
                case 3: light = -normal; break;  // facing away
                case 4: eye = glm::normalize(Real(2) * normal * glm::dot(normal, light) - light); break;  // R.V about 1
                default: break;
            }
            scalar[l].to_light[k] = light;
            to_light[k].set(l, light);
        }
        // After the lights, which may aim the eye: lanes whose lights are mostly random.
        if (l % 16 == 14) eye = Vec3<Real>(Real(0));  // the eye at the point: no highlight
        if (l % 16 == 13) eye = kEyeAtInfinity<Real>;  // orthographic
        scalar[l].to_eye = eye;
        to_eye.set(l, eye);
        in.normal.set(l, normal);
        in.color.set(l, color);
    }
    in.to_light = to_light.data();
    in.to_eye = &to_eye;
    AxisLanes<Real, N> lit;
    shade_with_lanes(shader, in, lit);
    int differing = 0;
    for (std::size_t l = 0; l < N; ++l) {
        const Vec3<Real> expected = shader.shade_with(scalar[l], in.normal.get(l), in.color.get(l));
        if (!same_bits(expected, lit.get(l))) ++differing;
    }
    return differing;
}

template <typename Real>
void check_every_effect_set() {
    std::mt19937 random(2026);
    for (int key = 0; key < 8; ++key) {
        EffectSet effects;
        effects.ambient = (key & 4) != 0;
        effects.diffuse = (key & 2) != 0;
        effects.specular = (key & 1) != 0;
        effects.normals = effects.diffuse || effects.specular;
        for (std::size_t lights : {std::size_t(1), std::size_t(3), std::size_t(8)}) {
            for (float exponent : {0.0f, 1.0f, 32.0f, 7.5f, 300.0f}) {
                for (int round = 0; round < 4; ++round) {
                    INFO("effects " << key << ", " << lights << " lights, n = " << exponent);
                    CHECK(lanes_differing<Real>(lights, effects, exponent, random) == 0);
                }
            }
        }
    }
}

}  // namespace

TEST_CASE("lit in lanes: every lane as shade_with() gives it, bit for bit (float)") { check_every_effect_set<float>(); }

TEST_CASE("lit in lanes: every lane as shade_with() gives it, bit for bit (double)") {
    check_every_effect_set<double>();
}
