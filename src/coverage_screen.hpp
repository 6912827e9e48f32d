// Set-up's coverage screen (internal header): which whole triangles certainly
// cover no sample centre, decided four triangles at a time (AVX2; two on the
// baseline) before set-up.
//
// On a mesh of one-pixel triangles most set-up work goes to triangles that
// draw nothing: on the 1.3M-triangle sphere at 1024², 40% of the triangles
// (55% of the 8M's) cover no centre, found only after each was checked,
// snapped and its coverage set up one at a time (TriangleSetup::run). The
// screen repeats, in vector lanes of doubles, exactly the tests set-up makes
// of a whole triangle (inside the image, drawable depths, in front of the near
// plane; snapped area; the centres its box holds; for a box of at most 2 x 2
// centres, the top-left rule at each), so a screened triangle is counted as
// set-up would count it and costs nothing more. Every value is an integer
// below 2^53 where the verdict depends on it, so the double lanes compute the
// 64-bit integers set-up does, bit for bit; a lane where that is not sure
// (or any test fails) is left to set-up.
//
// Compiled once per instruction set like the lighting lanes (lanes_isa.hpp):
// coverage_screen.cpp (baseline, and the choice), coverage_screen_avx2.cpp.
#ifndef PHONGRAST_SRC_COVERAGE_SCREEN_HPP
#define PHONGRAST_SRC_COVERAGE_SCREEN_HPP

#include <cstddef>
#include <cstdint>

#include "fill_types.hpp"
#include "lanes_isa.hpp"
#include "raster.hpp"
#include "vertex_stage.hpp"

namespace phongrast::detail {

/// What the screen found for one triangle.
enum class ScreenVerdict : std::uint8_t {
    set_up,           ///< not decided: set it up
    degenerate,       ///< whole, zero snapped area: SetupCounts::degenerate
    between_samples,  ///< whole, non-zero area, no centre covered: SetupCounts::between_samples
    /// Whole, non-zero area, a box of at most 2 x 2 centres, some covered:
    /// drawn, and all the fill needs is in the block's TinyCoverageBlock
    /// (given only when one is asked for).
    tiny_covered,
};

/// What the screen reads: the frame's screen vertices and the view's bounds,
/// as TriangleSetup::run() tests them.
struct CoverageScreenInput {
    const Triangle* triangles = nullptr;
    const ScreenVertex* screen = nullptr;
    double column_offset = 0.0, row_offset = 0.0;  ///< View::sample_offset
    double columns = 0.0, rows = 0.0;              ///< the frame's, in samples
    /// The depths run() draws whole: from max(View::near_depth, the least
    /// positive double) (a depth > 0 and >= near_depth) to kMaxDrawableDepth<Real>.
    double min_depth = 0.0, max_depth = 0.0;
};

/// Whether set-up screens (the default), and what it was: the tests and
/// benchmarks compare renders with and without the screen in one process.
bool use_coverage_screen(bool on);
bool coverage_screen_in_use();

/// Triangles screened per call at most (the caller's verdict array).
constexpr std::size_t kScreenBlock = 64;

/// The screen's TinyCoverage of a block's triangles, in lanes (valid where
/// the verdict is ScreenVerdict::tiny_covered).
struct TinyCoverageBlock {
    alignas(32) double e[3][kScreenBlock];
    alignas(32) double column_step[3][kScreenBlock];
    alignas(32) double row_step[3][kScreenBlock];
    alignas(32) double area2[kScreenBlock];  ///< signed: < 0 where the corners were swapped
    alignas(32) double column_min[kScreenBlock];
    alignas(32) double row_min[kScreenBlock];
    alignas(32) std::uint8_t covered[kScreenBlock];

