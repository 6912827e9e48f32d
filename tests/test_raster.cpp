// Coverage is exact: pixel centres, 1/256-pixel snapping, top-left tie rule.
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "raster.hpp"

using namespace phongrast::detail;

namespace {

struct Point {
    double column, row;
};

/// Counts, per pixel, how many of the triangles cover its centre.
std::vector<int> coverage_counts(const std::vector<std::array<Point, 3>>& triangles, int rows, int columns) {
    std::vector<int> counts(std::size_t(rows) * columns, 0);
    for (const auto& t : triangles) {
        CoverageTriangle setup;
        if (!setup_coverage(snap(t[0].column, t[0].row), snap(t[1].column, t[1].row), snap(t[2].column, t[2].row),
                            rows, columns, setup)) {
            continue;
        }
        for_each_covered_pixel(setup, 0, rows, [&](int row, int column, std::int64_t, std::int64_t, std::int64_t) {
            ++counts[std::size_t(row) * columns + column];
        });
    }
    return counts;
}

/// The square [lo, hi]^2 as a jittered grid of n x n cells, each split along a
/// random diagonal, in random winding. Boundary vertices stay on the boundary;
/// jitter below a quarter cell keeps every quad convex, so either diagonal is valid.
/// With `on_centres`, every vertex sits exactly on a pixel centre.
std::vector<std::array<Point, 3>> random_square_triangulation(double lo, double hi, int n, unsigned seed,
                                                              bool on_centres) {
    std::mt19937 rng(seed);
    const double cell = (hi - lo) / n;
    std::uniform_real_distribution<double> jitter(-0.2 * cell, 0.2 * cell);
    std::vector<Point> grid(std::size_t(n + 1) * (n + 1));
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            double column = lo + j * cell, row = lo + i * cell;
            if (j > 0 && j < n) column += jitter(rng);
            if (i > 0 && i < n) row += jitter(rng);
            if (on_centres) {
                column = std::floor(column) + 0.5;
                row = std::floor(row) + 0.5;
            }
            grid[std::size_t(i) * (n + 1) + j] = {column, row};
        }
    }
    std::vector<std::array<Point, 3>> triangles;
    std::bernoulli_distribution coin(0.5);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Point a = grid[std::size_t(i) * (n + 1) + j], b = grid[std::size_t(i) * (n + 1) + j + 1];
            const Point c = grid[std::size_t(i + 1) * (n + 1) + j + 1], d = grid[std::size_t(i + 1) * (n + 1) + j];
            std::array<Point, 3> t1{a, b, c}, t2{a, c, d};
            if (coin(rng)) {
                t1 = {a, b, d};
                t2 = {b, c, d};
            }
            if (coin(rng)) std::swap(t1[1], t1[2]);
            if (coin(rng)) std::swap(t2[1], t2[2]);
            triangles.push_back(t1);
            triangles.push_back(t2);
        }
    }
    return triangles;
}

}  // namespace

TEST_CASE("a randomly triangulated square covers every pixel inside exactly once") {
    const int size = 100;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        // Corners at 10.3 and 89.7: no centre lies on the square's own border.
        const auto triangles = random_square_triangulation(10.3, 89.7, 12, seed, false);
        const std::vector<int> counts = coverage_counts(triangles, size, size);
        int wrong = 0;
        for (int row = 0; row < size; ++row) {
            for (int column = 0; column < size; ++column) {
                const bool inside = column >= 10 && column <= 89 && row >= 10 && row <= 89;
                wrong += counts[std::size_t(row) * size + column] != (inside ? 1 : 0);
            }
        }
        INFO("seed " << seed);
        CHECK(wrong == 0);
    }
}

