// phongrast::shade_gouraud / shade_phong: the seed's one-triangle fill on the renderer's coverage rule.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <utility>

#include "phongrast/seed_fill.hpp"

using namespace phongrast;

namespace {

using Painted = std::map<std::pair<int, int>, glm::dvec3>;

Painted paint_gouraud(const std::array<SeedCorner, 3>& corners, const SeedLighting& lighting, int rows, int columns) {
    Painted painted;
    shade_gouraud(corners, lighting, rows, columns,
                  [&](int row, int column, const glm::dvec3& color) { painted[{row, column}] = color; });
    return painted;
}

SeedLighting ambient_only() {
    SeedLighting lighting;
    lighting.material.ka = glm::vec3(1.0f);
    lighting.ambient = glm::dvec3(1.0);
    lighting.lighting = Lighting::only_ambient();
    return lighting;
}

}  // namespace

TEST_CASE("Gouraud interpolates the lit corners with screen-space weights at pixel centres") {
    const std::array<SeedCorner, 3> corners = {SeedCorner{{0, 0}, {0, 0, 1}, {1, 0, 0}},
                                               SeedCorner{{6, 0}, {0, 0, 1}, {0, 1, 0}},
                                               SeedCorner{{0, 4}, {0, 0, 1}, {0, 0, 1}}};
    const Painted painted = paint_gouraud(corners, ambient_only(), 4, 6);
    CHECK(painted.size() == 12);  // the centres below the diagonal
    // Pixel (0, 0) is at (0.5, 0.5): weights 1 - 0.5/6 - 0.5/4, 0.5/6, 0.5/4.
    const glm::dvec3 first = painted.at({0, 0});
    CHECK(first.x == Approx(1 - 0.5 / 6 - 0.5 / 4));
    CHECK(first.y == Approx(0.5 / 6));
    CHECK(first.z == Approx(0.5 / 4));
    CHECK(painted.count({3, 5}) == 0);
}

TEST_CASE("either winding paints the same pixels with the same colours, Phong lights each pixel") {
    std::array<SeedCorner, 3> corners = {SeedCorner{{1.3, 0.7}, {0, 0, 1}, {1, 0, 0}},
                                         SeedCorner{{9.6, 2.2}, {0, 1, 1}, {0, 1, 0}},
                                         SeedCorner{{3.1, 7.9}, {1, 0, 1}, {0, 0, 1}}};
    const Painted counter_clockwise = paint_gouraud(corners, ambient_only(), 8, 10);
    std::swap(corners[1], corners[2]);
    CHECK(paint_gouraud(corners, ambient_only(), 8, 10) == counter_clockwise);
    SeedLighting lit = ambient_only();
    lit.lighting = Lighting::full();
    lit.material.kd = glm::vec3(0.8f);
    lit.lights = {{{5.0, 5.0, 10.0}, glm::vec3(1.0f)}};
    lit.eye = {5.0, 4.0, 10.0};
    int phong_pixels = 0;
    shade_phong(corners, lit, 8, 10, [&](int row, int column, const glm::dvec3& color) {
        ++phong_pixels;
        CHECK(counter_clockwise.count({row, column}) == 1);
        CHECK(std::isfinite(color.x + color.y + color.z));
    });
    CHECK(phong_pixels == static_cast<int>(counter_clockwise.size()));
}

TEST_CASE("degenerate, off-canvas and out-of-range corners, on purpose") {
    const SeedLighting lighting = ambient_only();
    int painted = 0;
    const PaintPixel count = [&](int, int, const glm::dvec3&) { ++painted; };
    // A line: no area, nothing painted. Off the canvas: nothing painted.
    shade_gouraud({SeedCorner{{0, 0}}, SeedCorner{{5, 5}}, SeedCorner{{10, 10}}}, lighting, 16, 16, count);
    shade_gouraud({SeedCorner{{-9, -9}}, SeedCorner{{-5, -9}}, SeedCorner{{-9, -5}}}, lighting, 16, 16, count);
    CHECK(painted == 0);
    CHECK_THROWS_WITH(shade_phong({SeedCorner{{0, 0}}, SeedCorner{{2e6, 0}}, SeedCorner{{0, 1}}}, lighting, 8, 8, count),
                      Catch::Contains("vertex 1: expected finite pixel coordinates within +-1048576"));
    CHECK_THROWS_AS(shade_gouraud({SeedCorner{{0, std::nan("")}}, SeedCorner{{1, 0}}, SeedCorner{{0, 1}}}, lighting,
                                  8, 8, count),
                    std::invalid_argument);
}
