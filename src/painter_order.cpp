#include "painter_order.hpp"

#include <algorithm>
#include <numeric>

#include <tbb/parallel_for.h>

namespace phongrast::detail {

void painter_order(const std::vector<std::vector<DrawnTriangle>>& chunk_drawn,
                   const std::vector<std::vector<std::uint64_t>>& chunk_keys, std::size_t chunks, bool sort,
                   PainterOrderMemory& memory, ProgressMonitor& progress) {
    std::vector<std::size_t>& offsets = memory.chunk_offsets;
    offsets.resize(chunks + 1);
    offsets[0] = 0;
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) offsets[chunk + 1] = offsets[chunk] + chunk_drawn[chunk].size();
    const std::size_t total = offsets[chunks];
    memory.drawn.resize(total);
    if (sort) memory.sort.keys.resize(total);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
        std::copy(chunk_drawn[chunk].begin(), chunk_drawn[chunk].end(), memory.drawn.begin() + offsets[chunk]);
        if (sort) std::copy(chunk_keys[chunk].begin(), chunk_keys[chunk].end(), memory.sort.keys.begin() + offsets[chunk]);
    });
    progress.begin_stage(0.35, 0.4, 1);
    if (sort) {
        order_by_keys(total, memory.order, memory.sort, progress.poll_function());
    } else {
        memory.order.resize(total);
        std::iota(memory.order.begin(), memory.order.end(), 0u);
    }
}

}  // namespace phongrast::detail
