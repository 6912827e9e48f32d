// Can back faces be seen? Only if the mesh has a boundary or the eye is inside it.
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "scene_analysis.hpp"

namespace phongrast::detail {
namespace {

// Two independent 64-bit mixes of a directed edge (splitmix64 finaliser).
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}
std::uint64_t edge_hash(std::uint32_t from, std::uint32_t to, std::uint64_t salt) {
    return mix((std::uint64_t(from) << 32 | to) ^ salt);
}

struct Sums {
    // Sum over directed edges of hash(a, b) - hash(b, a), modulo 2^64, for two salts.
    std::uint64_t edges[2] = {0, 0};
    double solid_angle = 0.0;  ///< signed solid angle of the surface seen from the eye
    double volume6 = 0.0;      ///< six times the signed enclosed volume (relative to the eye)
};

}  // namespace

// Closedness: a surface without boundary has, as a 1-chain, zero boundary:
// every directed edge a->b is cancelled by some b->a. The sums of a random
// hash over directed edges and over their reverses are then equal; an
// unmatched edge makes them differ except with probability about 2^-64 per
// salt (two salts are used). This is O(triangles) and parallel, unlike
// sorting the edges, so it costs ~1% of a render.
HiddenBackFaces find_hidden_back_faces(const Mesh& mesh, const glm::dvec3& eye) {
    if (mesh.triangles.empty()) return HiddenBackFaces::unknown;
    const Sums total = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 8192), Sums{},
        [&](const tbb::blocked_range<std::size_t>& range, Sums sums) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
                const Triangle& tri = mesh.triangles[t];
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
                    for (int s = 0; s < 2; ++s) {
                        const std::uint64_t salt = s == 0 ? 0x5851f42d4c957f2dull : 0x14057b7ef767814full;
                        sums.edges[s] += edge_hash(a, b, salt) - edge_hash(b, a, salt);
                    }
                }
                // Van Oosterom-Strackee solid angle of the triangle seen from the eye.
                const glm::dvec3 r1 = mesh.positions[tri[0]] - eye;
                const glm::dvec3 r2 = mesh.positions[tri[1]] - eye;
                const glm::dvec3 r3 = mesh.positions[tri[2]] - eye;
                const double l1 = glm::length(r1), l2 = glm::length(r2), l3 = glm::length(r3);
                const double triple = glm::dot(r1, glm::cross(r2, r3));
                const double denominator = l1 * l2 * l3 + glm::dot(r1, r2) * l3 + glm::dot(r1, r3) * l2 +
                                           glm::dot(r2, r3) * l1;
                sums.solid_angle += 2.0 * std::atan2(triple, denominator);
                sums.volume6 += triple;
            }
            return sums;
        },
        [](Sums a, const Sums& b) {
            a.edges[0] += b.edges[0];
            a.edges[1] += b.edges[1];
            a.solid_angle += b.solid_angle;
            a.volume6 += b.volume6;
            return a;
        });
    if (total.edges[0] != 0 || total.edges[1] != 0) return HiddenBackFaces::unknown;  // has a boundary
    // Winding number of the eye: 0 outside, +-1 (or more) inside. Anything not
    // clearly 0 (the eye on the surface, rounding) keeps every face.
    const double winding = total.solid_angle / (4.0 * M_PI);
    if (!std::isfinite(winding) || std::abs(winding) > 0.25) return HiddenBackFaces::unknown;
    // Orientation from the enclosed volume's sign (independent of where the eye is).
    if (!(std::abs(total.volume6) > 0.0) || !std::isfinite(total.volume6)) return HiddenBackFaces::unknown;
    return total.volume6 > 0.0 ? HiddenBackFaces::outward_oriented : HiddenBackFaces::inward_oriented;
}

}  // namespace phongrast::detail
