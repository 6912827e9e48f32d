#include "mesh_scans.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace phongrast::detail {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vec3 is three packed floats");
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "dvec3 is three packed doubles");
static_assert(sizeof(Triangle) == 3 * sizeof(std::uint32_t), "a triangle is three packed indices");

std::uint32_t passing_magnitude_bits(double limit) {
    constexpr float kMax = std::numeric_limits<float>::max();
    if (!(limit >= 0.0)) return ~std::uint32_t(0);  // nothing passes (NaN included)
    float largest = limit < double(kMax) ? static_cast<float>(limit) : kMax;
    if (double(largest) > limit) largest = std::nextafter(largest, 0.0f);  // rounded up: one float down
    std::uint32_t bits;
    std::memcpy(&bits, &largest, sizeof bits);
    return bits;
}

std::uint32_t finite_magnitude_bits() { return passing_magnitude_bits(std::numeric_limits<float>::max()); }

// A float's bits without the sign order its magnitude (infinity above every
// finite float, NaN above infinity), so |a| <= limit is magnitude <= limit
// bits; limit - magnitude, in 32-bit unsigned arithmetic, has bit 31 set
// exactly when it fails (both are below 2^31, or the limit is all ones).
bool any_beyond(const glm::vec3* v, std::size_t begin, std::size_t end, const std::uint32_t channel_bits[3]) {
    if (begin >= end) return false;
    std::uint32_t limits[24];  // eight vectors' channels: whole SIMD registers of them
    for (int k = 0; k < 24; ++k) limits[k] = channel_bits[k % 3];
    const float* x = &v[begin].x;
    const std::size_t floats = 3 * (end - begin), whole = floats / 24 * 24;
    std::uint32_t failed = 0;
    for (std::size_t group = 0; group < whole; group += 24) {
        for (int k = 0; k < 24; ++k) {
            std::uint32_t bits;
            std::memcpy(&bits, x + group + k, sizeof bits);
            failed |= limits[k] - (bits & 0x7fffffffu);
        }
    }
    for (std::size_t k = whole; k < floats; ++k) {
        std::uint32_t bits;
        std::memcpy(&bits, x + k, sizeof bits);
        failed |= limits[k % 24] - (bits & 0x7fffffffu);
    }
    return (failed >> 31) != 0;
}

// Infinite or NaN: every exponent bit set, the one pattern where adding one
// to the exponent carries into the sign bit.
bool any_nonfinite(const glm::dvec3* v, std::size_t begin, std::size_t end) {
    if (begin >= end) return false;
    const double* x = &v[begin].x;
    std::uint64_t carried = 0;
    for (std::size_t k = 0; k < 3 * (end - begin); ++k) {
        std::uint64_t bits;
        std::memcpy(&bits, x + k, sizeof bits);
        carried |= (bits & 0x7ff0000000000000ull) + 0x0010000000000000ull;
    }
    return (carried >> 63) != 0;
}

bool any_index_at_least(const Triangle* triangles, std::size_t begin, std::size_t end, std::size_t vertices) {
    if (begin >= end) return false;
    const std::uint32_t* index = triangles[begin].data();
    std::uint32_t largest = 0;
    for (std::size_t k = 0; k < 3 * (end - begin); ++k) largest = std::max(largest, index[k]);
    return largest >= vertices;
}

}  // namespace phongrast::detail
