// CoveredRows::solve() for triangles larger than tiny: every way it finds a
// row's span (a mask of the row's centres for boxes under 32 columns whose
// edge values fit 32 bits, a walk along narrow rows, a bound per edge on
// wide ones; the masks also row after row, as the fill walks them) against
// every centre tested on its own from scratch: the same spans and edge
// values, at any position, in any band of rows.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "raster.hpp"
#include "support/covered_spans.hpp"

using namespace phongrast::detail;

namespace {

constexpr int kRows = 9000, kColumns = 9000;

struct Corners {
    double x[3], y[3];
};

/// A triangle whose bounding box is about `width` x `height` pixels at
/// (column, row): random corners, or corners on the half-pixel grid (centres
/// on edges and corners; vertical and horizontal edges).
Corners random_corners(std::mt19937& rng, double column, double row, double width, double height) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Corners c{};
    const bool on_grid = rng() % 3 == 0;
    for (int i = 0; i < 3; ++i) {
        c.x[i] = column + unit(rng) * width;
        c.y[i] = row + unit(rng) * height;
        if (on_grid) {
            c.x[i] = std::round(c.x[i] * 2.0) / 2.0;
            c.y[i] = std::round(c.y[i] * 2.0) / 2.0;
        }
    }
    if (rng() % 4 == 0) c.x[1] = c.x[0];  // a vertical edge: no change along the row
    if (rng() % 4 == 0) c.y[2] = c.y[0];  // a horizontal edge: top or bottom
    return c;
}

}  // namespace

TEST_CASE("rows of larger triangles: masks, walks and bounds find every centre the edge functions cover") {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int by_masks = 0, too_tall_for_masks = 0, wide = 0, narrow_walked = 0, spans_compared = 0;
    for (int n = 0; n < 4000; ++n) {
        // Box widths across the mask limit (32 columns); heights up to slivers of thousands of rows,
        // whose edge values no longer fit 32 bits; anywhere in the image, off its edges too.
        const double width = 1.0 + unit(rng) * 80.0;
        const double height = (n % 7 == 0) ? 300.0 + unit(rng) * 3000.0 : 1.0 + unit(rng) * 60.0;
        const double column = -20.0 + unit(rng) * (kColumns - width + 20.0);
        const double row = -20.0 + unit(rng) * (kRows - height + 20.0);
        const Corners c = random_corners(rng, column, row, width, height);
        CoverageTriangle t;
        if (!setup_coverage(snap(c.x[0], c.y[0]), snap(c.x[1], c.y[1]), snap(c.x[2], c.y[2]), kRows, kColumns, t)) {
            continue;
        }
        const int cut_begin = t.row_min + static_cast<int>(rng() % 8);
        const int bands[][2] = {{0, kRows}, {cut_begin, cut_begin + 1 + static_cast<int>(rng() % 20)}};
        for (const auto& band : bands) {
            const CoveredRows rows(t, band[0], band[1]);
            if (rows.empty() || rows.tiny()) continue;
            const bool narrow = t.column_max - t.column_min < CoveredRows::kWalkedSpanColumns;
            if (rows.solves_rows_by_masks()) {
                ++by_masks;
            } else if (t.column_max - t.column_min < CoveredRows::kMaskColumns) {
                ++too_tall_for_masks;
                narrow_walked += narrow ? 1 : 0;
            } else {
                ++wide;
            }
            const std::vector<CoveredSpan> solved = solved_spans(rows);
            REQUIRE(same_spans(solved, brute_force_spans(t, rows.first_row(), rows.last_row())));
#if PHONGRAST_ROW_MASKS
            // The fill's walk of the rows by masks, values carried from row to row: the same spans.
            if (rows.solves_rows_by_masks()) REQUIRE(same_spans(masked_spans(rows), solved));
#endif
            spans_compared += static_cast<int>(solved.size());
        }
    }
    INFO(by_masks << " by masks, " << too_tall_for_masks << " too tall for masks (" << narrow_walked << " walked), "
                  << wide << " wide, " << spans_compared << " spans");
#if PHONGRAST_ROW_MASKS
    CHECK(by_masks > 3000);
#endif
    CHECK(too_tall_for_masks > 100);
    CHECK(narrow_walked > 30);
    CHECK(wide > 1000);
    CHECK(spans_compared > 100000);
}

TEST_CASE("rows by masks: a tall box of one group of columns, whose column step times four needs more than 32 bits") {
    // A vertical edge 9000 rows long through column 0's centres and a third corner 1.5 columns to the right: in a band
    // of 16 rows the box's edge values fit 32 bits (masks), while four times the long edge's step per column does not.
    const int rows = 9001, columns = 8;
    CoverageTriangle t;
    REQUIRE(setup_coverage(snap(0.5, 0.0), snap(0.5, 9000.0), snap(2.0, 4500.0), rows, columns, t));
    std::int64_t largest_step = 0;
    for (int band_begin = 4400; band_begin < 4600; band_begin += 16) {
        const CoveredRows band(t, band_begin, band_begin + 16);
        REQUIRE(band.solves_rows_by_masks() == (PHONGRAST_ROW_MASKS == 1));
        for (int i = 0; i < 3; ++i) largest_step = std::max(largest_step, std::abs(band.step()[i]));
        const std::vector<CoveredSpan> solved = solved_spans(band);
        REQUIRE(solved.size() == 16);
        REQUIRE(same_spans(solved, brute_force_spans(t, band.first_row(), band.last_row())));
#if PHONGRAST_ROW_MASKS
        REQUIRE(same_spans(masked_spans(band), solved));
#endif
    }
    CHECK(4 * largest_step > std::int64_t(INT32_MAX));
    CHECK(3 * largest_step <= std::int64_t(INT32_MAX));
}
