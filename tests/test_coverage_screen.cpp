// Set-up's coverage screen (coverage_screen.hpp): whole triangles that
// certainly cover no sample centre, decided in vector lanes before set-up.
// Its verdicts must be exactly what set-up's own scalar tests find (raster.hpp:
// snap(), setup_coverage(), may_cover_a_centre(), after run()'s image and
// depth tests) on every triangle it decides, in every instruction set; and a
// render must paint the same bits and count the same triangles with and
// without it, culling back faces or not.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "clipping.hpp"
#include "coverage_screen.hpp"
#include "fill_dispatch.hpp"
#include "fill_driver.hpp"
#include "raster.hpp"
#include "same_render_stats.hpp"
#include "support/meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using detail::CoverageScreenInput;
using detail::ScreenVerdict;
using detail::ScreenVertex;

namespace {

/// The coverage set-up gives a whole triangle inside the frame, by its own function.
detail::CoverageTriangle set_up_coverage(const CoverageScreenInput& in, const phongrast::Triangle& tri, bool& box) {
    const ScreenVertex& a = in.screen[tri[0]];
    const ScreenVertex& b = in.screen[tri[1]];
    const ScreenVertex& c = in.screen[tri[2]];
    detail::CoverageTriangle coverage;
    box = detail::setup_coverage(detail::snap(a.column, a.row), detail::snap(b.column, b.row),
                                 detail::snap(c.column, c.row), static_cast<int>(in.rows), static_cast<int>(in.columns),
                                 coverage);
    return coverage;
}

/// What TriangleSetup::run() and set_up_piece() conclude for a triangle, by
/// their own functions: set_up where it is not a whole triangle that covers
/// nothing, or (what the screen finds when asked for it) tiny_covered where
/// it is a whole one drawn in a box of at most 2 x 2 centres.
ScreenVerdict set_up_verdict(const CoverageScreenInput& in, double near_depth, const phongrast::Triangle& tri) {
    for (std::uint32_t index : tri) {
        const ScreenVertex& s = in.screen[index];
        const double c = s.column + in.column_offset, r = s.row + in.row_offset;
        const bool inside = s.depth > 0.0 && c >= 0.0 && c <= in.columns && r >= 0.0 && r <= in.rows;
        const bool drawable = s.depth <= in.max_depth || s.depth < 0.0;
        if (!inside || !drawable || !(s.depth >= near_depth)) return ScreenVerdict::set_up;
    }
    bool box = false;
    const detail::CoverageTriangle coverage = set_up_coverage(in, tri, box);
    if (!box) return coverage.area2() == 0 ? ScreenVerdict::degenerate : ScreenVerdict::between_samples;
    if (!detail::may_cover_a_centre(coverage)) return ScreenVerdict::between_samples;
    const bool tiny = coverage.row_max - coverage.row_min < 2 && coverage.column_max - coverage.column_min < 2;
    return tiny ? ScreenVerdict::tiny_covered : ScreenVerdict::set_up;
}

/// The verdict of a screen not asked for tiny triangles.
ScreenVerdict without_tiny(ScreenVerdict verdict) {
    return verdict == ScreenVerdict::tiny_covered ? ScreenVerdict::set_up : verdict;
}

/// Checks the screen's TinyCoverage of a tiny covered triangle against set-up's
/// coverage and the fill's spans (for_each_covered_pixel(): the centres covered
/// and the exact edge values at each).
void check_tiny_coverage(const CoverageScreenInput& in, const phongrast::Triangle& tri, const detail::TinyCoverage& got) {
    bool box = false;
    const detail::CoverageTriangle coverage = set_up_coverage(in, tri, box);
    REQUIRE(box);
    CHECK(got.swapped == coverage.swapped);
    CHECK(got.area2 == double(coverage.area2()));
    CHECK(got.column_min == coverage.column_min);
    CHECK(got.row_min == coverage.row_min);
    unsigned covered = 0;
    detail::for_each_covered_pixel(coverage, coverage.row_min, coverage.row_max + 1,
                                   [&](int row, int column, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
        const int r = row - coverage.row_min, c = column - coverage.column_min;
        covered |= 1u << (2 * r + c);
        const std::int64_t e[3] = {e0, e1, e2};
        for (int i = 0; i < 3; ++i) {
            CHECK(got.e[i] + got.row_step[i] * r + got.column_step[i] * c == double(e[i]));
        }
    });
    CHECK(got.covered == covered);
}

/// A coordinate on the 1/256 grid, often exactly on a sample centre or a
/// pixel edge (where the top-left rule decides), sometimes between grid points.
double grid_coordinate(std::mt19937& random, double low, double high) {
    std::uniform_real_distribution<double> uniform(low, high);
    const double x = uniform(random);
    switch (random() % 4) {
        case 0: return std::floor(x) + 0.5;        // a centre
        case 1: return std::round(x * 256.0) / 256.0;  // a grid point
        case 2: return std::floor(x * 2.0) / 2.0;  // a centre or a pixel edge
        default: return x;                         // snapped by the screen and by set-up alike
    }
}

/// Vertices of a frame of `columns` x `rows` samples: most inside it and in
/// front of the near plane at 0.5, the rest past a border, behind the near
/// plane or the eye, too far, or NaN (a vertex not in front of the eye).
std::vector<ScreenVertex> screen_vertices(std::mt19937& random, double columns, double rows, std::size_t count) {
    std::vector<ScreenVertex> vertices;
    for (std::size_t i = 0; i < count; ++i) {
        ScreenVertex v{grid_coordinate(random, -0.2, columns + 0.2), grid_coordinate(random, -0.2, rows + 0.2),
                       1.0 + double(random() % 100)};
        switch (random() % 24) {
            case 0: v.depth = 0.25; break;                                      // behind the near plane
            case 1: v.depth = -3.0; break;                                      // behind the eye
            case 2: v.depth = 2e30; break;                                      // past float's drawable depth
            case 3: v.depth = 0.5; break;                                       // on the near plane
            case 4: v.column = v.row = std::numeric_limits<double>::quiet_NaN(); v.depth = -1.0; break;
            case 5: v.depth = std::numeric_limits<double>::quiet_NaN(); break;  // an overflowed transform
            case 6: v.column = columns; break;                                  // on the border
            case 7: v.row = 0.0; break;
            default: break;
        }
        vertices.push_back(v);
    }
    return vertices;
}

/// Triangles of those vertices: any three, three near each other (boxes of
/// a few centres: the tiny test), collinear ones and ones with a repeated corner.
std::vector<phongrast::Triangle> screen_triangles(std::mt19937& random, std::vector<ScreenVertex>& vertices,
                                               std::size_t count) {
    std::vector<phongrast::Triangle> triangles;
    const auto any = [&] { return static_cast<std::uint32_t>(random() % vertices.size()); };
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t a = any();
        switch (random() % 5) {
            case 0: triangles.push_back({a, any(), any()}); break;
            case 1: triangles.push_back({a, a, any()}); break;  // degenerate
            case 2: {  // collinear: the middle of two corners
                const std::uint32_t b = any();
                ScreenVertex mid = vertices[a];
                mid.column = (vertices[a].column + vertices[b].column) / 2.0;
                mid.row = (vertices[a].row + vertices[b].row) / 2.0;
                vertices.push_back(mid);
                triangles.push_back({a, b, static_cast<std::uint32_t>(vertices.size() - 1)});
                break;
            }
            default: {  // within about two pixels of corner a
                const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
                for (int k = 0; k < 2; ++k) {
                    ScreenVertex near_a = vertices[a];
                    near_a.column += grid_coordinate(random, -1.6, 1.6);
                    near_a.row += grid_coordinate(random, -1.6, 1.6);
                    vertices.push_back(near_a);
                }
                triangles.push_back({a, first, first + 1});
                break;
            }
        }
    }
    return triangles;
}

