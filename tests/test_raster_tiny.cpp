// The tiny-triangle path of the coverage (CoveredRows::tiny_spans(), taken by
// for_each_weighted_span() when a triangle's bounding box holds at most 2 x 2
// samples of the band) against the general one (CoveredRows::solve() row by
// row, for_each_weighted_row()) and against the edge functions evaluated from
// scratch at every centre: the same spans, edge values and weights, bit for bit.
#include <cstring>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_kernels.hpp"
#include "raster.hpp"
#include "support/covered_spans.hpp"

using namespace phongrast::detail;

namespace {

constexpr int kRows = 37, kColumns = 29;  // not multiples of the 16-row bands

std::vector<CoveredSpan> tiny_spans(const CoveredRows& rows) {
    CoveredSpan spans[2];
    const int found = rows.tiny_spans(spans);
    return std::vector<CoveredSpan>(spans, spans + found);
}

/// A span as the fill kernels see it: where, and the weights' start and step, as bits.
template <typename Real>
struct WeightedSpan {
    int row, first_column, count;
    Real q[3], dq[3];
    bool operator==(const WeightedSpan& o) const {
        return row == o.row && first_column == o.first_column && count == o.count &&
               std::memcmp(q, o.q, sizeof q) == 0 && std::memcmp(dq, o.dq, sizeof dq) == 0;
    }
};

template <typename Real>
struct SpanRecorder {
    std::vector<WeightedSpan<Real>>* out;
    void operator()(int row, int first_column, int count, const Real* q, const Real* dq) const {
        WeightedSpan<Real> span{row, first_column, count, {q[0], q[1], q[2]}, {dq[0], dq[1], dq[2]}};
        out->push_back(span);
    }
};

/// The kernels' weighted spans through for_each_weighted_span() (tiny path
/// where it applies) and through the general for_each_weighted_row(): identical.
template <typename Real, bool Perspective>
void check_weights(const CoverageTriangle& t, const Real* depth, int row_begin, int row_end) {
    FillTriangle<Real> draw{};
    draw.coverage = t;
    for (int i = 0; i < 3; ++i) draw.depth[i] = depth[i];
    phongrast::Image image;
    std::vector<Real> depth_buffer;
    FillTarget<Real> target{image, depth_buffer, row_begin, row_end, false, 0, 0};
    std::vector<WeightedSpan<Real>> either, general;
    for_each_weighted_span<Real, Perspective>(draw, target, SpanRecorder<Real>{&either});
    const CoveredRows rows(t, row_begin, row_end);
    if (!rows.empty()) {
        SpanRecorder<Real> record{&general};
        for_each_weighted_row<Real, Perspective>(rows, draw, record);
    }
    REQUIRE(either == general);
}

struct Corners {
    double x[3], y[3];
};

/// Small triangles (some around 2 x 2 centres), slivers (thin, long, any angle,
/// some axis-aligned on the centres' rows and columns) and triangles with corners on the half-pixel
/// grid (centres exactly on edges), around and beyond the image's borders.
Corners random_corners(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double cx = -2.0 + unit(rng) * (kColumns + 4), cy = -2.0 + unit(rng) * (kRows + 4);
    Corners c{};
    switch (rng() % 5) {
        case 0: {  // small: corners within up to 2.5 pixels
            const double r = 0.05 + 2.45 * unit(rng);
            for (int i = 0; i < 3; ++i) {
                c.x[i] = cx + r * (2 * unit(rng) - 1);
                c.y[i] = cy + r * (2 * unit(rng) - 1);
            }
            break;
        }
        case 1: {  // sliver: up to 40 pixels long, 0.001 to 0.3 wide
            const double angle = 6.283185307179586 * unit(rng), length = 40 * unit(rng);
            const double width = 0.001 + 0.3 * unit(rng), dx = std::cos(angle), dy = std::sin(angle);
            c.x[0] = cx, c.y[0] = cy;
            c.x[1] = cx + length * dx, c.y[1] = cy + length * dy;
            const double along = unit(rng) * length;
            c.x[2] = cx + along * dx - width * dy, c.y[2] = cy + along * dy + width * dx;
            break;
        }
        case 2: {  // axis-aligned sliver along a row or a column of centres
            const double along = std::floor(cy) + 0.5, length = 1 + 6 * unit(rng), width = 0.5 * unit(rng);
            const bool vertical = rng() % 2 == 0;
            const double a[3] = {cx, cx + length, cx + unit(rng) * length};
            const double b[3] = {along, along, along + (rng() % 2 ? width : -width)};
            for (int i = 0; i < 3; ++i) {
                c.x[i] = vertical ? b[i] : a[i];
                c.y[i] = vertical ? a[i] : b[i];
            }
            break;
        }
        case 3: {  // near three corners of a box of 2 x 2 centres: often covering three of them
            const int skipped = static_cast<int>(rng() % 4);
            for (int i = 0, corner = 0; i < 3; ++i, ++corner) {
                if (corner == skipped) ++corner;
                const double inward_x = 0.01 + 0.2 * unit(rng), inward_y = 0.01 + 0.2 * unit(rng);
                c.x[i] = std::floor(cx) + ((corner & 1) ? 2.0 - inward_x : inward_x);
                c.y[i] = std::floor(cy) + ((corner & 2) ? 2.0 - inward_y : inward_y);
            }
            break;
        }
        default:  // corners on the half-pixel grid: centres on edges and corners
            for (int i = 0; i < 3; ++i) {
                c.x[i] = std::floor(cx) + 0.5 * double(rng() % 6);
                c.y[i] = std::floor(cy) + 0.5 * double(rng() % 6);
            }
            break;
    }
    if (rng() % 2) std::swap(c.x[1], c.x[2]), std::swap(c.y[1], c.y[2]);  // either winding
    return c;
}

}  // namespace

