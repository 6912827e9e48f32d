#include "default_mesh.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace phongrast::cli {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double tube_radius = 0.42;

/// The (p, q) = (2, 3) torus knot: winds twice around the z axis and three times through the hole.
glm::dvec3 knot(double t) {
    const double radius = 2.0 + std::cos(3.0 * t);
    return {radius * std::cos(2.0 * t), radius * std::sin(2.0 * t), std::sin(3.0 * t)};
}

/// Hue h in [0,1) to a soft, saturated RGB (HSV with s = 0.7, v = 0.95).
glm::vec3 rainbow(double h) {
    const double saturation = 0.7;
    const double value = 0.95;
    const double sector = std::fmod(h, 1.0) * 6.0;
    const int i = static_cast<int>(sector) % 6;
    const double f = sector - std::floor(sector);
    const double p = value * (1.0 - saturation);
    const double q = value * (1.0 - saturation * f);
    const double u = value * (1.0 - saturation * (1.0 - f));
    const double rgb[6][3] = {{value, u, p}, {q, value, p}, {p, value, u}, {p, q, value}, {u, p, value}, {value, p, q}};
    return {static_cast<float>(rgb[i][0]), static_cast<float>(rgb[i][1]), static_cast<float>(rgb[i][2])};
}

}  // namespace

Mesh make_torus_knot(int segments, int sides) {
    if (segments < 3 || sides < 3) throw std::invalid_argument("torus knot: need at least 3 segments and 3 sides");
    Mesh mesh;
    const double step = 2.0 * pi / segments;
    for (int s = 0; s < segments; ++s) {
        const double t = s * step;
        // Frenet-like frame from finite differences: the knot's curvature never
        // vanishes, so the normal (towards the centre of curvature) is defined.
        const glm::dvec3 centre = knot(t);
        const glm::dvec3 tangent = glm::normalize(knot(t + 1e-4) - knot(t - 1e-4));
        const glm::dvec3 bend = knot(t + 1e-3) - 2.0 * centre + knot(t - 1e-3);
        const glm::dvec3 normal = glm::normalize(bend - glm::dot(bend, tangent) * tangent);
        const glm::dvec3 binormal = glm::cross(tangent, normal);
        const glm::vec3 color = rainbow(static_cast<double>(s) / segments);
        for (int k = 0; k < sides; ++k) {
            const double angle = 2.0 * pi * k / sides;
            mesh.positions.push_back(centre + tube_radius * (std::cos(angle) * normal + std::sin(angle) * binormal));
            mesh.colors.push_back(color);
        }
    }
    const auto index = [&](int s, int k) {
        return static_cast<std::uint32_t>((s % segments) * sides + (k % sides));
    };
    for (int s = 0; s < segments; ++s) {
        for (int k = 0; k < sides; ++k) {
            // Around the ring the angle turns from normal towards binormal =
            // tangent x normal, i.e. counter-clockwise about the tangent, so
            // (s,k) -> (s,k+1) -> (s+1,k+1) is counter-clockwise seen from
            // outside the tube (tests check the mesh's signed volume is positive).
            mesh.triangles.push_back({index(s, k), index(s, k + 1), index(s + 1, k + 1)});
            mesh.triangles.push_back({index(s, k), index(s + 1, k + 1), index(s + 1, k)});
        }
    }
    return mesh;
}

}  // namespace phongrast::cli