/// The screen as set-up calls it, in kScreenBlock blocks from `begin`; with
/// `tiny`, as the walk calls it, each tiny covered triangle's coverage there.
std::vector<ScreenVerdict> screened(const CoverageScreenInput& in, std::size_t begin, std::size_t end,
                                    std::vector<detail::TinyCoverage>* tiny = nullptr) {
    std::vector<ScreenVerdict> verdicts(end - begin);
    if (tiny != nullptr) tiny->assign(end - begin, detail::TinyCoverage{});
    detail::TinyCoverageBlock block;
    for (std::size_t from = begin; from < end; from += detail::kScreenBlock) {
        const std::size_t to = std::min(end, from + detail::kScreenBlock);
        detail::screen_coverage_dispatched(in, from, to, verdicts.data() + (from - begin),
                                           tiny != nullptr ? &block : nullptr);
        for (std::size_t t = from; tiny != nullptr && t < to; ++t) block.get(t - from, (*tiny)[t - begin]);
    }
    return verdicts;
}

}  // namespace

TEST_CASE("the coverage screen decides a whole triangle exactly as set-up's tests do, in every instruction set") {
    std::mt19937 random(20261129);
    for (const glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(0.125, -0.375)}) {
        const double columns = 9, rows = 6, near_depth = 0.5;
        std::vector<ScreenVertex> vertices = screen_vertices(random, columns, rows, 400);
        const std::vector<phongrast::Triangle> triangles = screen_triangles(random, vertices, 4000);
        CoverageScreenInput in;
        in.triangles = triangles.data();
        in.screen = vertices.data();
        in.column_offset = offset.x;
        in.row_offset = offset.y;
        in.columns = columns;
        in.rows = rows;
        in.min_depth = near_depth;
        in.max_depth = detail::kMaxDrawableDepth<float>;
        std::size_t expected_decided = 0;
        for (const phongrast::Triangle& tri : triangles) {
            expected_decided += without_tiny(set_up_verdict(in, near_depth, tri)) != ScreenVerdict::set_up;
        }
        // Not a vacuous comparison: many triangles of each kind.
        CHECK(expected_decided > triangles.size() / 5);
        for (detail::KernelIsa isa : {detail::KernelIsa::baseline, detail::KernelIsa::avx2}) {
            if (!detail::kernel_isa_available(isa)) {
                WARN("skipped: the AVX2 copy of the screen (this CPU has no AVX2)");
                continue;
            }
            detail::override_kernel_isa(isa);
            // From 0, and from 3: blocks whose last lane group is not full.
            for (std::size_t begin : {std::size_t(0), std::size_t(3)}) {
                const std::vector<ScreenVerdict> verdicts = screened(in, begin, triangles.size());
                std::vector<detail::TinyCoverage> tiny;
                const std::vector<ScreenVerdict> walk_verdicts = screened(in, begin, triangles.size(), &tiny);
                std::size_t counts[4] = {};
                for (std::size_t t = begin; t < triangles.size(); ++t) {
                    const ScreenVerdict expected = set_up_verdict(in, near_depth, triangles[t]);
                    const ScreenVerdict got = verdicts[t - begin];
                    INFO("triangle " << t << ", ISA " << int(isa) << ", offset " << offset.x);
                    // Every value is exact on this small frame: the screen decides all it may.
                    REQUIRE(int(got) == int(without_tiny(expected)));
                    REQUIRE(int(walk_verdicts[t - begin]) == int(expected));
                    if (expected == ScreenVerdict::tiny_covered) check_tiny_coverage(in, triangles[t], tiny[t - begin]);
                    ++counts[int(walk_verdicts[t - begin])];
                }
                CHECK(counts[int(ScreenVerdict::degenerate)] > 50);
                CHECK(counts[int(ScreenVerdict::between_samples)] > 200);
                CHECK(counts[int(ScreenVerdict::tiny_covered)] > 200);
            }
        }
        detail::override_kernel_isa(std::nullopt);
    }
}

