#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "api_checks.hpp"
#include "finite.hpp"
#include "normals.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"
#include "prefetch.hpp"
#include "resize_polling.hpp"
#include "same_array.hpp"

namespace phongrast {
namespace detail {
namespace {

constexpr std::size_t kBlock = 16384;

/// Every face's cross product and its length, twice the face's area (w = -1:
/// not finite, skipped), in parallel over triangles: scratch.faces.
const FrameVector<glm::dvec4>& compute_faces(const std::vector<glm::dvec3>& positions,
                                             const std::vector<Triangle>& triangles, NormalsScratch& scratch,
                                             const std::function<void()>& poll) {
    FrameVector<glm::dvec4>& faces = scratch.faces;
    resize_polling(faces, triangles.size(), poll);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), kBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
            const Triangle& triangle = triangles[t];
            const glm::dvec3& a = positions[triangle[0]];
            const glm::dvec3& b = positions[triangle[1]];
            const glm::dvec3& c = positions[triangle[2]];
            // Edges from the first vertex keep the cross product small relative to
            // the coordinates for meshes far from the origin.
            const glm::dvec3 face = glm::cross(b - a, c - a);
            faces[t] = detail::all_finite(face) ? glm::dvec4(face, glm::length(face)) : glm::dvec4(0.0, 0.0, 0.0, -1.0);
        }
    });
    if (poll) poll();
    return faces;
}

/// One face added to a vertex: its sum, and its largest face for the fallback.
/// Both ways of computing normals add through here or add_face_selected(),
/// which do the same operations on the same values: in the same order, the
/// same bits.
inline void add_face(const glm::dvec4& face, glm::dvec3& sum, double& largest_area, glm::dvec3& largest_face) {
    const double twice_area = face.w;
    if (twice_area < 0.0) return;  // not finite
    sum += glm::dvec3(face);
    if (twice_area > largest_area) {
        largest_area = twice_area;
        largest_face = glm::dvec3(face);
    }
}

/// add_face() without branches: the sum and the largest face selected, not
/// jumped over. For the corner lists' walk, where each vertex adds its six or
/// so faces in a row and the comparison's mispredictions cost more than the
/// selects (the pass over triangles, whose sums live in memory, is faster
/// with the branches).
inline void add_face_selected(const glm::dvec4& face, glm::dvec3& sum, double& largest_area, glm::dvec3& largest_face) {
    const double twice_area = face.w;
    const bool finite = twice_area >= 0.0;  // add_face()'s "not < 0": w is never NaN
    const glm::dvec3 added = sum + glm::dvec3(face);
    sum.x = finite ? added.x : sum.x;
    sum.y = finite ? added.y : sum.y;
    sum.z = finite ? added.z : sum.z;
    const bool larger = finite & (twice_area > largest_area);
    largest_area = larger ? twice_area : largest_area;
    largest_face.x = larger ? face.x : largest_face.x;
    largest_face.y = larger ? face.y : largest_face.y;
    largest_face.z = larger ? face.z : largest_face.z;
}

/// Corners ahead whose face the corner lists' walk prefetches: a vertex's
/// faces lie near each other, but a list often reaches back to faces far
/// behind (a neighbouring cell of the spatial sort).
constexpr std::size_t kCornersAhead = 32;

/// A vertex's normal from its sum of faces.
inline glm::vec3 vertex_normal(const glm::dvec3& sum, double largest_area, const glm::dvec3& largest_face) {
    glm::dvec3 normal = safe_normalize<double>(sum);
    // A sum that is tiny relative to its largest face means opposite faces
    // cancelled (two-sided sheet): its direction is rounding noise.
    const double sum_length = glm::length(sum);
    if (normal == glm::dvec3(0.0) || !(sum_length > 1e-12 * largest_area)) {
        normal = safe_normalize<double>(largest_face);
    }
    return glm::vec3(normal);
}

}  // namespace

