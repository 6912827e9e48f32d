#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "api_checks.hpp"
#include "finite.hpp"
#include "normals_scratch.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast {
namespace detail {
namespace {

/// body(i) for i in [0, count), with poll() (when given) before each block of
/// indices: one test per block, so a render without progress reports pays nothing per element.
template <typename Body>
void for_each_polling(std::size_t count, const std::function<void()>& poll, const Body& body) {
    constexpr std::size_t kPollEvery = 16384;
    for (std::size_t begin = 0; begin < count; begin += kPollEvery) {
        if (poll) poll();
        const std::size_t end = std::min(count, begin + kPollEvery);
        for (std::size_t i = begin; i < end; ++i) body(i);
    }
}

}  // namespace

void calculate_normals_into(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles,
                            NormalsScratch& scratch, std::vector<glm::vec3>& normals,
                            const std::function<void()>& poll) {
    std::vector<glm::dvec3>& sums = scratch.sums;
    sums.assign(positions.size(), glm::dvec3(0.0));
    // For the fallback: each vertex's largest adjacent face (twice its area) and unit normal.
    std::vector<double>& largest_area = scratch.largest_area;
    largest_area.assign(positions.size(), 0.0);
    std::vector<glm::dvec3>& largest_face_normal = scratch.largest_face_normal;
    largest_face_normal.assign(positions.size(), glm::dvec3(0.0));

    for_each_polling(triangles.size(), poll, [&](std::size_t t) {
        const Triangle& triangle = triangles[t];
        const glm::dvec3& a = positions[triangle[0]];
        const glm::dvec3& b = positions[triangle[1]];
        const glm::dvec3& c = positions[triangle[2]];
        // Edges from the first vertex keep the cross product small relative to
        // the coordinates for meshes far from the origin.
        const glm::dvec3 face = glm::cross(b - a, c - a);
        if (!detail::all_finite(face)) return;
        const double twice_area = glm::length(face);
        for (std::uint32_t vertex : triangle) {
            sums[vertex] += face;
            if (twice_area > largest_area[vertex]) {
                largest_area[vertex] = twice_area;
                largest_face_normal[vertex] = face;
            }
        }
    });

    normals.resize(positions.size());
    for_each_polling(positions.size(), poll, [&](std::size_t vertex) {
        glm::dvec3 normal = safe_normalize<double>(sums[vertex]);
        // A sum that is tiny relative to its largest face means opposite faces
        // cancelled (two-sided sheet): its direction is rounding noise.
        const double sum_length = glm::length(sums[vertex]);
        if (normal == glm::dvec3(0.0) || !(sum_length > 1e-12 * largest_area[vertex])) {
            normal = safe_normalize<double>(largest_face_normal[vertex]);
        }
        normals[vertex] = glm::vec3(normal);
    });
}

bool has_zero_normal(const std::vector<glm::vec3>& normals) {
    for (const glm::vec3& normal : normals) {
        if (normal == glm::vec3(0.0f)) return true;
    }
    return false;
}

void keep_given_normals(const std::vector<glm::vec3>& given, std::vector<glm::vec3>& computed) {
    for (std::size_t i = 0; i < given.size(); ++i) {
        if (given[i] != glm::vec3(0.0f)) computed[i] = given[i];
    }
}

}  // namespace detail

std::vector<glm::vec3> calculate_normals(const std::vector<glm::dvec3>& positions,
                                         const std::vector<Triangle>& triangles) {
    // Public entry: the indices come from the caller, unchecked (the renderer's
    // own calls come after validate_mesh).
    detail::validate_triangle_indices(triangles, positions.size(), "triangles");
    detail::NormalsScratch scratch;
    std::vector<glm::vec3> normals;
    detail::calculate_normals_into(positions, triangles, scratch, normals);
    return normals;
}

std::vector<glm::vec3> calculate_normals(const Mesh& mesh) {
    return calculate_normals(mesh.positions, mesh.triangles);
}

}  // namespace phongrast
