#include "scenes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

namespace llvmpipe_compare {
namespace {

// The regular icosahedron, faces counter-clockwise seen from outside.
constexpr double kGolden = 1.6180339887498948482;
const std::array<glm::dvec3, 12> kIcosahedronVertices = {{
    {-1, kGolden, 0}, {1, kGolden, 0}, {-1, -kGolden, 0}, {1, -kGolden, 0},
    {0, -1, kGolden}, {0, 1, kGolden}, {0, -1, -kGolden}, {0, 1, -kGolden},
    {kGolden, 0, -1}, {kGolden, 0, 1}, {-kGolden, 0, -1}, {-kGolden, 0, 1},
}};
const std::array<std::array<int, 3>, 20> kIcosahedronFaces = {{
    {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
    {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
    {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
    {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1},
}};

/// A grid point named by the icosahedron corners it mixes and their integer
/// weights, sorted by corner: the same point on an edge shared by two faces
/// gets the same key, which is how the faces are welded.
std::uint64_t grid_key(std::array<std::pair<int, int>, 3> corner_weights) {
    std::sort(corner_weights.begin(), corner_weights.end());
    std::uint64_t key = 0;
    for (const auto& [corner, weight] : corner_weights) {
        if (weight == 0) continue;
        key = (key << 14) | (std::uint64_t(corner) << 10) | std::uint64_t(weight);
    }
    return key;
}

}  // namespace

phongrast::Mesh colored_icosphere(int frequency, double bump) {
    if (frequency < 1 || frequency > 1023) throw std::invalid_argument("frequency: expected 1..1023");
    phongrast::Mesh mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> index_of;
    const std::size_t vertices_expected = 10 * std::size_t(frequency) * std::size_t(frequency) + 2;
    index_of.reserve(vertices_expected);
    mesh.positions.reserve(vertices_expected);
    mesh.colors.reserve(vertices_expected);
    mesh.triangles.reserve(20 * std::size_t(frequency) * std::size_t(frequency));

    for (const auto& face : kIcosahedronFaces) {
        // Grid point (i, j): weight i on the face's second corner, j on its third.
        const auto vertex = [&](int i, int j) {
            const int weights[3] = {frequency - i - j, i, j};
            const std::uint64_t key =
                grid_key({{{face[0], weights[0]}, {face[1], weights[1]}, {face[2], weights[2]}}});
            const auto [it, inserted] = index_of.try_emplace(key, std::uint32_t(mesh.positions.size()));
            if (inserted) {
                glm::dvec3 mix(0.0);
                for (int k = 0; k < 3; ++k) mix += double(weights[k]) * kIcosahedronVertices[face[k]];
                const glm::dvec3 d = glm::normalize(mix);
                const double radius =
                    1.0 + bump * std::sin(5.0 * d.x + 1.0) * std::cos(4.0 * d.y) * std::sin(3.0 * d.z + 0.5);
                mesh.positions.push_back(radius * d);
                mesh.colors.push_back(glm::vec3(0.55 + 0.4 * std::sin(3.0 * d.x + 0.3),
                                                0.55 + 0.4 * std::sin(3.0 * d.y + 2.0),
                                                0.55 + 0.4 * std::sin(3.0 * d.z + 4.0)));
            }
            return it->second;
        };
        for (int i = 0; i < frequency; ++i) {
            for (int j = 0; i + j < frequency; ++j) {
                mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)});
                if (i + j + 1 < frequency) {
                    mesh.triangles.push_back({vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
                }
            }
        }
    }
    return mesh;
}

void light_scene(phongrast::Scene& scene, const glm::dvec3& centre, double diagonal) {
    // A warm key light up-right-front, a blue fill from the left and a dim red
    // rim light from below-behind: three lights of different colours, so a
    // mistake in one light's term shows up as a hue shift.
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
    scene.lighting = phongrast::Lighting::full();
}

NamedScene icosphere_scene(const std::string& name, int frequency, int rows) {
    NamedScene named;
    named.name = name;
    phongrast::Scene& scene = named.scene;
    scene.mesh = colored_icosphere(frequency, 0.08);
    scene.camera.eye = {0.0, 0.8, 4.0};
    scene.camera.lookat = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.focal = glm::length(scene.camera.eye);
    scene.camera.sensor_height = scene.camera.sensor_width = 2.7;
    scene.image.rows = scene.image.columns = rows;
    light_scene(scene, glm::dvec3(0.0), 2.0 * std::sqrt(3.0));
    compute_normals(scene);
    return named;
}

void compute_normals(phongrast::Scene& scene) {
    scene.mesh.normals = phongrast::calculate_normals(scene.mesh);
}

}  // namespace llvmpipe_compare