// In parallel, and the same bits as one pass over the triangles in order:
// each vertex's sums see its faces in the same order (ascending triangle,
// then corner), whichever task or thread computes it. First every face's
// cross product and length (in parallel over triangles); then the vertices
// are split into as many ranges as the arena has threads, and each range's
// task walks all triangles in order, adding only to its own vertices (a
// sequential read of the index list per task; the scattered additions, the
// cost on a mesh in a random order, are shared out); then each vertex is
// normalised (in parallel).
void calculate_normals_into(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles,
                            NormalsScratch& scratch, std::vector<glm::vec3>& normals,
                            const std::function<void()>& poll) {
    const std::size_t vertex_count = positions.size(), triangle_count = triangles.size();
    // New scratch memory is filled with polls in between (resize_polling.hpp).
    FrameVector<glm::dvec3>& sums = scratch.sums;
    assign_polling(sums, vertex_count, glm::dvec3(0.0), poll);
    // For the fallback: each vertex's largest adjacent face (twice its area) and unit normal.
    FrameVector<double>& largest_area = scratch.largest_area;
    assign_polling(largest_area, vertex_count, 0.0, poll);
    FrameVector<glm::dvec3>& largest_face_normal = scratch.largest_face_normal;
    assign_polling(largest_face_normal, vertex_count, glm::dvec3(0.0), poll);
    if (poll) poll();

    const FrameVector<glm::dvec4>& faces = compute_faces(positions, triangles, scratch, poll);

    const std::size_t ranges = std::max<std::size_t>(
        1, std::min<std::size_t>(static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
                                 vertex_count / kBlock + 1));
    tbb::parallel_for(std::size_t(0), ranges, [&](std::size_t range) {
        const std::uint32_t first = static_cast<std::uint32_t>(range * vertex_count / ranges);
        const std::uint32_t end = static_cast<std::uint32_t>((range + 1) * vertex_count / ranges);
        for (std::size_t t = 0; t < triangle_count; ++t) {
            // Each task walks every triangle (100-200 ms for 300k under load):
            // poll inside, so a cancel (RenderCancelled from `poll`, on any
            // thread) does not wait for the walks to end.
            if (poll && t % kBlock == 0) poll();
            for (std::uint32_t vertex : triangles[t]) {
                if (vertex < first || vertex >= end) continue;
                add_face(faces[t], sums[vertex], largest_area[vertex], largest_face_normal[vertex]);
            }
        }
    });
    if (poll) poll();

    normals.resize(vertex_count);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertex_count, kBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t vertex = range.begin(); vertex != range.end(); ++vertex) {
            normals[vertex] = vertex_normal(sums[vertex], largest_area[vertex], largest_face_normal[vertex]);
        }
    });
}

// Each vertex adds its faces in the order `corners` lists them, the order in
// which the caller's mesh's one pass would add them: the same additions on
// the same values, so the same bits. The faces are computed over the
// renumbered triangles (local); each vertex then reads the faces of its
// neighbourhood.
bool calculate_normals_by_corners(const std::vector<glm::dvec3>& positions, const std::vector<Triangle>& triangles,
                                  const VertexCorners& corners, NormalsScratch& scratch,
                                  std::vector<glm::vec3>& normals, const std::function<void()>& poll) {
    const std::size_t vertex_count = positions.size(), triangle_count = triangles.size();
    if (triangle_count > kVertexCornersMaxTriangles || corners.first.size() != vertex_count + 1 ||
        corners.corners.size() != 3 * triangle_count || corners.first.back() != corners.corners.size()) {
        return false;
    }
    const FrameVector<glm::dvec4>& faces = compute_faces(positions, triangles, scratch, poll);
    resize_polling(normals, vertex_count, poll);
    const std::size_t corner_count = corners.corners.size();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertex_count, kBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t vertex = range.begin(); vertex != range.end(); ++vertex) {
            glm::dvec3 sum(0.0), largest_face(0.0);
            double largest_area = 0.0;
            const std::uint32_t end = corners.first[vertex + 1];
            for (std::uint32_t k = corners.first[vertex]; k < end; ++k) {
                if (k + kCornersAhead < corner_count) prefetch_address(&faces[corners.corners[k + kCornersAhead] >> 2]);
                add_face_selected(faces[corners.corners[k] >> 2], sum, largest_area, largest_face);
            }
            normals[vertex] = vertex_normal(sum, largest_area, largest_face);
        }
    });
    if (poll) poll();
    return true;
}

bool ComputedNormalsSource::matches(const Mesh& mesh) const {
    // Bytes, not values: -0.0 against 0.0 or a NaN payload recomputes, which is
    // never wrong; equal bytes give calculate_normals_into() equal inputs.
    return valid && same_array(positions, mesh.positions) && same_array(triangles, mesh.triangles);
}

void ComputedNormalsSource::remember(const Mesh& mesh) {
    valid = false;
    if (mesh.triangles.size() > kReusedNormalsMaxTriangles) {
        std::vector<glm::dvec3>().swap(positions);
        std::vector<Triangle>().swap(triangles);
        return;
    }
    positions.assign(mesh.positions.begin(), mesh.positions.end());
    triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    valid = true;
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

void keep_given_normals(const std::vector<glm::vec3>& given, const std::vector<std::uint32_t>& source,
                        std::vector<glm::vec3>& computed) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, computed.size(), kBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            const glm::vec3& normal = given[source[v]];
            if (normal != glm::vec3(0.0f)) computed[v] = normal;
        }
    });
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
