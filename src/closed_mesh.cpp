// Can back faces be seen? Only if the mesh has a boundary or the eye is inside it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "closed_mesh.hpp"

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
};

/// Union-find over vertex indices, to split a mesh into its connected parts.
class VertexComponents {
public:
    explicit VertexComponents(std::size_t count) : parent_(count) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
    }
    std::uint32_t find(std::uint32_t v) {
        while (parent_[v] != v) {
            parent_[v] = parent_[parent_[v]];  // path halving
            v = parent_[v];
        }
        return v;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::uint32_t> parent_;
};

/// Every connected part must enclose a volume clearly different from zero,
/// and all parts must be wound the same way. Returns +1 (all outward), -1
/// (all inward) or 0 (mixed, or some part encloses nothing -- a two-sided
/// sheet, whose volume is zero up to rounding).
int common_orientation(const Mesh& mesh) {
    VertexComponents components(mesh.positions.size());
    for (const Triangle& tri : mesh.triangles) {
        components.unite(tri[0], tri[1]);
        components.unite(tri[1], tri[2]);
    }
    std::vector<double> volume6(mesh.positions.size(), 0.0), magnitude(mesh.positions.size(), 0.0);
    for (const Triangle& tri : mesh.triangles) {
        // Relative to the part's first vertex, so a far-away mesh loses no digits.
        const std::uint32_t root = components.find(tri[0]);
        const glm::dvec3& origin = mesh.positions[root];
        const double triple = glm::dot(mesh.positions[tri[0]] - origin,
                                       glm::cross(mesh.positions[tri[1]] - origin, mesh.positions[tri[2]] - origin));
        volume6[root] += triple;
        magnitude[root] += std::abs(triple);
    }
    int orientation = 0;
    for (std::size_t v = 0; v < volume6.size(); ++v) {
        if (magnitude[v] == 0.0) continue;  // not a root, or a part of zero-volume triangles only
        // A closed part's volume is a sum of cancelling terms; anything within
        // 1e-9 of their magnitudes is rounding, not an enclosed volume.
        if (!std::isfinite(volume6[v]) || !(std::abs(volume6[v]) > 1e-9 * magnitude[v])) return 0;
        const int sign = volume6[v] > 0.0 ? 1 : -1;
        if (orientation != 0 && sign != orientation) return 0;
        orientation = sign;
    }
    return orientation;
}

}  // namespace

// Closedness: a surface without boundary has, as a 1-chain, zero boundary:
// every directed edge a->b is cancelled by some b->a. The sums of a random
// hash over directed edges and over their reverses are then equal; an
// unmatched edge makes them differ except with probability about 2^-64 per
// salt (two salts are used). This is O(triangles) and parallel, unlike
// sorting the edges; with the eye's solid angle and the per-part volumes it
// costs about 600 instructions per triangle (docs/performance.md, "Effect
// sets": about a third of an 82k-triangle Gouraud render), paid on every
// render that asks to cull.
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
            }
            return sums;
        },
        [](Sums a, const Sums& b) {
            a.edges[0] += b.edges[0];
            a.edges[1] += b.edges[1];
            a.solid_angle += b.solid_angle;
            return a;
        });
    if (total.edges[0] != 0 || total.edges[1] != 0) return HiddenBackFaces::unknown;  // has a boundary
    // Winding number of the eye: 0 outside, +-1 (or more) inside. Anything not
    // clearly 0 (the eye on the surface, rounding) keeps every face. With every
    // part wound the same way (checked next), each part's winding number has
    // the same sign, so a total of 0 means the eye is outside every part.
    const double winding = total.solid_angle / (4.0 * M_PI);
    if (!std::isfinite(winding) || std::abs(winding) > 0.25) return HiddenBackFaces::unknown;
    // Orientation from the sign of each part's enclosed volume (independent of the eye).
    switch (common_orientation(mesh)) {
        case 1: return HiddenBackFaces::outward_oriented;
        case -1: return HiddenBackFaces::inward_oriented;
        default: return HiddenBackFaces::unknown;
    }
}

}  // namespace phongrast::detail
