// The vertex stage normalises normals many at a time: bit for bit what
// safe_normalize() gives one at a time, edge cases included.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "normalize_lanes.hpp"
#include "phongrast/lighting.hpp"

namespace {

template <typename Real>
bool same_bits(Real a, Real b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

template <typename Real>
void check_lanes_match_scalar() {
    const Real inf = std::numeric_limits<Real>::infinity();
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real tiny = std::numeric_limits<Real>::denorm_min();
    const Real huge = std::numeric_limits<Real>::max();
    std::vector<phongrast::Vec3<Real>> vectors = {
        {0, 0, 0}, {-0.0f, 0, 0}, {tiny, 0, 0}, {tiny, tiny, -tiny}, {huge, huge, huge}, {huge, -huge, 1},
        {inf, 0, 0}, {1, nan, 0}, {nan, nan, nan}, {Real(1e-30), Real(2e-30), 0}, {3, 4, 0}, {0, 0, -1}};
    std::mt19937 random(11);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-40, 40);
    while (vectors.size() < 1000) {
        vectors.push_back({static_cast<Real>(std::ldexp(mantissa(random), exponent(random))),
                           static_cast<Real>(std::ldexp(mantissa(random), exponent(random))),
                           static_cast<Real>(std::ldexp(mantissa(random), exponent(random)))});
    }
    std::vector<Real> x, y, z;
    for (const auto& v : vectors) {
        x.push_back(v.x);
        y.push_back(v.y);
        z.push_back(v.z);
    }
    phongrast::detail::safe_normalize_lanes(vectors.size(), x.data(), y.data(), z.data());
    for (std::size_t i = 0; i < vectors.size(); ++i) {
        const phongrast::Vec3<Real> expected = phongrast::safe_normalize<Real>(vectors[i]);
        INFO("vector " << i << ": " << vectors[i].x << " " << vectors[i].y << " " << vectors[i].z);
        CHECK(same_bits(x[i], expected.x));
        CHECK(same_bits(y[i], expected.y));
        CHECK(same_bits(z[i], expected.z));
        // Finite in, finite out (NaN input, which mesh validation refuses, may come out NaN in both).
        if (std::isfinite(vectors[i].x) && std::isfinite(vectors[i].y) && std::isfinite(vectors[i].z)) {
            CHECK(std::isfinite(x[i] + y[i] + z[i]));
        }
    }
}

}  // namespace

TEST_CASE("normalising many normals at once matches safe_normalize bit for bit") {
    check_lanes_match_scalar<float>();
    check_lanes_match_scalar<double>();
}
