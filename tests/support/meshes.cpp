#include "meshes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace phongrast::support {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The cube's faces as quads seen from outside, counter-clockwise.
constexpr int kCubeQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

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

/// Where each face's grid points went: points on the icosahedron's edges are
/// shared with the neighbouring face (looked up by grid_key), points inside a
/// face belong to it alone (a plain array, reused from face to face, so the
/// hash table stays small even at millions of vertices).
struct IcosphereIndex {
    std::unordered_map<std::uint64_t, std::uint32_t> edge_points;
    std::vector<std::uint32_t> face_points;  ///< per grid point (i, j) of the current face
};

constexpr std::uint32_t kNoVertex = ~std::uint32_t(0);

/// Cuts one icosahedron face into frequency^2 triangles, adding each new grid point once.
void add_icosahedron_face(Mesh& mesh, IcosphereIndex& index, const std::array<int, 3>& face, int frequency,
                          double bump) {
    index.face_points.assign(std::size_t(frequency + 1) * std::size_t(frequency + 2) / 2, kNoVertex);
    // Grid point (i, j): weight i on the face's second corner, j on its third; row i holds j = 0..frequency - i.
    const auto vertex = [&](int i, int j) {
        std::uint32_t& slot = index.face_points[std::size_t(i) * std::size_t(frequency + 1) -
                                                std::size_t(i) * std::size_t(i - 1) / 2 + std::size_t(j)];
        if (slot != kNoVertex) return slot;
        const int weights[3] = {frequency - i - j, i, j};
        slot = std::uint32_t(mesh.positions.size());
        if (weights[0] == 0 || i == 0 || j == 0) {
            const std::uint64_t key = grid_key({{{face[0], weights[0]}, {face[1], weights[1]}, {face[2], weights[2]}}});
            const auto [it, inserted] = index.edge_points.try_emplace(key, slot);
            if (!inserted) return slot = it->second;
        }
        glm::dvec3 mix(0.0);
        for (int k = 0; k < 3; ++k) mix += double(weights[k]) * kIcosahedronVertices[face[k]];
        const glm::dvec3 d = glm::normalize(mix);
        const double radius = 1.0 + bump * std::sin(5.0 * d.x + 1.0) * std::cos(4.0 * d.y) * std::sin(3.0 * d.z + 0.5);
        mesh.positions.push_back(radius * d);
        mesh.colors.push_back(glm::vec3(0.55 + 0.4 * std::sin(3.0 * d.x + 0.3), 0.55 + 0.4 * std::sin(3.0 * d.y + 2.0),
                                        0.55 + 0.4 * std::sin(3.0 * d.z + 4.0)));
        return slot;
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

}  // namespace

Mesh unit_cube() {
    Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    for (const auto& q : kCubeQuads) {
        mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
        mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
    }
    return mesh;
}

Mesh symmetric_cube() {
    Mesh mesh = unit_cube();
    mesh.triangles.clear();
    for (const auto& q : kCubeQuads) {
        glm::dvec3 centre(0.0);
        for (int k = 0; k < 4; ++k) centre += mesh.positions[q[k]] / 4.0;
        const auto c = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(centre);
        for (int k = 0; k < 4; ++k) mesh.triangles.push_back({std::uint32_t(q[k]), std::uint32_t(q[(k + 1) % 4]), c});
    }
    return mesh;
}

Mesh uv_sphere(int stacks, int slices, double radius) {
    Mesh mesh;
    mesh.positions.push_back({0, radius, 0});
    for (int i = 1; i < stacks; ++i) {
        const double theta = kPi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * kPi * j / slices;
            mesh.positions.push_back({radius * std::sin(theta) * std::cos(phi), radius * std::cos(theta),
                                      -radius * std::sin(theta) * std::sin(phi)});
        }
    }
    mesh.positions.push_back({0, -radius, 0});
    const auto ring = [slices](int i, int j) { return std::uint32_t(1 + (i - 1) * slices + (j % slices)); };
    const auto bottom = std::uint32_t(mesh.positions.size() - 1);
    for (int j = 0; j < slices; ++j) {
        mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < stacks; ++i) {
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        mesh.triangles.push_back({ring(stacks - 1, j), bottom, ring(stacks - 1, j + 1)});
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

Mesh icosphere(int frequency, double bump) {
    if (frequency < 1 || frequency > 1023) throw std::invalid_argument("icosphere: frequency: expected 1..1023");
    Mesh mesh;
    IcosphereIndex index;
    index.edge_points.reserve(30 * std::size_t(frequency) + 12);  // the icosahedron's 30 edges and 12 corners
    const std::size_t vertices = 10 * std::size_t(frequency) * std::size_t(frequency) + 2;
    mesh.positions.reserve(vertices);
    mesh.colors.reserve(vertices);
    mesh.triangles.reserve(20 * std::size_t(frequency) * std::size_t(frequency));
    for (const auto& face : kIcosahedronFaces) add_icosahedron_face(mesh, index, face, frequency, bump);
    return mesh;
}

void color_by_position(Mesh& mesh) {
    if (mesh.positions.empty()) return;
    glm::dvec3 low = mesh.positions.front(), high = low;
    for (const glm::dvec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 extent = glm::max(high - low, glm::dvec3(1e-300));
    mesh.colors.clear();
    for (const glm::dvec3& p : mesh.positions) {
        const glm::dvec3 t = (p - low) / extent;  // in [0, 1] per axis
        mesh.colors.push_back(glm::vec3(0.35 + 0.6 * t.x, 0.35 + 0.6 * t.y, 0.95 - 0.6 * t.z));
    }
}

Mesh grid_plane(int quads, double dz_dx, double dz_dy) {
    Mesh mesh;
    for (int j = 0; j <= quads; ++j) {
        for (int i = 0; i <= quads; ++i) {
            const double x = -1.0 + 2.0 * i / quads, y = -1.0 + 2.0 * j / quads;
            mesh.positions.push_back({x, y, dz_dx * x + dz_dy * y});
        }
    }
    const auto at = [quads](int i, int j) { return static_cast<std::uint32_t>(j * (quads + 1) + i); };
    for (int j = 0; j < quads; ++j) {
        for (int i = 0; i < quads; ++i) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

Mesh rotated_about_x(Mesh mesh, double degrees) {
    const double angle = degrees * kPi / 180.0, c = std::cos(angle), s = std::sin(angle);
    for (glm::dvec3& p : mesh.positions) p = {p.x, c * p.y - s * p.z, s * p.y + c * p.z};
    for (glm::vec3& n : mesh.normals) {
        n = glm::vec3(n.x, float(c * n.y - s * n.z), float(s * n.y + c * n.z));
    }
    return mesh;
}

}  // namespace phongrast::support
