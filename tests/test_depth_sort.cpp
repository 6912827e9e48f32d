// The painter's sort gives std::stable_sort's order exactly.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "painter_order.hpp"

using phongrast::detail::farthest_first_order;

namespace {

std::vector<std::uint32_t> reference_order(const std::vector<double>& depth) {
    std::vector<std::uint32_t> order(depth.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&depth](std::uint32_t a, std::uint32_t b) { return depth[a] > depth[b]; });
    return order;
}

/// n depths uniform in [low, high), every `stride`-th one then set to the
/// one at index i / `back` before it: exact ties among close values.
std::vector<double> close_depths_with_ties(unsigned seed, double low, double high, std::size_t n, std::size_t stride,
                                           std::size_t back) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> spread(low, high);
    std::vector<double> depth(n);
    for (double& d : depth) d = spread(random);
    for (std::size_t i = 0; i < depth.size(); i += stride) depth[i] = depth[i / back];
    return depth;
}

}  // namespace

TEST_CASE("radix painter's order equals a stable sort, ties in mesh order") {
    std::mt19937_64 random(8);
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(100), std::size_t(255), std::size_t(256),
                          std::size_t(5000), std::size_t(70000)}) {
        std::vector<double> depth(n);
        std::uniform_real_distribution<double> spread(-5.0, 20.0);
        std::uniform_int_distribution<int> pick(0, 9);
        for (double& d : depth) {
            // Many exact ties, both zeros, negatives (behind the eye), tiny and huge values.
            switch (pick(random)) {
                case 0: d = 3.0; break;
                case 1: d = 0.0; break;
                case 2: d = -0.0; break;
                case 3: d = 1e-300; break;
                case 4: d = -1e300; break;
                case 5: d = std::nextafter(3.0, 4.0); break;
                default: d = spread(random);
            }
        }
        INFO("n = " << n);
        CHECK(farthest_first_order(depth) == reference_order(depth));
    }
}

TEST_CASE("radix painter's order of depths sharing their high bits") {
    // Depths in [7, 7.001): sign, exponent and leading mantissa bits equal, so passes are skipped.
    const std::vector<double> depth = close_depths_with_ties(9, 7.0, 7.001, 20000, 7, 2);
    CHECK(farthest_first_order(depth) == reference_order(depth));
}

TEST_CASE("painter's order when most depths fall into one leading-bits bucket") {
    // One far outlier stretches the keys' range, so the leading bits put
    // nearly every other depth into one bucket, too large to sort in cache:
    // it is split again by the next bits. Ties and nearby values throughout.
    std::vector<double> depth = close_depths_with_ties(10, 2.0, 2.0001, 60000, 5, 3);
    depth[12345] = 1e12;
    depth[23456] = -1e12;
    CHECK(farthest_first_order(depth) == reference_order(depth));
    std::fill(depth.begin(), depth.end(), 4.25);  // every key equal: mesh order
    CHECK(farthest_first_order(depth) == reference_order(depth));
}
