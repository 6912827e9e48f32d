#include "painter_order.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace phongrast::detail {

void painter_order(const std::vector<Triangle>& triangles, const std::vector<double>& camera_depth,
                   PainterOrderMemory& memory, std::vector<std::uint32_t>& order, ProgressMonitor& progress) {
    std::vector<double>& depth = memory.mean_depth;
    depth.resize(triangles.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 16384),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
            const Triangle& tri = triangles[t];
            depth[t] = (camera_depth[tri[0]] + camera_depth[tri[1]] + camera_depth[tri[2]]) / 3.0;
        }
    });
    progress.begin_stage(0.1, 0.15, 1);
    farthest_first_order(depth, order, memory.sort, progress.poll_function());
}

}  // namespace phongrast::detail
