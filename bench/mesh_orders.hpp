// The benchmarks' generated meshes in several orders, so that every speed
// goal can be read per order (docs/performance.md, "Mesh order"):
//   generator  as the generator writes it (icosphere: face by face, row by row)
//   spatial    triangles in Morton order of their centroids, vertices by first
//              use: the order the renderer puts a large mesh in (src/mesh_order.hpp)
//   shuffled   faces and vertices in a random order (fixed seed)
// The picture is the same bits in every order.
#ifndef PHONGRAST_BENCH_MESH_ORDERS_HPP
#define PHONGRAST_BENCH_MESH_ORDERS_HPP

#include <string>
#include <vector>

#include "phongrast/mesh.hpp"

namespace phongrast_bench {

/// "generator", "spatial", "shuffled".
const std::vector<std::string>& mesh_order_names();

/// `mesh` put into the order called `order`: its vertices (positions, colours,
/// normals) and triangles, each triangle with its own attributes (texture
/// coordinate and file normal indices, material); throws
/// std::invalid_argument naming the orders for another name.
phongrast::Mesh in_mesh_order(const phongrast::Mesh& mesh, const std::string& order);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_MESH_ORDERS_HPP
