// Binning (internal header): the fill triangles sorted into bands of rows,
// painter's order kept within each band. Binning writes the Bins; the fill
// only reads them, one band per task.
#ifndef PHONGRAST_SRC_BINNING_HPP
#define PHONGRAST_SRC_BINNING_HPP

#include <cstdint>
#include <functional>
#include <vector>

#include "fill_types.hpp"
#include "painter_order.hpp"
#include "triangle_setup.hpp"

namespace phongrast::detail {

/// The fill triangles of each band of kBandRows sample rows, in painter's order.
template <typename Real>
struct Bins {
    int bands = 0;
    std::vector<std::uint32_t> band_start;          ///< bands + 1 offsets into `draws`
    FrameVector<const FillTriangle<Real>*> draws;   ///< band after band (huge pages: huge_page_pool.hpp)

    const FillTriangle<Real>* const* band_draws(int band) const { return draws.data() + band_start[band]; }
    std::uint32_t band_size(int band) const { return band_start[band + 1] - band_start[band]; }
};

/// bin_draws()'s scratch, kept from frame to frame.
struct BinningMemory {
    std::vector<std::uint32_t> block_band_count;   ///< per block of painter's order and band: draws it puts there
    std::vector<std::uint32_t> block_band_cursor;  ///< per block and band: where its next one goes
};

/// Bins the draws of an image `rows` samples high, triangle by triangle in
/// painter's order (painter.sorted, whose draws are in `draws`). Counted and scattered in parallel over fixed blocks of that
/// order, each block writing its own slice of every band: the same bins for
/// any number of threads. `poll` (may be empty) is called between blocks, for progress reports.
template <typename Real>
void bin_draws(const DrawList<Real>& draws, const PainterOrderMemory& painter, int rows, BinningMemory& memory,
               Bins<Real>& bins, const std::function<void()>& poll = nullptr);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_BINNING_HPP
