// The seed's per-triangle fill: shade_gouraud and shade_phong paint one
// projected triangle, as the seed's render loop calls them (the Python
// module's functions of the same names are these).
#ifndef PHONGRAST_SEED_FILL_HPP
#define PHONGRAST_SEED_FILL_HPP

#include <array>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "phongrast/lighting.hpp"

namespace phongrast {

/// One corner of a projected triangle.
struct SeedCorner {
    /// Continuous pixel coordinates (column, row), what render() projects to:
    /// pixel (i, j) is painted when its centre (j + 0.5, i + 0.5) is inside.
    glm::dvec2 pixel{0.0};
    glm::dvec3 normal{0.0};  ///< world space
    glm::dvec3 color{1.0};
};

/// The lighting of one triangle, as the seed passes it: L and V at `centroid`.
struct SeedLighting {
    glm::dvec3 centroid{0.0};  ///< bcoords: where the light vectors are computed
    glm::dvec3 eye{0.0};       ///< cam_pos
    PhongMaterial material;
    std::vector<PointLight> lights;
    glm::dvec3 ambient{0.0};   ///< light_amb
    Lighting lighting = Lighting::full();
};

/// Receives each painted pixel: row, column (inside the canvas) and colour.
using PaintPixel = std::function<void(int row, int column, const glm::dvec3& color)>;

/// Largest |coordinate| of a corner, in pixels: the fixed-point coverage test's range.
constexpr double kMaxSeedPixelCoordinate = 1048576.0;

/// Gouraud: lights the three corners (in double precision), then paints each
/// covered pixel of a rows x columns canvas with the colours interpolated
/// linearly in screen space. Coverage is the renderer's: corners snapped to
/// 1/256 pixel, 64-bit edge functions, the top-left rule. Throws
/// std::invalid_argument for a non-finite corner or one beyond kMaxSeedPixelCoordinate.
void shade_gouraud(const std::array<SeedCorner, 3>& corners, const SeedLighting& lighting, int rows, int columns,
                   const PaintPixel& paint);

/// Phong: interpolates normal and colour linearly in screen space and lights
/// each covered pixel (the normal renormalised). Otherwise as shade_gouraud.
void shade_phong(const std::array<SeedCorner, 3>& corners, const SeedLighting& lighting, int rows, int columns,
                 const PaintPixel& paint);

}  // namespace phongrast

#endif  // PHONGRAST_SEED_FILL_HPP
