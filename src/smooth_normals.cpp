#include "phongrast/smooth_normals.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "finite.hpp"
#include "phongrast/lighting.hpp"

namespace phongrast {
namespace {

constexpr double pi = 3.14159265358979323846;

struct PositionKey {
    double x, y, z;
    bool operator==(const PositionKey& other) const { return x == other.x && y == other.y && z == other.z; }
};

struct PositionHash {
    std::size_t operator()(const PositionKey& key) const {
        const std::hash<double> hash;
        std::size_t h = hash(key.x);
        h ^= hash(key.y) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h ^= hash(key.z) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        return h;
    }
};

// The group each vertex pools its faces in: its own index, or one id per
// distinct position (adding 0.0 turns -0.0 into 0.0, so both weld).
std::vector<std::uint32_t> sharing_groups(const Mesh& mesh, NormalSharing sharing) {
    std::vector<std::uint32_t> group(mesh.positions.size());
    if (sharing == NormalSharing::vertex_index) {
        for (std::size_t v = 0; v < group.size(); ++v) group[v] = static_cast<std::uint32_t>(v);
        return group;
    }
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> ids;
    ids.reserve(mesh.positions.size());
    for (std::size_t v = 0; v < group.size(); ++v) {
        const glm::dvec3& p = mesh.positions[v];
        const PositionKey key{p.x + 0.0, p.y + 0.0, p.z + 0.0};
        group[v] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    return group;
}

// The faces touching each group, in triangle order, each face once per group
// (compressed rows: the faces of group g are faces[offsets[g]..offsets[g+1])).
struct GroupFaces {
    std::vector<std::size_t> offsets;
    std::vector<std::uint32_t> faces;
};

GroupFaces faces_per_group(const Mesh& mesh, const std::vector<std::uint32_t>& group, std::size_t groups) {
    GroupFaces result;
    result.offsets.assign(groups + 1, 0);
    auto for_each_distinct_group = [&](const Triangle& t, auto&& visit) {
        const std::uint32_t g0 = group[t[0]], g1 = group[t[1]], g2 = group[t[2]];
        visit(g0);
        if (g1 != g0) visit(g1);
        if (g2 != g0 && g2 != g1) visit(g2);
    };
    for (const Triangle& t : mesh.triangles) for_each_distinct_group(t, [&](std::uint32_t g) { ++result.offsets[g + 1]; });
    for (std::size_t g = 0; g < groups; ++g) result.offsets[g + 1] += result.offsets[g];
    result.faces.resize(result.offsets[groups]);
    std::vector<std::size_t> next(result.offsets.begin(), result.offsets.end() - 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        for_each_distinct_group(mesh.triangles[f],
                                [&](std::uint32_t g) { result.faces[next[g]++] = static_cast<std::uint32_t>(f); });
    }
    return result;
}

// Each face's right-hand cross product (twice its area, pointing out) and its
// unit direction (zero for a zero-area or non-finite face).
struct FaceNormals {
    std::vector<glm::dvec3> weighted;
    std::vector<glm::dvec3> unit;
};

FaceNormals face_normals(const Mesh& mesh) {
    FaceNormals normals;
    normals.weighted.resize(mesh.triangles.size());
    normals.unit.resize(mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const glm::dvec3& a = mesh.positions[t[0]];
        glm::dvec3 cross = glm::cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
        if (!detail::all_finite(cross)) cross = glm::dvec3(0.0);
        normals.weighted[f] = cross;
        normals.unit[f] = safe_normalize<double>(cross);
    }
    return normals;
}

// The normal of face `face`'s corner in a group: its pooled faces' sum, with
// calculate_normals' fallback when the sum cancels (two-sided sheets).
glm::vec3 pooled_normal(const FaceNormals& normals, const std::uint32_t* begin, const std::uint32_t* end,
                        std::uint32_t face, double min_cosine) {
    const glm::dvec3& own = normals.unit[face];
    const bool pool_all = own == glm::dvec3(0.0) || min_cosine <= -1.0;
    glm::dvec3 sum(0.0);
    glm::dvec3 largest_face(0.0);
    double largest_area = 0.0;
    for (const std::uint32_t* other = begin; other != end; ++other) {
        if (!pool_all && !(glm::dot(own, normals.unit[*other]) >= min_cosine)) continue;
        const glm::dvec3& weighted = normals.weighted[*other];
        sum += weighted;
        const double twice_area = glm::length(weighted);
        if (twice_area > largest_area) {
            largest_area = twice_area;
            largest_face = weighted;
        }
    }
    glm::dvec3 normal = safe_normalize<double>(sum);
    if (normal == glm::dvec3(0.0) || !(glm::length(sum) > 1e-12 * largest_area)) normal = safe_normalize<double>(largest_face);
    return glm::vec3(normal);
}

// Gives every corner its normal, splitting a vertex whose corners disagree:
// copies[v] chains the (normal, index) pairs already made for vertex v.
class VertexSplitter {
public:
    explicit VertexSplitter(Mesh& mesh) : mesh_(mesh), original_count_(mesh.positions.size()) {
        head_.assign(original_count_, none);
        mesh_.normals.assign(original_count_, glm::vec3(0.0f));
    }

    std::uint32_t index_for(std::uint32_t vertex, const glm::vec3& normal) {
        for (std::uint32_t entry = head_[vertex]; entry != none; entry = entries_[entry].next) {
            if (mesh_.normals[entries_[entry].index] == normal) return entries_[entry].index;
        }
        std::uint32_t index = vertex;
        if (head_[vertex] != none) {
            if (mesh_.positions.size() >= std::numeric_limits<std::uint32_t>::max()) {
                throw std::invalid_argument("mesh: too many vertices after splitting at creases (limit 2^32 - 1)");
            }
            index = static_cast<std::uint32_t>(mesh_.positions.size());
            mesh_.positions.push_back(mesh_.positions[vertex]);
            if (!mesh_.colors.empty()) mesh_.colors.push_back(mesh_.colors[vertex]);
            mesh_.normals.push_back(normal);
        }
        mesh_.normals[index] = normal;
        entries_.push_back({index, head_[vertex]});
        head_[vertex] = static_cast<std::uint32_t>(entries_.size() - 1);
        return index;
    }

private:
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    struct Entry {
        std::uint32_t index;
        std::uint32_t next;
    };
    Mesh& mesh_;
    std::size_t original_count_;
    std::vector<std::uint32_t> head_;
    std::vector<Entry> entries_;
};

}  // namespace

Mesh with_normals(const Mesh& mesh, const NormalOptions& options) {
    if (!(options.crease_degrees >= 0.0 && options.crease_degrees <= 180.0)) {
        throw std::invalid_argument("normals: crease angle " + std::to_string(options.crease_degrees) +
                                    " degrees, expected a number from 0 to 180");
    }
    validate_mesh(mesh);
    Mesh result = mesh;
    if (options.is_contract()) {
        result.normals = calculate_normals(mesh);
        return result;
    }
    const std::vector<std::uint32_t> group = sharing_groups(mesh, options.sharing);
    std::size_t groups = 0;
    for (std::uint32_t g : group) groups = std::max<std::size_t>(groups, std::size_t(g) + 1);
    const GroupFaces group_faces = faces_per_group(mesh, group, groups);
    const FaceNormals normals = face_normals(mesh);
    // 180 degrees pools every face: -1 (and below, against rounding) accepts all.
    const double min_cosine =
        options.crease_degrees >= 180.0 ? -2.0 : std::cos(options.crease_degrees * pi / 180.0);

    // A corner that pools every face of its group (no crease, or a zero-area
    // face) gets the group's one normal: computed once, so a fan of many faces
    // around one position costs linear time.
    std::vector<glm::vec3> whole_group_normal(groups);
    std::vector<bool> whole_group_known(groups, false);
    VertexSplitter splitter(result);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const bool pools_all = min_cosine <= -1.0 || normals.unit[f] == glm::dvec3(0.0);
        for (std::size_t corner = 0; corner < 3; ++corner) {
            const std::uint32_t vertex = mesh.triangles[f][corner];
            const std::uint32_t g = group[vertex];
            const std::uint32_t* begin = group_faces.faces.data() + group_faces.offsets[g];
            const std::uint32_t* end = group_faces.faces.data() + group_faces.offsets[g + 1];
            glm::vec3 normal;
            if (pools_all && whole_group_known[g]) {
                normal = whole_group_normal[g];
            } else {
                normal = pooled_normal(normals, begin, end, static_cast<std::uint32_t>(f), min_cosine);
                if (pools_all) {
                    whole_group_normal[g] = normal;
                    whole_group_known[g] = true;
                }
            }
            result.triangles[f][corner] = splitter.index_for(vertex, normal);
        }
    }
    return result;
}

}  // namespace phongrast
