#include "scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "meshes.hpp"

namespace phongrast::support {
namespace {

constexpr double kPi = 3.14159265358979323846;

void set_view(Scene& scene, glm::dvec3 eye, glm::dvec3 lookat, double fov_degrees, int size) {
    scene.camera.eye = eye;
    scene.camera.lookat = lookat;
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 1.0;
    const double sensor = 2.0 * std::tan(fov_degrees * kPi / 360.0);
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

}  // namespace

NamedScene sphere_scene(int size) {
    NamedScene s{"sphere", "coloured icosphere, 1280 triangles, n = 20, two lights", {}};
    Scene& scene = s.scene;
    scene.mesh = icosphere(8);
    set_view(scene, {0.6, 1.2, 4.0}, {0, 0, 0}, 36.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.5f), 20.0f};
    scene.lights = {{{4, 5, 6}, glm::vec3(0.8f)}, {{-5, 1, 2}, {0.3f, 0.3f, 0.5f}}};
    scene.shader = Shader::phong;
    return s;
}

NamedScene floor_scene(int size) {
    NamedScene s{"floor", "close-up floor: 4x4 quads of 10x10 units seen from 1 unit above, light 0.4 above it", {}};
    Scene& scene = s.scene;
    const glm::vec3 palette[4] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.3f, 0.9f}, {0.95f, 0.9f, 0.3f}};
    scene.mesh = grid(
        4, -20.0, 20.0, -38.0, 2.0, [](double, double) { return 0.0; },
        [&palette](int i, int j) { return palette[(i * 3 + j) % 4]; });
    set_view(scene, {0.0, 1.0, 1.5}, {0.0, 0.0, -4.0}, 70.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.2f), glm::vec3(0.7f), glm::vec3(0.6f), 30.0f};
    scene.lights = {{{0.5, 0.4, -2.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

NamedScene shiny_scene(int size) {
    NamedScene s{"shiny", "curved sheet, 24x24 quads, n = 150, lit from behind 4 degrees above its plane", {}};
    Scene& scene = s.scene;
    scene.mesh = grid(
        24, -2.0, 2.0, -2.0, 2.0, [](double x, double z) { return 0.12 * std::sin(1.7 * x) * std::cos(1.3 * z); },
        [](int i, int j) { return glm::vec3(0.5f + 0.02f * float(i % 5), 0.6f, 0.8f - 0.02f * float(j % 5)); });
    set_view(scene, {0.0, 0.9, 3.6}, {0.0, 0.0, -0.5}, 50.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.15f), glm::vec3(0.5f), glm::vec3(1.0f), 150.0f};
    // Grazing: 0.5 up, 8 units behind the sheet (about 4 degrees above its plane),
    // so the bumps' slopes reflect tight highlights toward the low eye.
    scene.lights = {{{0.3, 0.5, -8.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

NamedScene overlap_scene(int size) {
    NamedScene s{"overlap", "two quads passing through each other (2 triangles each): painter's order fails on one side", {}};
    Scene& scene = s.scene;
    Mesh& mesh = scene.mesh;
    // Red quad in the plane z = 0; green quad tilted about y so that z = 0.9 x.
    mesh.positions = {{-1.5, -1.0, 0.0}, {1.5, -1.0, 0.0}, {1.5, 1.0, 0.0}, {-1.5, 1.0, 0.0},
                      {-1.2, -0.7, -1.08}, {1.2, -0.7, 1.08}, {1.2, 1.3, 1.08}, {-1.2, 1.3, -1.08}};
    const glm::vec3 red(0.9f, 0.25f, 0.2f), green(0.25f, 0.85f, 0.3f);
    mesh.colors = {red, red, red, red, green, green, green, green};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    set_view(scene, {0.4, 0.6, 5.0}, {0.0, 0.1, 0.0}, 40.0, size);
    scene.image.background = glm::vec3(0.1f);
    scene.material = {glm::vec3(0.25f), glm::vec3(0.7f), glm::vec3(0.3f), 10.0f};
    scene.lights = {{{1.0, 3.0, 6.0}, glm::vec3(1.0f)}};
    scene.shader = Shader::phong;
    return s;
}

std::vector<NamedScene> generated_scenes(int size) {
    return {sphere_scene(size), floor_scene(size), shiny_scene(size), overlap_scene(size)};
}

NamedScene icosphere_scene(const std::string& name, int frequency, int rows) {
    NamedScene named;
    named.name = name;
    named.description = "dented icosphere, " + std::to_string(20 * frequency * frequency) + " triangles, three lights";
    Scene& scene = named.scene;
    scene.mesh = icosphere(frequency, 0.08);
    scene.camera.eye = {0.0, 0.8, 4.0};
    scene.camera.lookat = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.focal = glm::length(scene.camera.eye);
    scene.camera.sensor_height = scene.camera.sensor_width = 2.7;
    scene.image.rows = scene.image.columns = rows;
    three_lights(scene, glm::dvec3(0.0), 2.0 * std::sqrt(3.0));
    scene.mesh.normals = calculate_normals(scene.mesh);
    return named;
}

void three_lights(Scene& scene, const glm::dvec3& centre, double diagonal) {
    scene.lights = {
        {centre + diagonal * glm::dvec3(1.5, 1.5, 2.0), {0.8f, 0.75f, 0.7f}},
        {centre + diagonal * glm::dvec3(-2.0, 0.5, 1.0), {0.2f, 0.3f, 0.6f}},
        {centre + diagonal * glm::dvec3(0.3, -2.0, -1.0), {0.5f, 0.15f, 0.1f}},
    };
    scene.ambient = glm::vec3(0.2f);
    scene.material.ka = glm::vec3(0.1f);
    scene.material.kd = glm::vec3(0.8f);
    scene.material.ks = glm::vec3(0.5f);
    scene.material.n = 16.0f;
    scene.image.background = glm::vec3(0.05f, 0.06f, 0.09f);
    scene.lighting = Lighting::full();
}

std::vector<PointLight> lights_around(const Scene& scene, int count) {
    const glm::dvec3 centre = scene.camera.lookat;
    const glm::dvec3 view = scene.camera.eye - centre;
    const double reach = 0.8 * glm::length(view);
    const glm::dvec3 back = glm::normalize(view);
    const glm::dvec3 side = glm::normalize(glm::cross(scene.camera.up, back));
    const glm::dvec3 up = glm::cross(back, side);
    std::vector<PointLight> lights;
    for (int k = 0; k < count; ++k) {
        // On a cone around the view direction, so every light reaches the visible side.
        const double angle = 2.0 * kPi * (k + 0.25) / std::max(count, 1);
        const glm::dvec3 direction = glm::normalize(back + 0.8 * (std::cos(angle) * side + std::sin(angle) * up));
        const float warm = 0.5f + 0.1f * static_cast<float>(k % 3);
        lights.push_back({centre + reach * direction, glm::vec3(warm, 0.55f, 0.6f) / static_cast<float>(std::max(count, 1))});
    }
    return lights;
}

}  // namespace phongrast::support
