// Painter's order (internal header): the contract's draw order, farthest
// mean camera depth first, ties in mesh order.
#ifndef PHONGRAST_SRC_PAINTER_ORDER_HPP
#define PHONGRAST_SRC_PAINTER_ORDER_HPP

#include <cstdint>
#include <vector>

#include "depth_sort.hpp"
#include "phongrast/mesh.hpp"
#include "progress_monitor.hpp"

namespace phongrast::detail {

/// painter_order()'s scratch, kept from frame to frame.
struct PainterOrderMemory {
    std::vector<double> mean_depth;  ///< per triangle: the mean z_c of its vertices
    DepthSortScratch sort;
};

/// Fills `order` with the triangle indices farthest first by the mean z_c
/// (camera space) of their three vertices; equal depths keep mesh order.
/// Reports progress through `progress`.
void painter_order(const std::vector<Triangle>& triangles, const std::vector<double>& camera_depth,
                   PainterOrderMemory& memory, std::vector<std::uint32_t>& order, ProgressMonitor& progress);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PAINTER_ORDER_HPP