TEST_CASE("tiny triangles: the direct test of the bounding box finds the general path's spans and weights") {
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> depth_range(0.5, 50.0);
    int tiny = 0, tiny_covering_several = 0, tiny_covering_none = 0, general = 0, band_cuts = 0, small_boxes_dropped = 0;
    for (int n = 0; n < 60000; ++n) {
        const Corners c = random_corners(rng);
        CoverageTriangle t;
        const SnappedPoint a = snap(c.x[0], c.y[0]), b = snap(c.x[1], c.y[1]), d = snap(c.x[2], c.y[2]);
        if (!setup_coverage(a, b, d, kRows, kColumns, t)) continue;
        // Set-up's test of a small box (may_cover_a_centre) agrees with the centres covered.
        const bool covers_some = !brute_force_spans(t, t.row_min, t.row_max).empty();
        const bool small_box = t.row_max - t.row_min < 2 && t.column_max - t.column_min < 2;
        REQUIRE(may_cover_a_centre(t) == (covers_some || !small_box));
        small_boxes_dropped += small_box && !covers_some ? 1 : 0;
        // The whole image, the 16-row bands and a random cut of 1 to 3 rows through the triangle.
        const int cut_begin = t.row_min + static_cast<int>(rng() % 2);
        const int cut_end = cut_begin + 1 + static_cast<int>(rng() % 3);
        const int bands[][2] = {{0, kRows}, {0, 16}, {16, 32}, {32, kRows}, {cut_begin, cut_end}};
        const double depth_values[3] = {depth_range(rng), depth_range(rng), depth_range(rng)};
        const float depth_f[3] = {float(depth_values[0]), float(depth_values[1]), float(depth_values[2])};
        for (const auto& band : bands) {
            const CoveredRows rows(t, band[0], band[1]);
            if (rows.empty()) continue;
            band_cuts += (band[0] > t.row_min || band[1] <= t.row_max) ? 1 : 0;
            const std::vector<CoveredSpan> expected = brute_force_spans(t, rows.first_row(), rows.last_row());
            REQUIRE(same_spans(solved_spans(rows), expected));
            if (rows.tiny()) {
                ++tiny;
                const std::vector<CoveredSpan> found = tiny_spans(rows);
                REQUIRE(same_spans(found, expected));
                int samples = 0;
                for (const CoveredSpan& span : found) samples += span.count;
                tiny_covering_none += samples == 0 ? 1 : 0;
                tiny_covering_several += samples >= 3 ? 1 : 0;  // four cannot fit in a box this small
            } else {
                ++general;
            }
            check_weights<float, true>(t, depth_f, band[0], band[1]);
            check_weights<float, false>(t, depth_f, band[0], band[1]);
            check_weights<double, true>(t, depth_values, band[0], band[1]);
        }
    }
    // The cases the comparison is meant to reach were reached.
    INFO(tiny << " tiny, " << tiny_covering_none << " covering none, " << tiny_covering_several
              << " covering 3, " << general << " general, " << band_cuts << " cut by a band");
    CHECK(tiny > 30000);
    CHECK(tiny_covering_none > 10000);
    CHECK(tiny_covering_several > 3000);
    CHECK(general > 30000);
    CHECK(band_cuts > 15000);
    CHECK(small_boxes_dropped > 5000);
}

TEST_CASE("tiny triangles: which bounding boxes take the direct test") {
    CoverageTriangle t;
    // Centres (1, 1), (2, 1), (1, 2), (2, 2) in the box: tiny, three of them covered.
    REQUIRE(setup_coverage(snap(0.9, 0.9), snap(3.2, 0.9), snap(0.9, 3.2), 10, 10, t));
    const CoveredRows square(t, 0, 10);
    REQUIRE(square.tiny());
    const std::vector<CoveredSpan> spans = tiny_spans(square);
    REQUIRE(spans.size() == 2);
    CHECK((spans[0].row == 1 && spans[0].first_column == 1 && spans[0].count == 2));
    CHECK((spans[1].row == 2 && spans[1].first_column == 1 && spans[1].count == 1));
    // Three columns of centres: the general path.
    REQUIRE(setup_coverage(snap(0.9, 0.9), snap(4.0, 0.9), snap(0.9, 2.0), 10, 10, t));
    CHECK_FALSE(CoveredRows(t, 0, 10).tiny());
    // Three rows in the image, but a band of two of them: tiny within the band.
    REQUIRE(setup_coverage(snap(0.9, 0.9), snap(2.0, 0.9), snap(0.9, 4.0), 10, 10, t));
    CHECK_FALSE(CoveredRows(t, 0, 10).tiny());
    CHECK(CoveredRows(t, 2, 4).tiny());
}
