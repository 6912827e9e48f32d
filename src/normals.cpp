#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "normals_scratch.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast {
namespace {

bool is_finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Unit vector of v in double, or zero when v is zero or not finite. Scaling by
// the largest component keeps tiny meshes (1e-6 units) from underflowing.
glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double largest = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
    if (!(largest > 0.0) || !std::isfinite(largest)) return glm::dvec3(0.0);
    const glm::dvec3 scaled = v / largest;
    return scaled / std::sqrt(glm::dot(scaled, scaled));
}

}  // namespace

namespace detail {

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

    constexpr std::size_t kPollEvery = 16384;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        if (poll && t % kPollEvery == 0) poll();
        const Triangle& triangle = triangles[t];
        const glm::dvec3& a = positions[triangle[0]];
        const glm::dvec3& b = positions[triangle[1]];
        const glm::dvec3& c = positions[triangle[2]];
        // Edges from the first vertex keep the cross product small relative to
        // the coordinates for meshes far from the origin.
        const glm::dvec3 face = glm::cross(b - a, c - a);
        if (!is_finite(face)) continue;
        const double twice_area = glm::length(face);
        for (std::uint32_t vertex : triangle) {
            sums[vertex] += face;
            if (twice_area > largest_area[vertex]) {
                largest_area[vertex] = twice_area;
                largest_face_normal[vertex] = face;
            }
        }
    }

    normals.resize(positions.size());
    for (std::size_t vertex = 0; vertex < positions.size(); ++vertex) {
        if (poll && vertex % kPollEvery == 0) poll();
        glm::dvec3 normal = unit_or_zero(sums[vertex]);
        // A sum that is tiny relative to its largest face means opposite faces
        // cancelled (two-sided sheet): its direction is rounding noise.
        const double sum_length = glm::length(sums[vertex]);
        if (normal == glm::dvec3(0.0) || !(sum_length > 1e-12 * largest_area[vertex])) {
            normal = unit_or_zero(largest_face_normal[vertex]);
        }
        normals[vertex] = glm::vec3(normal);
    }
}

}  // namespace detail

std::vector<glm::vec3> calculate_normals(const std::vector<glm::dvec3>& positions,
                                         const std::vector<Triangle>& triangles) {
    detail::NormalsScratch scratch;
    std::vector<glm::vec3> normals;
    detail::calculate_normals_into(positions, triangles, scratch, normals);
    return normals;
}

std::vector<glm::vec3> calculate_normals(const Mesh& mesh) {
    return calculate_normals(mesh.positions, mesh.triangles);
}

void validate_mesh(const Mesh& mesh) {
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (!is_finite(mesh.positions[i])) {
            throw std::invalid_argument("mesh: position of vertex " + std::to_string(i) +
                                        " is not finite");
        }
    }
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.colors.size()) +
                                    " colours for " + std::to_string(mesh.positions.size()) +
                                    " vertices (expected one per vertex, or none)");
    }
    for (std::size_t i = 0; i < mesh.colors.size(); ++i) {
        const glm::vec3& c = mesh.colors[i];
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            throw std::invalid_argument("mesh: colour of vertex " + std::to_string(i) +
                                        " is not finite");
        }
    }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.normals.size()) +
                                    " normals for " + std::to_string(mesh.positions.size()) +
                                    " vertices (expected one per vertex, or none)");
    }
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (std::uint32_t index : mesh.triangles[i]) {
            if (index >= mesh.positions.size()) {
                throw std::invalid_argument("mesh: triangle " + std::to_string(i) +
                                            " has vertex index " + std::to_string(index) +
                                            ", expected below " +
                                            std::to_string(mesh.positions.size()));
            }
        }
    }
}

}  // namespace phongrast
