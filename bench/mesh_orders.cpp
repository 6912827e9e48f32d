#include "mesh_orders.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

// Internal: the renderer's own permutation gives the spatial order.
#include "mesh_order.hpp"

namespace phongrast_bench {
namespace {

/// `mesh` with triangle k = old triangle triangle_source[k] and vertex v moved to vertex_target[v].
/// A triangle's own attributes (its corners' texture coordinates and file normals, its material)
/// go with it: left in place, a textured mesh's corners would take other faces' texture
/// coordinates, and assembly would split its vertices into another, larger mesh.
phongrast::Mesh permuted(const phongrast::Mesh& mesh, const std::vector<std::uint32_t>& triangle_source,
                         const std::vector<std::uint32_t>& vertex_target) {
    phongrast::Mesh out = mesh;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        out.positions[vertex_target[v]] = mesh.positions[v];
        if (!mesh.colors.empty()) out.colors[vertex_target[v]] = mesh.colors[v];
        if (!mesh.normals.empty()) out.normals[vertex_target[v]] = mesh.normals[v];
    }
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const std::uint32_t source = triangle_source[k];
        const phongrast::Triangle& tri = mesh.triangles[source];
        out.triangles[k] = {vertex_target[tri[0]], vertex_target[tri[1]], vertex_target[tri[2]]};
        if (!mesh.texcoord_triangles.empty()) out.texcoord_triangles[k] = mesh.texcoord_triangles[source];
        if (!mesh.file_normal_triangles.empty()) out.file_normal_triangles[k] = mesh.file_normal_triangles[source];
        if (!mesh.face_materials.empty()) out.face_materials[k] = mesh.face_materials[source];
    }
    return out;
}

}  // namespace

const std::vector<std::string>& mesh_order_names() {
    static const std::vector<std::string> names = {"generator", "spatial", "shuffled"};
    return names;
}

phongrast::Mesh in_mesh_order(const phongrast::Mesh& mesh, const std::string& order) {
    if (order == "generator") return mesh;
    if (order == "spatial") {
        phongrast::detail::MeshOrder spatial;
        phongrast::detail::compute_mesh_order(mesh, spatial);
        return permuted(mesh, spatial.triangle_source, phongrast::detail::vertex_targets(spatial));
    }
    if (order == "shuffled") {
        std::mt19937_64 random(2026);
        std::vector<std::uint32_t> triangle_source(mesh.triangles.size()), vertex_target(mesh.positions.size());
        std::iota(triangle_source.begin(), triangle_source.end(), 0u);
        std::iota(vertex_target.begin(), vertex_target.end(), 0u);
        std::shuffle(triangle_source.begin(), triangle_source.end(), random);
        std::shuffle(vertex_target.begin(), vertex_target.end(), random);
        return permuted(mesh, triangle_source, vertex_target);
    }
    throw std::invalid_argument("mesh order: expected generator, spatial or shuffled, got '" + order + "'");
}

}  // namespace phongrast_bench
