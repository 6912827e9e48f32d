// The whole-mesh scans behind validation (mesh_scans.hpp): each block test
// agrees with the element test it stands in for, at every place in a block
// of vectors (the groups of eight and the tail), and first_bad() finds the
// first bad element across oneTBB's blocks, as a loop from element 0 does.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "mesh_scans.hpp"

using namespace phongrast::detail;

namespace {

constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// any_beyond() on one vector (all three channels the same number) against one limit.
bool beyond(float value, double limit) {
    const std::uint32_t bits[3] = {passing_magnitude_bits(limit), passing_magnitude_bits(limit),
                                   passing_magnitude_bits(limit)};
    const glm::vec3 v(value);
    return any_beyond(&v, 0, 1, bits);
}

}  // namespace

TEST_CASE("any_beyond is |value| <= limit compared in double, NaN and infinity failing") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    CHECK_FALSE(beyond(1.0f, 1.0));
    CHECK_FALSE(beyond(-1.0f, 1.0));
    CHECK(beyond(std::nextafter(1.0f, 2.0f), 1.0));
    CHECK_FALSE(beyond(0.0f, 0.0));
    CHECK_FALSE(beyond(-0.0f, 0.0));
    CHECK(beyond(std::numeric_limits<float>::denorm_min(), 0.0));
    // A limit between two floats: the one below passes, the one above fails.
    const double between = (1.0 + double(std::nextafter(1.0f, 2.0f))) / 2.0;
    CHECK_FALSE(beyond(1.0f, between));
    CHECK(beyond(std::nextafter(1.0f, 2.0f), between));
    // No limit (infinite, or past the floats): every finite float passes, infinity and NaN fail.
    for (double limit : {kInf, 1e300, double(kFloatMax)}) {
        CHECK_FALSE(beyond(kFloatMax, limit));
        CHECK_FALSE(beyond(-kFloatMax, limit));
        CHECK(beyond(inf, limit));
        CHECK(beyond(-inf, limit));
        CHECK(beyond(nan, limit));
    }
    // A negative or NaN limit: nothing passes, zero included.
    CHECK(beyond(0.0f, -1.0));
    CHECK(beyond(0.0f, std::nan("")));

    // The same answer as the double comparison on random numbers of every magnitude.
    std::mt19937 rng(7);
    std::uniform_int_distribution<std::uint32_t> any_bits;
    std::uniform_real_distribution<double> exponent(-45.0, 40.0);
    for (int i = 0; i < 20000; ++i) {
        const std::uint32_t raw = any_bits(rng);
        float value;
        std::memcpy(&value, &raw, sizeof value);
        const double limit = std::pow(10.0, exponent(rng));
        const bool expected = !(std::abs(double(value)) <= limit) || !std::isfinite(value);
        REQUIRE(beyond(value, limit) == expected);
        const double near = std::abs(double(value));  // limits at the value itself and one double either side
        if (std::isfinite(near)) {
            for (double at : {near, std::nextafter(near, 0.0), std::nextafter(near, kInf)}) {
                REQUIRE(beyond(value, at) == !(near <= at));
            }
        }
    }
}

TEST_CASE("the scans see a bad element wherever it sits in a block of vectors") {
    const std::uint32_t finite[3] = {finite_magnitude_bits(), finite_magnitude_bits(), finite_magnitude_bits()};
    const std::uint32_t per_channel[3] = {passing_magnitude_bits(1.0), passing_magnitude_bits(2.0),
                                          passing_magnitude_bits(3.0)};
    for (std::size_t count : {1, 7, 8, 9, 16, 23, 31}) {
        for (std::size_t begin : {std::size_t(0), std::size_t(1)}) {
            if (begin >= count) continue;
            std::vector<glm::dvec3> positions(count, glm::dvec3(1e300, -1e-300, 0.0));
            std::vector<glm::vec3> colours(count, glm::vec3(-1.0f, 2.0f, -3.0f));  // each at its limit
            std::vector<phongrast::Triangle> triangles(count, phongrast::Triangle{0, 4, 9});
            CHECK_FALSE(any_nonfinite(positions.data(), begin, count));
            CHECK_FALSE(any_beyond(colours.data(), begin, count, per_channel));
            CHECK_FALSE(any_beyond(colours.data(), begin, count, finite));
            CHECK_FALSE(any_index_at_least(triangles.data(), begin, count, 10));
            CHECK(any_index_at_least(triangles.data(), begin, count, 9));
            for (std::size_t bad = begin; bad < count; ++bad) {
                for (int channel = 0; channel < 3; ++channel) {
                    std::vector<glm::dvec3> p = positions;
                    p[bad][channel] = channel == 1 ? std::nan("") : -kInf;
                    CHECK(any_nonfinite(p.data(), begin, count));
                    CHECK_FALSE(any_nonfinite(p.data(), begin, bad));  // the range before it is clean
                    std::vector<glm::vec3> c = colours;
                    c[bad][channel] = std::nextafter(c[bad][channel], 2.0f * c[bad][channel]);  // one float further out
                    CHECK(any_beyond(c.data(), begin, count, per_channel));
                    CHECK_FALSE(any_beyond(c.data(), begin, bad, per_channel));
                    CHECK_FALSE(any_beyond(c.data(), begin, count, finite));
                    std::vector<phongrast::Triangle> t = triangles;
                    t[bad][static_cast<std::size_t>(channel)] = 10;
                    CHECK(any_index_at_least(t.data(), begin, count, 10));
                    CHECK_FALSE(any_index_at_least(t.data(), begin, bad, 10));
                }
            }
        }
    }
    // Empty ranges hold nothing bad.
    CHECK_FALSE(any_nonfinite(nullptr, 0, 0));
    CHECK_FALSE(any_beyond(nullptr, 0, 0, finite));
    CHECK_FALSE(any_index_at_least(nullptr, 0, 0, 0));
}

TEST_CASE("first_bad finds the first bad element across blocks, as a loop from element 0") {
    const std::size_t n = 300000;  // several of first_bad's blocks of 65536
    std::vector<glm::dvec3> positions(n, glm::dvec3(0.5));
    const auto first = [&] {
        return first_bad(
            n, [&](std::size_t begin, std::size_t end) { return any_nonfinite(positions.data(), begin, end); },
            [&](std::size_t i) { return !std::isfinite(positions[i].x + positions[i].y + positions[i].z); });
    };
    CHECK(first() == n);
    for (std::size_t bad : {std::size_t(0), std::size_t(65535), std::size_t(65536), std::size_t(200001), n - 1}) {
        positions[bad].y = kInf;
        positions[n - 1].z = std::nan("");  // a later bad one does not hide it
        CHECK(first() == bad);
        positions[bad].y = 0.5;
        positions[n - 1].z = 0.5;
    }
}
