// Small procedural meshes shared by the tests.
#ifndef PHONGRAST_TESTS_TEST_MESHES_HPP
#define PHONGRAST_TESTS_TEST_MESHES_HPP

#include <cmath>

#include "phongrast/mesh.hpp"

namespace test_meshes {

/// Unit cube [0,1]^3, 8 vertices, 12 outward (counter-clockwise) triangles.
inline phongrast::Mesh unit_cube() {
    phongrast::Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    // Quads as seen from outside, counter-clockwise.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
        mesh.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
    }
    return mesh;
}

/// Unit cube with a centre vertex on each face (vertices 8..13) and each face
/// split into four triangles around it: every corner sees its three faces equally.
inline phongrast::Mesh symmetric_cube() {
    phongrast::Mesh mesh = unit_cube();
    mesh.triangles.clear();
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        glm::dvec3 centre(0.0);
        for (int k = 0; k < 4; ++k) centre += mesh.positions[q[k]] / 4.0;
        const auto c = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(centre);
        for (int k = 0; k < 4; ++k) {
            mesh.triangles.push_back({std::uint32_t(q[k]), std::uint32_t(q[(k + 1) % 4]), c});
        }
    }
    return mesh;
}

/// Latitude-longitude sphere of the given radius around the origin, outward faces.
inline phongrast::Mesh uv_sphere(int stacks, int slices, double radius) {
    phongrast::Mesh mesh;
    const double pi = 3.14159265358979323846;
    mesh.positions.push_back({0, radius, 0});
    for (int i = 1; i < stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * pi * j / slices;
            mesh.positions.push_back(
                {radius * std::sin(theta) * std::cos(phi), radius * std::cos(theta), -radius * std::sin(theta) * std::sin(phi)});
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

/// Torus around the y axis (major radius R, minor r), outward faces: closed, genus 1.
inline phongrast::Mesh torus(int rings, int sides, double major, double minor) {
    phongrast::Mesh mesh;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < rings; ++i) {
        const double u = 2 * pi * i / rings;
        for (int j = 0; j < sides; ++j) {
            const double v = 2 * pi * j / sides;
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

}  // namespace test_meshes

#endif  // PHONGRAST_TESTS_TEST_MESHES_HPP

#include <sstream>
#include <catch2/catch.hpp>

namespace Catch {
template <>
struct StringMaker<glm::vec3> {
    static std::string convert(const glm::vec3& v) {
        std::ostringstream out;
        out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
        return out.str();
    }
};
}  // namespace Catch
