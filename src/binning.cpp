#include "binning.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "populate_pages.hpp"

namespace phongrast::detail {
namespace {

/// Drawn triangles of painter's order binned by one task.
constexpr std::size_t kBinningBlock = 16384;

/// Calls visit(band, draw) for every band every draw of `drawn` touches. A
/// triangle with one draw (nearly all) is binned from its DrawSpan
/// alone; only clipped ones read their draws' rows.
template <typename Real, typename Visit>
void for_each_band(const DrawList<Real>& draws, const DrawSpan& drawn, Visit&& visit) {
    const FillTriangle<Real>* first = draws.chunk_draws[drawn.chunk()].data() + drawn.first();
    if (drawn.single()) {
        const std::size_t band_last = static_cast<std::size_t>(drawn.band_last());
        for (std::size_t band = static_cast<std::size_t>(drawn.band_first()); band <= band_last; ++band) visit(band, first);
        return;
    }
    for (const FillTriangle<Real>* draw = first; draw != first + drawn.count(); ++draw) {
        const std::size_t band_last = static_cast<std::size_t>(draw->coverage.row_max / kBandRows);
        for (std::size_t band = static_cast<std::size_t>(draw->coverage.row_min / kBandRows); band <= band_last; ++band) {
            visit(band, draw);
        }
    }
}

// Band-major offsets: band b's slice starts at band_start[b]; within it, block after block.
template <typename Real>
void lay_out_bands(std::size_t blocks, BinningMemory& memory, Bins<Real>& bins) {
    const std::size_t bands = static_cast<std::size_t>(bins.bands);
    bins.band_start.assign(bands + 1, 0);
    memory.block_band_cursor.resize(memory.block_band_count.size());
    std::uint32_t total = 0;
    for (std::size_t band = 0; band < bands; ++band) {
        bins.band_start[band] = total;
        for (std::size_t block = 0; block < blocks; ++block) {
            const std::size_t slot = block * bands + band;
            memory.block_band_cursor[slot] = total;
            total += memory.block_band_count[slot];
        }
    }
    bins.band_start[bands] = total;
}

}  // namespace

template <typename Real>
void bin_draws(const DrawList<Real>& draws, const PainterOrderMemory& painter, int rows, BinningMemory& memory,
               Bins<Real>& bins, const std::function<void()>& poll) {
    bins.bands = (rows + kBandRows - 1) / kBandRows;
    const std::size_t bands = static_cast<std::size_t>(bins.bands);
    const FrameVector<PaintRecord>& sorted = painter.sorted;
    const std::size_t blocks = (sorted.size() + kBinningBlock - 1) / kBinningBlock;
    // Calls visit(band, draw) for every draw of block `block`, in painter's order.
    const auto for_each_draw_of_block = [&](std::size_t block, auto&& visit) {
        const std::size_t end = std::min(sorted.size(), (block + 1) * kBinningBlock);
        for (std::size_t k = block * kBinningBlock; k < end; ++k) for_each_band(draws, sorted[k].drawn, visit);
    };
    memory.block_band_count.assign(blocks * bands, 0);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        std::uint32_t* count = &memory.block_band_count[block * bands];
        for_each_draw_of_block(block, [&](std::size_t band, const FillTriangle<Real>*) { ++count[band]; });
        if (poll) poll();
    });
    lay_out_bands(blocks, memory, bins);
    reserve_populated(bins.draws, bins.band_start[bands]);
    bins.draws.resize(bins.band_start[bands]);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        std::uint32_t* cursor = &memory.block_band_cursor[block * bands];
        for_each_draw_of_block(block, [&](std::size_t band, const FillTriangle<Real>* draw) {
            bins.draws[cursor[band]++] = draw;
        });
        if (poll) poll();
    });
}

template void bin_draws<float>(const DrawList<float>&, const PainterOrderMemory&, int, BinningMemory&, Bins<float>&,
                               const std::function<void()>&);
template void bin_draws<double>(const DrawList<double>&, const PainterOrderMemory&, int, BinningMemory&,
                                Bins<double>&, const std::function<void()>&);

}  // namespace phongrast::detail