TEST_CASE("the coverage screen leaves to set-up what its doubles might not compute exactly") {
    // A sliver across a huge frame: its box is 2^27 x 2^27 subpixels, whose
    // products need 2^54: the screen must not decide it (set-up's 64-bit
    // integers do), even though this one covers no centre.
    const double side = double(1 << 19);
    const std::vector<ScreenVertex> vertices = {{0.25, 0.25, 2.0}, {side - 0.25, side - 0.25, 2.0},
                                                {side - 0.25 - 1.0 / 256.0, side - 0.25, 2.0}};
    const std::vector<phongrast::Triangle> triangles = {{0, 1, 2}};
    CoverageScreenInput in;
    in.triangles = triangles.data();
    in.screen = vertices.data();
    in.columns = in.rows = side;
    in.min_depth = 0.5;
    in.max_depth = detail::kMaxDrawableDepth<double>;
    ScreenVerdict verdict = ScreenVerdict::degenerate;
    detail::screen_coverage_dispatched(in, 0, 1, &verdict);
    CHECK(verdict == ScreenVerdict::set_up);
}

TEST_CASE("a render paints the same bits and counts with the coverage screen and without it") {
    // A sphere of about 20,000 triangles on 48 x 40 pixels: most cover no
    // centre; some cross the image's border (clipped, or dropped in seed mode; not screened).
    Scene scene;
    scene.mesh = support::uv_sphere(100, 100, 1.0);
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.3 + 0.2 * p.z));
    }
    scene.camera.eye = {0.3, 0.4, 2.4};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.3;
    scene.image = {40, 48, {0.1f, 0.2f, 0.3f}};
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}};
    scene.material.ks = glm::vec3(0.5f);
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
            for (int threads : {1, 2}) {
                for (int samples : {1, 2}) {
                    scene.shader = shader;
                    RenderOptions options = mode.options;
                    options.threads = threads;
                    options.samples_per_axis = samples;
                    options.sample_pattern = SamplePattern::rotated_grid;  // sample offsets: shifted geometry
                    // Culling counts a back face before any coverage test: the screen must then stand aside.
                    options.back_faces = threads == 2 ? BackFaces::cull_when_hidden : BackFaces::draw;
                    INFO(to_string(shader) << ", " << mode.name << ", " << threads << " threads, " << samples
                                           << " samples per axis");
                    const RenderResult screened_render = render(scene, options);
                    const bool was = detail::use_coverage_screen(false);
                    const RenderResult plain = render(scene, options);
                    detail::use_coverage_screen(was);
                    CHECK(test_render_modes::same_bits(screened_render.image, plain.image));
                    check_same_render_stats(screened_render.stats, plain.stats);
                    CHECK(screened_render.stats.triangles_between_samples > (threads == 2 ? 100u : 1000u));
                    // The seed-faithful mode draws back faces whatever the option says.
                    const bool culls = threads == 2 && mode.name.rfind("exact", 0) == 0;
                    CHECK((screened_render.stats.triangles_culled > 0) == culls);
                    CHECK(screened_render.stats.triangles_clipped + screened_render.stats.triangles_dropped > 0);
                }
            }
        }
    }
}
