// The seed's per-triangle fill on the renderer's coverage rule (raster.hpp).
#include "phongrast/seed_fill.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "raster.hpp"

namespace phongrast {
namespace {

detail::SnappedPoint snapped_corner(const SeedCorner& corner, int index) {
    const glm::dvec2 p = corner.pixel;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kMaxSeedPixelCoordinate ||
        std::abs(p.y) > kMaxSeedPixelCoordinate) {
        throw std::invalid_argument("verts_p: vertex " + std::to_string(index) +
                                    ": expected finite pixel coordinates within +-1048576");
    }
    return detail::snap(p.x, p.y);
}

/// Calls shade(w) for every covered pixel centre, w the screen-space weights
/// of the corners in their given order, and paints what it returns.
template <typename Shade>
void fill(const std::array<SeedCorner, 3>& corners, int rows, int columns, const PaintPixel& paint,
          const Shade& shade) {
    const detail::SnappedPoint a = snapped_corner(corners[0], 0);
    const detail::SnappedPoint b = snapped_corner(corners[1], 1);
    const detail::SnappedPoint c = snapped_corner(corners[2], 2);
    if (rows < 1 || columns < 1) return;
    detail::CoverageTriangle triangle;
    if (!detail::setup_coverage(a, b, c, rows, columns, triangle)) return;  // no area, or no centre inside
    const double area = static_cast<double>(triangle.area2());
    detail::for_each_covered_pixel(triangle, 0, rows,
                                   [&](int row, int column, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
        // Coverage may have swapped corners 1 and 2 to make the area positive.
        const double w1 = static_cast<double>(e1) / area, w2 = static_cast<double>(e2) / area;
        const glm::dvec3 w(static_cast<double>(e0) / area, triangle.swapped ? w2 : w1, triangle.swapped ? w1 : w2);
        paint(row, column, shade(w));
    });
}

glm::dvec3 light_at(const SeedLighting& in, const glm::dvec3& normal, const glm::dvec3& color) {
    return light<double>(in.centroid, normal, color, in.eye, in.material, in.lights, in.ambient, in.lighting);
}

}  // namespace

void shade_gouraud(const std::array<SeedCorner, 3>& corners, const SeedLighting& lighting, int rows, int columns,
                   const PaintPixel& paint) {
    const glm::dvec3 lit[3] = {light_at(lighting, corners[0].normal, corners[0].color),
                               light_at(lighting, corners[1].normal, corners[1].color),
                               light_at(lighting, corners[2].normal, corners[2].color)};
    fill(corners, rows, columns, paint, [&](const glm::dvec3& w) { return w[0] * lit[0] + w[1] * lit[1] + w[2] * lit[2]; });
}

void shade_phong(const std::array<SeedCorner, 3>& corners, const SeedLighting& lighting, int rows, int columns,
                 const PaintPixel& paint) {
    fill(corners, rows, columns, paint, [&](const glm::dvec3& w) {
        const glm::dvec3 normal = w[0] * corners[0].normal + w[1] * corners[1].normal + w[2] * corners[2].normal;
        const glm::dvec3 color = w[0] * corners[0].color + w[1] * corners[1].color + w[2] * corners[2].color;
        return light_at(lighting, normal, color);
    });
}

}  // namespace phongrast
