// The fill kernels' texture lookup (texture_at() in src/fill_phong_lanes.hpp)
// skips fmod and the wrap modes when every texel it reads lies inside the
// image. That shortcut must give bit for bit what the general path gives:
// here both paths look up the same (s, t), inside, on and across every edge,
// far outside, at texel centres and borders, for every wrap mode, filter,
// precision and a few image sizes (1 x 1 and one-row images included).
// texel_lanes() (bilinear_lanes(): the lookup of a batch of samples in vector
// loops, what the textured kernels call) must give texture_at()'s bits lane
// for lane, for batches mixing samples inside and outside the image.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_kernels.hpp"

using namespace phongrast;

namespace {

template <typename Real>
bool same_bits(const Vec3<Real>& a, const Vec3<Real>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// (s, t) to look up on an image of the size given: a grid through texel
/// centres and borders from two periods before the image to two after, and
/// random points in and far out of it.
std::vector<float> coordinates(int size, std::mt19937& random) {
    std::vector<float> values;
    for (int k = -16 * size; k <= 24 * size; ++k) values.push_back(float(k) / float(8 * size));
    std::uniform_real_distribution<float> near(-0.2f, 1.2f), far(-1e4f, 1e4f);
    for (int k = 0; k < 40; ++k) values.push_back(near(random));
    for (int k = 0; k < 8; ++k) values.push_back(far(random));
    values.push_back(1e30f);  // x out of range in float: T = 1 either way
    return values;
}

template <typename Real>
void check_fast_path_matches_general(int rows, int columns) {
    std::mt19937 random(static_cast<std::uint32_t>(rows * 131 + columns));
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec3> texels(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    for (glm::vec3& texel : texels) texel = glm::vec3(unit(random), unit(random), unit(random));
    const std::vector<float> s_values = coordinates(columns, random), t_values = coordinates(rows, random);
    const TextureWrap wraps[] = {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat};
    for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest}) {
        for (TextureWrap wrap_s : wraps) {
            for (TextureWrap wrap_t : wraps) {
                detail::KernelTexture texture;
                texture.texels = texels.data();
                texture.rows = rows;
                texture.columns = columns;
                texture.wrap_s = wrap_s;
                texture.wrap_t = wrap_t;
                texture.filter = filter;
                int mismatches = 0;
                for (float s : s_values) {
                    for (float t : t_values) {
                        const Vec3<Real> fast = detail::texture_at<Real>(texture, Real(s), Real(t));
                        const Vec3<Real> general = detail::texture_at<Real, true>(texture, Real(s), Real(t));
                        if (!same_bits(fast, general)) ++mismatches;
                    }
                }
                INFO(rows << " x " << columns << ", " << to_string(filter) << ", wrap " << to_string(wrap_s)
                          << " / " << to_string(wrap_t));
                CHECK(mismatches == 0);
            }
        }
    }
}

/// Every (s, t) of the grid through texel_lanes() in batches of every length
/// up to kSampleBatch (so lanes inside and outside the image share batches),
/// against texture_at() one at a time.
template <typename Real>
void check_lanes_match_one_at_a_time(int rows, int columns) {
    std::mt19937 random(static_cast<std::uint32_t>(rows * 977 + columns));
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> texels(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    for (glm::vec3& texel : texels) texel = glm::vec3(unit(random), unit(random), unit(random));
    std::vector<float> s_values = coordinates(columns, random), t_values = coordinates(rows, random);
    s_values.push_back(std::numeric_limits<float>::quiet_NaN());
    t_values.push_back(-std::numeric_limits<float>::infinity());
    std::vector<std::pair<Real, Real>> points;
    for (float s : s_values) {
        for (float t : t_values) points.emplace_back(Real(s), Real(t));
    }
    std::shuffle(points.begin(), points.end(), random);
    constexpr int kBatch = detail::kSampleBatch;
    const TextureWrap wraps[] = {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat};
    for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest}) {
        for (TextureWrap wrap : wraps) {
            detail::KernelTexture texture;
            texture.texels = texels.data();
            texture.rows = rows;
            texture.columns = columns;
            texture.wrap_s = wrap;
            texture.wrap_t = wraps[(static_cast<int>(wrap) + 1) % 3];
            texture.filter = filter;
            int mismatches = 0, inside = 0;
            std::size_t next = 0;
            for (int n = 1; next < points.size(); n = n % kBatch + 1) {
                const int count = static_cast<int>(std::min<std::size_t>(n, points.size() - next));
                detail::Lanes<Real> s, t, lanes[3];
                for (int l = 0; l < count; ++l) {
                    s[l] = points[next + l].first;
                    t[l] = points[next + l].second;
                }
                detail::texel_lanes(texture, count, s, t, lanes);
                for (int l = 0; l < count; ++l) {
                    const Vec3<Real> one = detail::texture_at<Real>(texture, s[l], t[l]);
                    const Vec3<Real> lane(lanes[0][l], lanes[1][l], lanes[2][l]);
                    if (!same_bits(one, lane)) ++mismatches;
                    if (s[l] >= Real(0.5) / Real(columns) && s[l] < Real(1) - Real(0.5) / Real(columns) &&
                        t[l] >= Real(0.5) / Real(rows) && t[l] < Real(1) - Real(0.5) / Real(rows)) {
                        ++inside;
                    }
                }
                next += static_cast<std::size_t>(count);
            }
            INFO(rows << " x " << columns << ", " << to_string(filter) << ", wrap " << to_string(texture.wrap_s)
                      << " / " << to_string(texture.wrap_t));
            CHECK(mismatches == 0);
            if (rows >= 2 && columns >= 2) CHECK(inside > 0);  // the vector path was taken
        }
    }
}

}  // namespace