TEST_CASE("ties: vertices exactly on pixel centres still cover each pixel once") {
    const int size = 100;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        // Corners on the centres 10.5 and 90.5: the top and left borders own
        // their centres, the bottom and right ones do not, so columns and rows
        // 10..89 are covered.
        const auto triangles = random_square_triangulation(10.5, 90.5, 10, seed, true);
        const std::vector<int> counts = coverage_counts(triangles, size, size);
        int wrong = 0;
        for (int row = 0; row < size; ++row) {
            for (int column = 0; column < size; ++column) {
                const bool inside = column >= 10 && column <= 89 && row >= 10 && row <= 89;
                wrong += counts[std::size_t(row) * size + column] != (inside ? 1 : 0);
            }
        }
        INFO("seed " << seed);
        CHECK(wrong == 0);
    }
}

TEST_CASE("top-left rule on a single axis-aligned triangle") {
    // Right triangle with its corner on centres: (2.5,2.5), (6.5,2.5), (2.5,6.5).
    // The top edge (row 2.5) and the left edge (column 2.5) own their centres;
    // the hypotenuse owns none of the centres exactly on it.
    const std::vector<std::array<Point, 3>> triangle{{{{2.5, 2.5}, {6.5, 2.5}, {2.5, 6.5}}}};
    const std::vector<int> counts = coverage_counts(triangle, 10, 10);
    int covered = 0;
    for (int row = 0; row < 10; ++row) {
        for (int column = 0; column < 10; ++column) {
            const double x = column + 0.5, y = row + 0.5;
            const bool expected = x >= 2.5 && y >= 2.5 && (x - 2.5) + (y - 2.5) < 4.0;
            INFO("pixel " << row << "," << column);
            CHECK(counts[std::size_t(row) * 10 + column] == (expected ? 1 : 0));
            covered += counts[std::size_t(row) * 10 + column];
        }
    }
    CHECK(covered == 10);  // 4 + 3 + 2 + 1
}

TEST_CASE("a fan of thin triangles around a centre covers each pixel once at every angle") {
    const int size = 64;
    for (int spokes : {7, 60, 360}) {
        std::vector<std::array<Point, 3>> fan;
        const Point centre{32.0, 32.0};  // a pixel corner; 32.5 would be a centre
        for (int k = 0; k < spokes; ++k) {
            const double a0 = 2 * M_PI * k / spokes, a1 = 2 * M_PI * (k + 1) / spokes;
            fan.push_back({centre, Point{32 + 60 * std::cos(a0), 32 + 60 * std::sin(a0)},
                           Point{32 + 60 * std::cos(a1), 32 + 60 * std::sin(a1)}});
        }
        const std::vector<int> counts = coverage_counts(fan, size, size);
        int wrong = 0;
        for (int c : counts) wrong += c != 1;  // the radius-60 fan spans the whole 64x64 image
        INFO(spokes << " spokes");
        CHECK(wrong == 0);
    }
}

TEST_CASE("zero-area and centre-free triangles cover nothing") {
    CoverageTriangle setup;
    // Collinear.
    CHECK_FALSE(setup_coverage(snap(1, 1), snap(5, 5), snap(9, 9), 10, 10, setup));
    // Repeated vertex.
    CHECK_FALSE(setup_coverage(snap(1, 1), snap(1, 1), snap(9, 2), 10, 10, setup));
    // Entirely right of the image.
    CHECK_FALSE(setup_coverage(snap(11, 1), snap(15, 1), snap(12, 5), 10, 10, setup));
    // Tiny, between centres.
    CHECK_FALSE(setup_coverage(snap(1.6, 1.6), snap(1.9, 1.6), snap(1.6, 1.9), 10, 10, setup));
}

TEST_CASE("edge values are barycentric numerators") {
    CoverageTriangle setup;
    REQUIRE(setup_coverage(snap(0.5, 0.5), snap(8.5, 0.5), snap(0.5, 8.5), 10, 10, setup));
    bool saw_corner = false;
    for_each_covered_pixel(setup, 0, 10, [&](int row, int column, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
        CHECK(e0 + e1 + e2 == setup.area2());
        if (row == 0 && column == 0) {
            saw_corner = true;
            CHECK(e0 == setup.area2());  // at vertex 0 all weight is on vertex 0
        }
    });
    CHECK(saw_corner);
}
