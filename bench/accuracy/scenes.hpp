// Scenes generated in code for the accuracy report, each built so that one
// accuracy option matters (header-only, shared with the tests).
//
//   sphere   a coloured icosphere: smooth, everything inside the image
//   floor    a close-up floor of large triangles seen at a low angle: perspective
//            and the image border matter
//   shiny    a gently curved sheet, Phong exponent 150, a light at a grazing angle
//   overlap  two quads that pass through each other: painter's order is wrong on one side
#ifndef PHONGRAST_BENCH_ACCURACY_SCENES_HPP
#define PHONGRAST_BENCH_ACCURACY_SCENES_HPP

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "phongrast/render.hpp"

namespace phongrast::accuracy {

struct NamedScene {
    std::string name;
    std::string description;
    Scene scene;
};

namespace scene_detail {

inline void set_view(Scene& scene, glm::dvec3 eye, glm::dvec3 lookat, double fov_degrees, int size) {
    scene.camera.eye = eye;
    scene.camera.lookat = lookat;
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 1.0;
    const double sensor = 2.0 * std::tan(fov_degrees * 3.14159265358979323846 / 360.0);
    scene.camera.sensor_height = scene.camera.sensor_width = sensor;
    scene.image.rows = scene.image.columns = size;
}

/// Grid of (cells + 1)^2 vertices over x, z in [x0, x1] x [z0, z1] at height height(x, z),
/// two counter-clockwise (seen from +y) triangles per cell.
template <typename Height, typename Color>
Mesh grid(int cells, double x0, double x1, double z0, double z1, Height height, Color color) {
    Mesh mesh;
    for (int i = 0; i <= cells; ++i) {
        for (int j = 0; j <= cells; ++j) {
            const double x = x0 + (x1 - x0) * j / cells, z = z0 + (z1 - z0) * i / cells;
            mesh.positions.push_back({x, height(x, z), z});
            mesh.colors.push_back(color(i, j));
        }
    }
    const auto at = [cells](int i, int j) { return std::uint32_t(i * (cells + 1) + j); };
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            // Rows of z grow toward the viewer: (i, j) -> (i+1, j) -> (i+1, j+1) is counter-clockwise from +y.
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

}  // namespace scene_detail

/// Icosahedron subdivided `levels` times, radius 1 at the origin, coloured by position.
inline Mesh icosphere(int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Mesh mesh;
    mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (glm::dvec3& p : mesh.positions) p = glm::normalize(p);
    mesh.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto edge = std::make_pair(std::min(a, b), std::max(a, b));
            const auto found = midpoints.find(edge);
            if (found != midpoints.end()) return found->second;
            mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
            const auto index = std::uint32_t(mesh.positions.size() - 1);
            midpoints.emplace(edge, index);
            return index;
        };
        std::vector<Triangle> finer;
        for (const Triangle& tri : mesh.triangles) {
            const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                                ca = midpoint(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    for (const glm::dvec3& p : mesh.positions) {
        mesh.colors.push_back(glm::vec3(0.55 + 0.45 * p.x, 0.55 + 0.45 * p.y, 0.55 - 0.45 * p.x * p.y));
    }
    return mesh;
}

inline NamedScene sphere_scene(int size) {
    NamedScene s{"sphere", "coloured icosphere, 1280 triangles, n = 20, two lights", {}};
    Scene& scene = s.scene;
    scene.mesh = icosphere(3);
    scene_detail::set_view(scene, {0.6, 1.2, 4.0}, {0, 0, 0}, 36.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.5f), 20.0f};
    scene.lights = {{{4, 5, 6}, glm::vec3(0.8f)}, {{-5, 1, 2}, {0.3f, 0.3f, 0.5f}}};
    scene.shader = Shader::phong;
    return s;
}

inline NamedScene floor_scene(int size) {
    NamedScene s{"floor", "close-up floor: 4x4 quads of 10x10 units seen from 1 unit above, light 0.4 above it", {}};
    Scene& scene = s.scene;
    const glm::vec3 palette[4] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.3f, 0.9f}, {0.95f, 0.9f, 0.3f}};
    scene.mesh = scene_detail::grid(
        4, -20.0, 20.0, -38.0, 2.0, [](double, double) { return 0.0; },
        [&palette](int i, int j) { return palette[(i * 3 + j) % 4]; });
    scene_detail::set_view(scene, {0.0, 1.0, 1.5}, {0.0, 0.0, -4.0}, 70.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.6f), 30.0f};
    scene.lights = {{{0.5, 0.4, -2.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

inline NamedScene shiny_scene(int size) {
    NamedScene s{"shiny", "curved sheet, 24x24 quads, n = 150, lit from behind 4 degrees above its plane", {}};
    Scene& scene = s.scene;
    scene.mesh = scene_detail::grid(
        24, -2.0, 2.0, -2.0, 2.0,
        [](double x, double z) { return 0.12 * std::sin(1.7 * x) * std::cos(1.3 * z); },
        [](int i, int j) { return glm::vec3(0.5f + 0.02f * float(i % 5), 0.6f, 0.8f - 0.02f * float(j % 5)); });
    scene_detail::set_view(scene, {0.0, 0.9, 3.6}, {0.0, 0.0, -0.5}, 50.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.15f), glm::vec3(0.5f), glm::vec3(1.0f), 150.0f};
    // Grazing: 0.5 up, 8 units behind the sheet (about 4 degrees above its plane),
    // so the bumps' slopes reflect tight highlights toward the low eye.
    scene.lights = {{{0.3, 0.5, -8.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

inline NamedScene overlap_scene(int size) {
    NamedScene s{"overlap", "two quads passing through each other (2 triangles each): painter's order fails on one side", {}};
    Scene& scene = s.scene;
    Mesh& mesh = scene.mesh;
    // Red quad in the plane z = 0; green quad tilted about y so that z = 0.9 x.
    mesh.positions = {{-1.5, -1.0, 0.0}, {1.5, -1.0, 0.0}, {1.5, 1.0, 0.0}, {-1.5, 1.0, 0.0},
                      {-1.2, -0.7, -1.08}, {1.2, -0.7, 1.08}, {1.2, 1.3, 1.08}, {-1.2, 1.3, -1.08}};
    const glm::vec3 red(0.9f, 0.25f, 0.2f), green(0.25f, 0.85f, 0.3f);
    mesh.colors = {red, red, red, red, green, green, green, green};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    scene_detail::set_view(scene, {0.4, 0.6, 5.0}, {0.0, 0.1, 0.0}, 40.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.25f), glm::vec3(0.7f), glm::vec3(0.3f), 10.0f};
    scene.lights = {{{1.0, 3.0, 6.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

inline std::vector<NamedScene> generated_scenes(int size) {
    return {sphere_scene(size), floor_scene(size), shiny_scene(size), overlap_scene(size)};
}

}  // namespace phongrast::accuracy

#endif  // PHONGRAST_BENCH_ACCURACY_SCENES_HPP