TEST_CASE("texture lookup: a batch of samples in vector loops gives one lookup at a time's bits", "[texture]") {
    for (const auto& size : {std::pair{1, 1}, std::pair{1, 6}, std::pair{6, 1}, std::pair{2, 2}, std::pair{5, 3},
                             std::pair{16, 16}, std::pair{64, 48}}) {
        check_lanes_match_one_at_a_time<float>(size.first, size.second);
        check_lanes_match_one_at_a_time<double>(size.first, size.second);
    }
}

TEST_CASE("texture lookup: the inside-the-image shortcut gives the general path's bits", "[texture]") {
    for (const auto& size : {std::pair{1, 1}, std::pair{1, 6}, std::pair{2, 2}, std::pair{5, 3}, std::pair{16, 16}}) {
        check_fast_path_matches_general<float>(size.first, size.second);
        check_fast_path_matches_general<double>(size.first, size.second);
    }
}

TEST_CASE("texture lookup: inside the image, bilinear at a texel centre is that texel", "[texture]") {
    // A check that the comparison above is not of two equally wrong lookups.
    const std::vector<glm::vec3> texels = {{0.1f, 0.2f, 0.3f}, {0.4f, 0.5f, 0.6f}, {0.7f, 0.8f, 0.9f},
                                           {0.15f, 0.25f, 0.35f}, {0.45f, 0.55f, 0.65f}, {0.75f, 0.85f, 0.95f}};
    detail::KernelTexture texture;
    texture.texels = texels.data();
    texture.rows = 2;
    texture.columns = 3;
    // Column 1 of row 0 (the top row, t near 1): centre at s = 1.5 / 3, t = 1 - 0.5 / 2.
    const Vec3<double> top_middle = detail::texture_at<double>(texture, 0.5, 0.75);
    CHECK(top_middle == Vec3<double>(texels[1]));
    // Halfway between the rows' centres of column 0: the mean of texels 0 and 3.
    const Vec3<double> between = detail::texture_at<double>(texture, 0.5 / 3.0, 0.5);
    CHECK(between.x == Approx(0.5 * (0.1 + 0.15)));
    CHECK(between.z == Approx(0.5 * (0.3 + 0.35)));
}
