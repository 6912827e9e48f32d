// Where a drawn mesh triangle's draws are in set-up's output (internal
// header): what painter's order sorts and binning walks. Apart from
// triangle_setup.hpp so that painter_order.hpp needs nothing else of set-up.
#ifndef PHONGRAST_SRC_DRAW_SPAN_HPP
#define PHONGRAST_SRC_DRAW_SPAN_HPP

#include <cstddef>
#include <cstdint>

namespace phongrast::detail {

/// Mesh triangles set up by one task (one chunk of the draw list), and the
/// fewest a task takes when a small mesh's chunks are made smaller so that
/// every thread gets several (items_per_task()).
constexpr std::size_t kSetupChunk = 4096;
constexpr std::size_t kSmallestSetupChunk = 512;

/// Where the draws (FillTriangles) of a mesh triangle that set-up drew are,
/// as painter's order and binning see it: 8 bytes, so that the sort moves
/// little and binning does not read the draws themselves.
class DrawSpan {
public:
    /// Bits of the place of a draw in its chunk's list (kSetupChunk triangles
    /// of at most 6 pieces each fit); the chunk takes the other 17, so a mesh
    /// has at most 2^29 triangles (validate_mesh() checks).
    static constexpr int kFirstBits = 15;
    static constexpr std::size_t kMaxTriangles = (std::size_t(1) << (32 - kFirstBits)) * kSetupChunk;

    DrawSpan() = default;
    /// One draw, touching bands [band_first, band_last] of kBandRows rows.
    static DrawSpan one(std::size_t chunk, std::size_t first, int band_first, int band_last) {
        return {chunk, first, static_cast<std::uint16_t>(band_first), static_cast<std::uint16_t>(band_last)};
    }
    /// `count` draws in a row (a clipped polygon's pieces): binning reads their rows.
    static DrawSpan several(std::size_t chunk, std::size_t first, int count) {
        return {chunk, first, static_cast<std::uint16_t>(count), kSeveral};
    }

    std::size_t chunk() const { return draw_ >> kFirstBits; }
    std::size_t first() const { return draw_ & ((std::uint32_t(1) << kFirstBits) - 1); }
    bool single() const { return band_last_ != kSeveral; }
    int count() const { return single() ? 1 : band_first_; }
    int band_first() const { return band_first_; }  ///< single() only
    int band_last() const { return band_last_; }    ///< single() only

private:
    /// Not a band: images are at most 2^19 rows, 2^15 bands.
    static constexpr std::uint16_t kSeveral = 0xffff;

    DrawSpan(std::size_t chunk, std::size_t first, std::uint16_t a, std::uint16_t b)
        : draw_(static_cast<std::uint32_t>(chunk << kFirstBits | first)), band_first_(a), band_last_(b) {}

    std::uint32_t draw_ = 0;  ///< chunk << kFirstBits | place of its first draw there
    std::uint16_t band_first_ = 0, band_last_ = 0;  ///< bands; or, when several, the count and kSeveral
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_DRAW_SPAN_HPP