    /// Triangle `lane` of the block.
    void get(std::size_t lane, TinyCoverage& out) const {
        for (int i = 0; i < 3; ++i) {
            out.e[i] = e[i][lane];
            out.column_step[i] = column_step[i][lane];
            out.row_step[i] = row_step[i][lane];
        }
        out.swapped = area2[lane] < 0.0;
        out.area2 = out.swapped ? -area2[lane] : area2[lane];
        out.column_min = static_cast<int>(column_min[lane]);
        out.row_min = static_cast<int>(row_min[lane]);
        out.covered = covered[lane];
    }
};

/// Writes the verdict of triangles [begin, end) (at most kScreenBlock) to
/// verdicts[0 .. end - begin), with the instruction set kernel_isa() names.
/// With `tiny`, a triangle drawn whole in a box of at most 2 x 2 centres is
/// ScreenVerdict::tiny_covered, its coverage in `tiny`; without, set_up.
void screen_coverage_dispatched(const CoverageScreenInput& in, std::size_t begin, std::size_t end,
                                ScreenVerdict* verdicts, TinyCoverageBlock* tiny = nullptr);

#if PHONGRAST_HAVE_AVX2_KERNELS
/// screen_coverage() compiled for AVX2 (coverage_screen_avx2.cpp).
void screen_coverage_avx2(const CoverageScreenInput& in, std::size_t begin, std::size_t end, ScreenVerdict* verdicts,
                          TinyCoverageBlock* tiny);
#endif

inline namespace PHONGRAST_LANES_ISA {

namespace screen_lanes {
// As wide as the instruction set's registers (coverage_screen_avx2.cpp sets
// 4; the target pragma does not define __AVX__ for the preprocessor), so that
// no vector argument changes the calling convention.
#ifndef PHONGRAST_SCREEN_LANES
#define PHONGRAST_SCREEN_LANES 2
#endif
constexpr std::size_t kLanes = PHONGRAST_SCREEN_LANES;
using Doubles = double __attribute__((vector_size(8 * kLanes)));
using Mask = decltype(Doubles{} < Doubles{});  // 64-bit lanes: -1 where true

/// Rounds integers-to-be to the nearest, ties to even (the default mode, as
/// llrint in snap()): exact for |x| < 2^51; larger lanes fail `exact` below.
inline Doubles round_nearest(Doubles x) {
    const Doubles magic = Doubles{} + 6755399441055744.0;  // 1.5 x 2^52
    return (x + magic) - magic;
}
inline Doubles select(Mask m, Doubles yes, Doubles no) { return m ? yes : no; }
inline Doubles maximum(Doubles a, Doubles b) { return a > b ? a : b; }
inline Doubles minimum(Doubles a, Doubles b) { return a < b ? a : b; }
/// 1.0 where m is set, else 0.0.
inline Doubles ones_where(Mask m) { return m ? Doubles{} + 1.0 : Doubles{}; }
/// floor(x / 256) and ceil(x / 256) for integer x: the division is exact (a power of two).
inline Doubles floor_256(Doubles x) {
    const Doubles q = x * (1.0 / double(kSubpixelScale)), r = round_nearest(q);
    return r - ones_where(r > q);
}
inline Doubles ceil_256(Doubles x) {
    const Doubles q = x * (1.0 / double(kSubpixelScale)), r = round_nearest(q);
    return r + ones_where(r < q);
}

/// The edge from p to q at the box's first centre c, less its top-left
/// threshold (edge_value(), CoveredRows::set_up_edge()), and its changes to
/// the next column and row: a centre is covered when all three edges are >= 0.
struct BiasedEdge {
    Doubles first, column_step, row_step, threshold;
};
inline BiasedEdge biased_edge(Doubles px, Doubles py, Doubles qx, Doubles qy, Doubles cx, Doubles cy) {
    const Doubles dx = qx - px, dy = qy - py;
    const Doubles threshold = ones_where((2.0 * dy - ones_where(dx > 0.0)) >= 0.0);
    const double scale = double(kSubpixelScale);
    return {dx * (cy - py) - dy * (cx - px) - threshold, -dy * scale, dx * scale, threshold};
}
inline void store(double* to, Doubles value) { __builtin_memcpy(to, &value, sizeof value); }
}  // namespace screen_lanes

/// See screen_coverage_dispatched().
inline void screen_coverage(const CoverageScreenInput& in, std::size_t begin, std::size_t end,
                            ScreenVerdict* verdicts, TinyCoverageBlock* tiny) {
    using namespace screen_lanes;
    // The corners in lanes: [corner][block triangle], rounded up to whole lane groups.
    alignas(32) double column[3][kScreenBlock], row[3][kScreenBlock], depth[3][kScreenBlock];
    const std::size_t count = end - begin;
    const std::size_t padded = (count + kLanes - 1) / kLanes * kLanes;
    for (std::size_t t = 0; t < padded; ++t) {
        const Triangle& tri = in.triangles[begin + (t < count ? t : 0)];
        for (int i = 0; i < 3; ++i) {
            const ScreenVertex& s = in.screen[tri[i]];
            column[i][t] = s.column;
            row[i][t] = s.row;
            depth[i][t] = s.depth;
        }
    }
    const double scale = double(kSubpixelScale);
    std::uint8_t lane_verdicts[kScreenBlock];
    for (std::size_t t = 0; t < padded; t += kLanes) {
        Doubles x[3], y[3];
        Mask eligible = Mask{} - 1;
        for (int i = 0; i < 3; ++i) {
            Doubles c, r, z;
            __builtin_memcpy(&c, &column[i][t], sizeof c);
            __builtin_memcpy(&r, &row[i][t], sizeof r);
            __builtin_memcpy(&z, &depth[i][t], sizeof z);
            // run(): inside the image (VertexStage::inside_image), within drawable depth, not clipped by the near plane.
            const Doubles shifted_c = c + in.column_offset, shifted_r = r + in.row_offset;
            eligible &= (shifted_c >= 0.0) & (shifted_c <= in.columns) & (shifted_r >= 0.0) &
                        (shifted_r <= in.rows) & (z >= in.min_depth) & (z <= in.max_depth);
            x[i] = round_nearest(c * scale);  // snap()
            y[i] = round_nearest(r * scale);
        }
        const Doubles x_min = minimum(minimum(x[0], x[1]), x[2]), x_max = maximum(maximum(x[0], x[1]), x[2]);
        const Doubles y_min = minimum(minimum(y[0], y[1]), y[2]), y_max = maximum(maximum(y[0], y[1]), y[2]);
        // Every product below is at most the box's width x height: under 2^50, each is
        // exact and so are their sums (and the snapped coordinates, 2^28 at most, too).
        const Mask exact = ((x_max - x_min) * (y_max - y_min) < 0x1p50) & (x_max - x_min < 0x1p30) &
                           (y_max - y_min < 0x1p30);
        const Doubles area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
        // setup_coverage(): the centres (256 j + 128) in the box, clamped to the image.
        const Doubles half = Doubles{} + double(kHalfPixel);
        const Doubles column_min = maximum(ceil_256(x_min - half), Doubles{});
        const Doubles column_max = minimum(floor_256(x_max - half), Doubles{} + (in.columns - 1.0));
        const Doubles row_min = maximum(ceil_256(y_min - half), Doubles{});
        const Doubles row_max = minimum(floor_256(y_max - half), Doubles{} + (in.rows - 1.0));
        const Mask empty = (column_min > column_max) | (row_min > row_max);
        const Mask tiny_box = ~empty & (row_max - row_min < 2.0) & (column_max - column_min < 2.0);
        // may_cover_a_centre(): the box's (at most four) centres, the vertices ordered so that area2 > 0.
        const Mask swapped = area2 < 0.0;
        const Doubles x1 = select(swapped, x[2], x[1]), y1 = select(swapped, y[2], y[1]);
        const Doubles x2 = select(swapped, x[1], x[2]), y2 = select(swapped, y[1], y[2]);
        const Doubles cx = column_min * scale + half, cy = row_min * scale + half;
        const BiasedEdge e0 = biased_edge(x1, y1, x2, y2, cx, cy);
        const BiasedEdge e1 = biased_edge(x2, y2, x[0], y[0], cx, cy);
        const BiasedEdge e2 = biased_edge(x[0], y[0], x1, y1, cx, cy);
        const Doubles zero{};
        const auto covered_at = [&](const Doubles& v0, const Doubles& v1, const Doubles& v2) {
            return (v0 >= zero) & (v1 >= zero) & (v2 >= zero);
        };
        const Mask second_column = column_max > column_min, second_row = row_max > row_min;
        const Doubles r0 = e0.first + e0.row_step, r1 = e1.first + e1.row_step, r2 = e2.first + e2.row_step;
        // Each centre of the box: first row, first and second column, then the second row's.
        const Mask covered_00 = covered_at(e0.first, e1.first, e2.first);
        const Mask covered_01 = second_column & covered_at(e0.first + e0.column_step, e1.first + e1.column_step,
                                                           e2.first + e2.column_step);
        const Mask covered_10 = second_row & covered_at(r0, r1, r2);
        const Mask covered_11 = second_column & second_row &
                                covered_at(r0 + e0.column_step, r1 + e1.column_step, r2 + e2.column_step);
        const Mask covered = covered_00 | covered_01 | covered_10 | covered_11;
        const Mask decided = eligible & exact;
        const Mask degenerate = decided & (area2 == 0.0);
        const Mask between = decided & ~(area2 == 0.0) & (empty | (tiny_box & ~covered));
        Mask verdict = (degenerate & static_cast<long>(ScreenVerdict::degenerate)) |
                       (between & static_cast<long>(ScreenVerdict::between_samples));
        if (tiny != nullptr) {
            const Mask drawn_tiny = decided & ~(area2 == 0.0) & tiny_box & covered;
            verdict |= drawn_tiny & static_cast<long>(ScreenVerdict::tiny_covered);
            const Mask bits = (covered_00 & 1L) | (covered_01 & 2L) | (covered_10 & 4L) | (covered_11 & 8L);
            const BiasedEdge* edges[3] = {&e0, &e1, &e2};
            for (int i = 0; i < 3; ++i) {
                store(&tiny->e[i][t], edges[i]->first + edges[i]->threshold);
                store(&tiny->column_step[i][t], edges[i]->column_step);
                store(&tiny->row_step[i][t], edges[i]->row_step);
            }
            store(&tiny->area2[t], area2);
            store(&tiny->column_min[t], column_min);
            store(&tiny->row_min[t], row_min);
            for (std::size_t lane = 0; lane < kLanes; ++lane) tiny->covered[t + lane] = static_cast<std::uint8_t>(bits[lane]);
        }
        for (std::size_t lane = 0; lane < kLanes; ++lane) lane_verdicts[t + lane] = static_cast<std::uint8_t>(verdict[lane]);
    }
    __builtin_memcpy(verdicts, lane_verdicts, count);
}

}  // namespace PHONGRAST_LANES_ISA
}  // namespace phongrast::detail

#undef PHONGRAST_SCREEN_LANES

#endif  // PHONGRAST_SRC_COVERAGE_SCREEN_HPP
