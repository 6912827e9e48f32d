#include "binning.hpp"

#include <tbb/parallel_for.h>

namespace phongrast::detail {
namespace {

template <typename Real, typename Visit>
void for_each_band(const DrawTriangle<Real>& draw, Visit&& visit) {
    for (int band = draw.coverage.row_min / kBandRows; band <= draw.coverage.row_max / kBandRows; ++band) {
        visit(static_cast<std::size_t>(band));
    }
}

// Band-major offsets: band b's slice starts at band_start[b]; within it, chunk after chunk.
template <typename Real>
void lay_out_bands(std::size_t chunks, BinningMemory& memory, Bins<Real>& bins) {
    const std::size_t bands = static_cast<std::size_t>(bins.bands);
    bins.band_start.assign(bands + 1, 0);
    memory.chunk_band_cursor.resize(memory.chunk_band_count.size());
    std::uint32_t total = 0;
    for (std::size_t band = 0; band < bands; ++band) {
        bins.band_start[band] = total;
        for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
            const std::size_t slot = chunk * bands + band;
            memory.chunk_band_cursor[slot] = total;
            total += memory.chunk_band_count[slot];
        }
    }
    bins.band_start[bands] = total;
}

}  // namespace

template <typename Real>
void bin_draws(const DrawList<Real>& draws, int rows, BinningMemory& memory, Bins<Real>& bins) {
    bins.bands = (rows + kBandRows - 1) / kBandRows;
    const std::size_t bands = static_cast<std::size_t>(bins.bands);
    const std::size_t chunks = draws.chunks;
    memory.chunk_band_count.assign(chunks * bands, 0);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
        std::uint32_t* count = &memory.chunk_band_count[chunk * bands];
        for (const DrawTriangle<Real>& draw : draws.chunk_draws[chunk]) {
            for_each_band(draw, [&](std::size_t band) { ++count[band]; });
        }
    });
    lay_out_bands(chunks, memory, bins);
    bins.draws.resize(bins.band_start[bands]);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
        std::uint32_t* cursor = &memory.chunk_band_cursor[chunk * bands];
        for (const DrawTriangle<Real>& draw : draws.chunk_draws[chunk]) {
            for_each_band(draw, [&](std::size_t band) { bins.draws[cursor[band]++] = &draw; });
        }
    });
}

template void bin_draws<float>(const DrawList<float>&, int, BinningMemory&, Bins<float>&);
template void bin_draws<double>(const DrawList<double>&, int, BinningMemory&, Bins<double>&);

}  // namespace phongrast::detail
