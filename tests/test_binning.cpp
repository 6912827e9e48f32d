// Binning on its own: every draw lands in exactly the bands of rows it
// touches, in painter's order, whatever the set-up chunk it came from.
#include <vector>

#include <catch2/catch.hpp>

#include "binning.hpp"

namespace pd = phongrast::detail;

namespace {

pd::FillTriangle<float> draw_over_rows(int row_min, int row_max) {
    pd::FillTriangle<float> draw{};
    draw.coverage.row_min = row_min;
    draw.coverage.row_max = row_max;
    return draw;
}

}  // namespace

/// The span of a triangle of one draw, as set-up records it.
pd::DrawSpan one_draw(std::size_t chunk, std::size_t first, int row_min, int row_max) {
    return pd::DrawSpan::one(chunk, first, row_min / pd::kBandRows, row_max / pd::kBandRows);
}

TEST_CASE("bins follow painter's order within each band, whatever chunk a draw came from") {
    constexpr int kRows = 40;  // bands of 16 rows: [0, 16), [16, 32), [32, 40)
    pd::DrawList<float> list;
    list.chunks = 2;
    list.chunk_draws.resize(3);  // a stale third chunk from an earlier frame must be ignored
    list.chunk_draws[0] = {draw_over_rows(0, 3), draw_over_rows(10, 20), draw_over_rows(33, 39)};
    // Chunk 1: one triangle, then a clipped one whose two pieces touch different bands.
    list.chunk_draws[1] = {draw_over_rows(15, 16), draw_over_rows(0, 5), draw_over_rows(30, 39)};
    list.chunk_draws[2] = {draw_over_rows(0, 39)};
    const auto& a = list.chunk_draws[0];
    const auto& b = list.chunk_draws[1];

    pd::PainterOrderMemory painter;
    // Painter's order: b's clipped triangle first, then a1, b0, a0, a2.
    painter.sorted = {{0, pd::DrawSpan::several(1, 1, 2)}, {1, one_draw(0, 1, 10, 20)}, {2, one_draw(1, 0, 15, 16)},
                      {3, one_draw(0, 0, 0, 3)}, {4, one_draw(0, 2, 33, 39)}};

    pd::BinningMemory memory;
    pd::Bins<float> bins;
    pd::bin_draws(list, painter, kRows, memory, bins);
    REQUIRE(bins.bands == 3);
    const auto band = [&](int index) {
        return std::vector<const pd::FillTriangle<float>*>(bins.band_draws(index),
                                                           bins.band_draws(index) + bins.band_size(index));
    };
    CHECK(band(0) == std::vector<const pd::FillTriangle<float>*>{&b[1], &a[1], &b[0], &a[0]});
    CHECK(band(1) == std::vector<const pd::FillTriangle<float>*>{&b[2], &a[1], &b[0]});
    CHECK(band(2) == std::vector<const pd::FillTriangle<float>*>{&b[2], &a[2]});
    CHECK(bins.draws.size() == 9);
}

TEST_CASE("binning an empty frame after a full one leaves empty bands") {
    pd::DrawList<float> list;
    list.chunks = 1;
    list.chunk_draws.resize(1);
    list.chunk_draws[0] = {draw_over_rows(0, 63)};
    pd::PainterOrderMemory painter;
    painter.sorted = {{0, one_draw(0, 0, 0, 63)}};
    pd::BinningMemory memory;
    pd::Bins<float> bins;
    pd::bin_draws(list, painter, 64, memory, bins);
    CHECK(bins.draws.size() == 4);
    list.chunk_draws[0].clear();
    painter.sorted.clear();
    pd::bin_draws(list, painter, 64, memory, bins);
    REQUIRE(bins.bands == 4);
    for (int b = 0; b < bins.bands; ++b) CHECK(bins.band_size(b) == 0);
}
