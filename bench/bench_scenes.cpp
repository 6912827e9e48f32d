#include "bench_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace phongrast_bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

using phongrast::Mesh;
using phongrast::Triangle;

// Index of the vertex halfway along edge (a, b), created once per edge so
// that neighbouring triangles share it and the surface stays closed.
std::uint32_t midpoint(Mesh& mesh, std::unordered_map<std::uint64_t, std::uint32_t>& cache, std::uint32_t a,
                       std::uint32_t b) {
    const std::uint64_t key = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
    const auto found = cache.find(key);
    if (found != cache.end()) return found->second;
    const auto index = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
    cache.emplace(key, index);
    return index;
}

}  // namespace

Mesh icosphere(int levels) {
    Mesh mesh;
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const glm::dvec3 corners[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (const glm::dvec3& c : corners) mesh.positions.push_back(glm::normalize(c));
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::unordered_map<std::uint64_t, std::uint32_t> cache;
        std::vector<Triangle> finer;
        finer.reserve(mesh.triangles.size() * 4);
        for (const Triangle& tri : mesh.triangles) {
            const std::uint32_t ab = midpoint(mesh, cache, tri[0], tri[1]);
            const std::uint32_t bc = midpoint(mesh, cache, tri[1], tri[2]);
            const std::uint32_t ca = midpoint(mesh, cache, tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    for (const glm::dvec3& p : mesh.positions) {
        mesh.colors.push_back(glm::vec3(0.55 + 0.45 * p.x, 0.55 + 0.45 * p.y, 0.55 + 0.45 * std::sin(3.0 * p.z)));
    }
    return mesh;
}

Mesh torus(int rings, int sides, double major, double minor) {
    Mesh mesh;
    for (int i = 0; i < rings; ++i) {
        const double u = 2 * kPi * i / rings;
        for (int j = 0; j < sides; ++j) {
            const double v = 2 * kPi * j / sides;
            const double radius = major + minor * std::cos(v);
            mesh.positions.push_back({radius * std::cos(u), minor * std::sin(v), -radius * std::sin(u)});
            mesh.colors.push_back(glm::vec3(0.5 + 0.5 * std::cos(u), 0.5 + 0.5 * std::sin(v), 0.6f));
        }
    }
    const auto at = [rings, sides](int i, int j) {
        return std::uint32_t(((i + rings) % rings) * sides + ((j + sides) % sides));
    };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

phongrast::Scene framed_scene(Mesh mesh, int rows, int columns, ViewAxis axis) {
    glm::dvec3 low(mesh.positions.front()), high(mesh.positions.front());
    for (const glm::dvec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 centre = (low + high) / 2.0;
    const double diagonal = glm::length(high - low);
    phongrast::Scene scene;
    scene.mesh = std::move(mesh);
    const double away = axis == ViewAxis::plus_z ? 1.0 : -1.0;
    scene.camera.eye = centre + diagonal * glm::dvec3(0.0, 0.6, 2.5 * away);
    scene.camera.lookat = centre;
    scene.camera.up = {0, 1, 0};
    // The mesh fits in a sphere of radius diagonal / 2; show 1.1 times that.
    const double distance = glm::length(scene.camera.eye - centre);
    scene.camera.focal = 1.0;
    scene.camera.sensor_height = 1.1 * diagonal / distance;
    scene.camera.sensor_width = scene.camera.sensor_height * columns / rows;
    scene.image = {rows, columns, {0.05f, 0.05f, 0.1f}};
    scene.material = phongrast::PhongMaterial{};  // ka 0.1, kd 0.8, ks 1, n 1: the contract's example
    scene.material.n = 16.0f;                     // a visible highlight; pow() costs the same for any n
    scene.ambient = glm::vec3(0.2f);
    scene.shader = phongrast::Shader::phong;
    scene.lighting = phongrast::Lighting::full();
    scene.lights = lights_around(scene, 2);
    return scene;
}

std::vector<phongrast::PointLight> lights_around(const phongrast::Scene& scene, int count) {
    const glm::dvec3 centre = scene.camera.lookat;
    const glm::dvec3 view = scene.camera.eye - centre;
    const double reach = 0.8 * glm::length(view);
    const glm::dvec3 back = glm::normalize(view);
    const glm::dvec3 side = glm::normalize(glm::cross(scene.camera.up, back));
    const glm::dvec3 up = glm::cross(back, side);
    std::vector<phongrast::PointLight> lights;
    for (int k = 0; k < count; ++k) {
        // On a cone around the view direction, so every light reaches the visible side.
        const double angle = 2.0 * kPi * (k + 0.25) / std::max(count, 1);
        const glm::dvec3 direction = glm::normalize(back + 0.8 * (std::cos(angle) * side + std::sin(angle) * up));
        const float warm = 0.5f + 0.1f * static_cast<float>(k % 3);
        lights.push_back({centre + reach * direction, glm::vec3(warm, 0.55f, 0.6f) / static_cast<float>(std::max(count, 1))});
    }
    return lights;
}

std::vector<EffectVariant> effect_variants() {
    using phongrast::Lighting;
    return {
        {"ambient", Lighting::only_ambient(), false, false},
        {"diffuse", Lighting::only_diffuse(), false, false},
        {"specular", Lighting::only_specular(), false, false},
        {"full", Lighting::full(), false, false},
        {"full-kd0", Lighting::full(), true, false},
        {"full-ks0", Lighting::full(), false, true},
    };
}

phongrast::Scene with_effect(phongrast::Scene scene, const EffectVariant& variant) {
    scene.lighting = variant.lighting;
    if (variant.zero_kd) scene.material.kd = glm::vec3(0.0f);
    if (variant.zero_ks) scene.material.ks = glm::vec3(0.0f);
    return scene;
}

}  // namespace phongrast_bench
