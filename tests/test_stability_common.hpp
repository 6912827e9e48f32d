// Scenes and checks shared by the stability tests (tests/test_stability_*.cpp).
//
// Most cases use a camera whose arithmetic is exact: the eye at the origin
// looking down -z with up +y, so camera coordinates are (x, y, -z) bit for bit,
// focal 1 and a 1 x 1 sensor. A world point built by at_pixel() at a depth
// that is a power of two then projects to exactly the pixel coordinates asked
// for, and a test can place vertices on pixel centres or edges on purpose.
#ifndef PHONGRAST_TESTS_TEST_STABILITY_COMMON_HPP
#define PHONGRAST_TESTS_TEST_STABILITY_COMMON_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

#include "phongrast/render.hpp"

namespace stability {

inline const glm::vec3 kBackground(0.0f, 0.0f, 1.0f);
inline const glm::vec3 kWhite(1.0f);

/// Ambient-only scene (ka = Ia = 1, white surface) on a blue background, so a
/// covered pixel is exactly white and an uncovered one exactly blue.
inline phongrast::Scene pixel_exact_scene(int rows = 64, int columns = 64) {
    phongrast::Scene scene;
    scene.camera.eye = {0, 0, 0};
    scene.camera.lookat = {0, 0, -1};
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 1;
    scene.camera.sensor_height = 1;
    scene.camera.sensor_width = 1;
    scene.image.rows = rows;
    scene.image.columns = columns;
    scene.image.background = kBackground;
    scene.material.ka = glm::vec3(1.0f);
    scene.ambient = glm::vec3(1.0f);
    scene.lighting = phongrast::Lighting::only_ambient();
    scene.shader = phongrast::Shader::flat;
    return scene;
}

/// The world point that pixel_exact_scene's camera projects to (column, row)
/// at camera depth `depth` (exact when depth and the image size are powers of two).
inline glm::dvec3 at_pixel(const phongrast::Scene& scene, double column, double row, double depth) {
    return {(column / scene.image.columns - 0.5) * depth, (0.5 - row / scene.image.rows) * depth, -depth};
}

// Corners by value: callers may pass the mesh's own positions, which the
// push_backs below can reallocate (AddressSanitizer caught that aliasing).
inline std::uint32_t add_triangle(phongrast::Mesh& mesh, const glm::dvec3 a, const glm::dvec3 b,
                                  const glm::dvec3 c) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    // Three push_backs, not insert({a, b, c}): GCC 12 warns falsely (stringop-overflow) on the latter.
    mesh.positions.push_back(a);
    mesh.positions.push_back(b);
    mesh.positions.push_back(c);
    mesh.triangles.push_back({base, base + 1, base + 2});
    return base;
}

inline bool all_finite(const phongrast::Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(), [](const glm::vec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    });
}

/// Pixels whose colour differs from `background`.
inline std::uint64_t count_not(const phongrast::Image& image, const glm::vec3& background = kBackground) {
    return static_cast<std::uint64_t>(std::count_if(image.pixels.begin(), image.pixels.end(),
                                                    [&](const glm::vec3& p) { return p != background; }));
}

inline float max_channel_difference(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = glm::abs(a - b);
    return std::max(d.x, std::max(d.y, d.z));
}

/// Every render of a hard case must end like this: finite pixels, and the last
/// guard (which replaces a non-finite value by 0 and counts it) never fired.
#define STABILITY_CHECK_FINITE(result)                               \
    do {                                                             \
        CHECK(stability::all_finite((result).image));                \
        CHECK((result).stats.nonfinite_values_replaced == 0u);       \
    } while (false)

}  // namespace stability

#endif  // PHONGRAST_TESTS_TEST_STABILITY_COMMON_HPP
