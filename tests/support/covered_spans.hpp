// Reference spans for the coverage tests: every centre of a bounding box
// tested on its own from scratch, to check CoveredRows' faster paths against.
#ifndef PHONGRAST_TESTS_SUPPORT_COVERED_SPANS_HPP
#define PHONGRAST_TESTS_SUPPORT_COVERED_SPANS_HPP

#include <cstring>
#include <vector>

#include <catch2/catch.hpp>

#include "raster.hpp"

namespace phongrast::detail {

inline bool same_span(const CoveredSpan& a, const CoveredSpan& b) {
    return a.row == b.row && a.first_column == b.first_column && a.count == b.count && a.e[0] == b.e[0] &&
           a.e[1] == b.e[1] && a.e[2] == b.e[2];
}

inline bool same_spans(const std::vector<CoveredSpan>& a, const std::vector<CoveredSpan>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t s = 0; s < a.size(); ++s) {
        if (!same_span(a[s], b[s])) return false;
    }
    return true;
}

/// Every centre of the bounding box in rows [first, last] tested on its own:
/// unbiased edge values, a centre on an edge owned by a top or left edge.
inline std::vector<CoveredSpan> brute_force_spans(const CoverageTriangle& t, int first, int last) {
    std::vector<CoveredSpan> spans;
    for (int row = first; row <= last; ++row) {
        CoveredSpan span{row, 0, 0, {0, 0, 0}};
        for (int column = t.column_min; column <= t.column_max; ++column) {
            const std::int64_t px = std::int64_t(column) * kSubpixelScale + kHalfPixel;
            const std::int64_t py = std::int64_t(row) * kSubpixelScale + kHalfPixel;
            std::int64_t e[3];
            bool inside = true;
            for (int i = 0; i < 3; ++i) {
                const SnappedPoint a = t.v[(i + 1) % 3], b = t.v[(i + 2) % 3];
                e[i] = edge_value(a, b, px, py);
                const bool top_left = (b.y - a.y < 0) || (b.y == a.y && b.x > a.x);
                inside = inside && (e[i] > 0 || (e[i] == 0 && top_left));
            }
            if (!inside) continue;
            if (span.count == 0) {
                span.first_column = column;
                std::memcpy(span.e, e, sizeof e);
            }
            REQUIRE(span.first_column + span.count == column);  // contiguous: the triangle is convex
            ++span.count;
        }
        if (span.count > 0) spans.push_back(span);
    }
    return spans;
}

inline std::vector<CoveredSpan> solved_spans(const CoveredRows& rows) {
    std::vector<CoveredSpan> spans;
    for (int row = rows.first_row(); row <= rows.last_row(); ++row) {
        CoveredSpan span;
        if (rows.solve(row, span)) spans.push_back(span);
    }
    return spans;
}

#if PHONGRAST_ROW_MASKS
/// The spans CoveredRows::MaskedRows finds row after row (solves_rows_by_masks() only).
inline std::vector<CoveredSpan> masked_spans(const CoveredRows& rows) {
    std::vector<CoveredSpan> spans;
    CoveredRows::MaskedRows masked(rows);
    for (int row = rows.first_row(); row <= rows.last_row(); ++row) {
        CoveredSpan span;
        if (masked.solve_and_advance(row, span)) spans.push_back(span);
    }
    return spans;
}
#endif

}  // namespace phongrast::detail

#endif  // PHONGRAST_TESTS_SUPPORT_COVERED_SPANS_HPP
