// Painter's order (internal header): the contract's draw order, farthest
// mean camera depth first, ties in mesh order, of the triangles set-up
// found to draw something.
#ifndef PHONGRAST_SRC_PAINTER_ORDER_HPP
#define PHONGRAST_SRC_PAINTER_ORDER_HPP

#include <cstdint>
#include <vector>

#include "depth_sort.hpp"
#include "phongrast/mesh.hpp"
#include "progress_monitor.hpp"
#include "triangle_setup.hpp"

namespace phongrast::detail {

/// The contract's sort key of a triangle: the mean z_c (camera space) of its
/// three vertices, as a key whose ascending order is farthest first.
inline std::uint64_t painter_key(const Triangle& triangle, const std::vector<double>& camera_depth) {
    return farthest_first_key((camera_depth[triangle[0]] + camera_depth[triangle[1]] + camera_depth[triangle[2]]) /
                              3.0);
}

/// painter_order()'s output and scratch, kept from frame to frame.
struct PainterOrderMemory {
    std::vector<DrawnTriangle> drawn;  ///< every drawn triangle, in mesh order
    std::vector<std::uint32_t> order;  ///< indices into `drawn`, in painter's order
    std::vector<std::size_t> chunk_offsets;  ///< where each chunk's drawn triangles start in `drawn`
    DepthSortScratch sort;
};

/// Gathers the drawn triangles of the first `chunks` set-up chunks (mesh
/// order) into memory.drawn and sorts them into memory.order: farthest mean
/// z_c first, equal depths in mesh order. Triangles that draw nothing are
/// not sorted at all; leaving them out changes no draw's place relative to
/// another's. With `sort` false (the order cannot change the picture), the
/// order is mesh order. Reports progress through `progress`.
void painter_order(const std::vector<std::vector<DrawnTriangle>>& chunk_drawn,
                   const std::vector<std::vector<std::uint64_t>>& chunk_keys, std::size_t chunks, bool sort,
                   PainterOrderMemory& memory, ProgressMonitor& progress);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PAINTER_ORDER_HPP
