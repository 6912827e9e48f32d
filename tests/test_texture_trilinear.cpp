// The trilinear texture filter (GL_LINEAR_MIPMAP_LINEAR, docs/accuracy.md
// "Trilinear"): the mip pyramid by hand on tiny textures (even and odd sizes),
// built once and shared; the level of detail lambda and the two-level lookup
// against the double-precision reference; rendered pixels of a screen-aligned
// quad (lambda known exactly, with and without supersampling) and of a
// slanted quad (lambda from finite differences of the uv output), where the
// magnified foreground is bilinear bit for bit and the far part is not; every
// shader; degenerate and huge texture coordinates.
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_kernels.hpp"
#include "phongrast/render.hpp"
#include "phongrast/texture.hpp"
#include "resolve.hpp"
#include "textured_quad.hpp"

using namespace phongrast;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// rows x columns texels, texel (i, j) = (j, i, i * columns + j): sums are exact in float.
std::shared_ptr<TextureImage> indexed_texture(int rows, int columns) {
    auto image = std::make_shared<TextureImage>();
    image->rows = rows;
    image->columns = columns;
    image->name = "indexed";
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) image->texels.push_back(glm::vec3(float(j), float(i), float(i * columns + j)));
    }
    return image;
}

/// rows x columns random texels in [0, 1]: every level differs from the next.
std::shared_ptr<const TextureImage> random_texture(int rows, int columns, unsigned seed) {
    auto image = std::make_shared<TextureImage>();
    image->rows = rows;
    image->columns = columns;
    image->name = "random";
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int k = 0; k < rows * columns; ++k) image->texels.push_back(glm::vec3(unit(random), unit(random), unit(random)));
    return image;
}

TextureMap map_of(std::shared_ptr<const TextureImage> image, TextureWrap s = TextureWrap::repeat,
                  TextureWrap t = TextureWrap::repeat) {
    TextureMap map;
    map.image = std::move(image);
    map.wrap_s = s;
    map.wrap_t = t;
    return map;
}

double largest_difference(const glm::dvec3& a, const glm::dvec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

/// textured_quad_scene() of the quad over `corners` with (s, t) `st`.
Scene textured_quad_scene(const glm::dvec3 (&corners)[4], const glm::vec2 (&st)[4], const TextureMap& map, int size) {
    return ::textured_quad_scene(textured_quad_mesh(corners, st, map), size);
}

/// The screen-filling quad with (s, t) from (0, 0) at the lower left to `repeat` at the upper right.
Scene screen_quad(const TextureMap& map, int size, float repeat) {
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {repeat, 0.0f}, {repeat, repeat}, {0.0f, repeat}};
    return textured_quad_scene(corners, st, map, size);
}

/// A floor seen at an angle: a 0.6 x 0.8 rectangle tilted 75 degrees about x,
/// (s, t) = (u, v) over it, so its near edge is magnified and its far edge
/// minified; all of it inside the image (seed mode drops triangles across the border).
Scene slanted_floor(const TextureMap& map, int size) {
    const double angle = 75.0 * 3.14159265358979323846 / 180.0, side = 0.8;
    const glm::dvec3 p0(-0.3, -0.3, 0.2), e1(0.6, 0.0, 0.0), e2(0.0, side * std::cos(angle), -side * std::sin(angle));
    const glm::dvec3 corners[4] = {p0, p0 + e1, p0 + e1 + e2, p0 + e2};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    return textured_quad_scene(corners, st, map, size);
}

bool same_bits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("the mip pyramid of a 4 x 4 texture: 2 x 2 boxes down to 1 x 1, by hand") {
    const auto image = indexed_texture(4, 4);
    const std::vector<MipLevel>& levels = image->mip_levels();
    REQUIRE(levels.size() == 2);
    REQUIRE(levels[0].rows == 2);
    REQUIRE(levels[0].columns == 2);
    // z = 4 i + j: each texel of level 1 is the mean of a 2 x 2 block.
    CHECK(levels[0].at(0, 0) == glm::vec3(0.5f, 0.5f, (0 + 1 + 4 + 5) / 4.0f));
    CHECK(levels[0].at(0, 1) == glm::vec3(2.5f, 0.5f, (2 + 3 + 6 + 7) / 4.0f));
    CHECK(levels[0].at(1, 0) == glm::vec3(0.5f, 2.5f, (8 + 9 + 12 + 13) / 4.0f));
    CHECK(levels[0].at(1, 1) == glm::vec3(2.5f, 2.5f, (10 + 11 + 14 + 15) / 4.0f));
    REQUIRE(levels[1].rows == 1);
    REQUIRE(levels[1].columns == 1);
    CHECK(levels[1].at(0, 0) == glm::vec3(1.5f, 1.5f, 7.5f));
    // Asked again: the same levels, not built again.
    CHECK(&image->mip_levels() == &levels);
    CHECK(image->mip_levels().data() == levels.data());
}

TEST_CASE("the mip pyramid of odd sizes: floor(n / 2) texels, each the area mean of the n / floor(n / 2) texels under it") {
    // 3 rows x 5 columns: level 1 is 1 x 2. Along the columns each texel of
    // level 1 covers 2.5 texels: columns 0, 1 and half of 2 (weights 0.4, 0.4,
    // 0.2), then half of 2, 3 and 4; along the rows all three, 1/3 each.
    const auto image = indexed_texture(3, 5);
    const std::vector<MipLevel>& levels = image->mip_levels();
    REQUIRE(levels.size() == 2);
    REQUIRE(levels[0].rows == 1);
    REQUIRE(levels[0].columns == 2);
    const auto close = [](const glm::vec3& a, const glm::vec3& b) {
        return largest_difference(glm::dvec3(a), glm::dvec3(b)) < 1e-6;
    };
    // x = j: 0.4 * 0 + 0.4 * 1 + 0.2 * 2 = 0.8; y = i: 1; z = 5 i + j: 5 + 0.8.
    CHECK(close(levels[0].at(0, 0), glm::vec3(0.8f, 1.0f, 5.8f)));
    // x: 0.2 * 2 + 0.4 * 3 + 0.4 * 4 = 3.2; z = 5 + 3.2.
    CHECK(close(levels[0].at(0, 1), glm::vec3(3.2f, 1.0f, 8.2f)));
    REQUIRE(levels[1].rows == 1);
    REQUIRE(levels[1].columns == 1);
    CHECK(close(levels[1].at(0, 0), glm::vec3(2.0f, 1.0f, 7.0f)));  // the mean of the whole image
    // 3 x 3 goes to 1 x 1 at once: the mean of all nine.
    const auto square = indexed_texture(3, 3);
    REQUIRE(square->mip_levels().size() == 1);
    CHECK(close(square->mip_levels()[0].at(0, 0), glm::vec3(1.0f, 1.0f, 4.0f)));
    // One row of 8: 4, 2, 1 columns, the rows staying 1.
    const auto row = indexed_texture(1, 8);
    REQUIRE(row->mip_levels().size() == 3);
    CHECK(row->mip_levels()[0].rows == 1);
    CHECK(row->mip_levels()[0].columns == 4);
    CHECK(row->mip_levels()[2].columns == 1);
    CHECK(close(row->mip_levels()[2].at(0, 0), glm::vec3(3.5f, 0.0f, 3.5f)));
    // 1 x 1 is its own last level: no pyramid below it.
    CHECK(indexed_texture(1, 1)->mip_levels().empty());
    // An image whose texels do not match its size gets none either (validation refuses it before any render).
    auto broken = indexed_texture(2, 2);
    broken->texels.pop_back();
    CHECK(broken->mip_levels().empty());
}

TEST_CASE("the pyramid is built once per image, whichever threads ask first, and a copy builds its own") {
    const auto image = random_texture(64, 32, 7);
    std::vector<const std::vector<MipLevel>*> seen(4, nullptr);
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < seen.size(); ++k) {
        threads.emplace_back([&, k] { seen[k] = &image->mip_levels(); });
    }
    for (std::thread& thread : threads) thread.join();
    for (const auto* levels : seen) CHECK(levels == seen[0]);
    REQUIRE(seen[0]->size() == 6);  // 32 x 16, 16 x 8, 8 x 4, 4 x 2, 2 x 1, 1 x 1
    CHECK((*seen[0])[4].rows == 2);
    CHECK((*seen[0])[4].columns == 1);
    const TextureImage copy = *image;
    CHECK(&copy.mip_levels() != seen[0]);
    REQUIRE(copy.mip_levels().size() == seen[0]->size());
    CHECK(copy.mip_levels().back().texels == seen[0]->back().texels);
}

TEST_CASE("lambda: log2 of the longer step in level-0 texels, with degenerate and non-finite derivatives") {
    // A step of 1/64 in s on 256 columns is 4 texels: lambda 2.
    CHECK(mip_lambda(1.0 / 64.0, 0.0, 0.0, 1.0 / 64.0, 256, 256) == 2.0);
    // The longer of the two steps counts: (3, 4) texels is 5 long.
    CHECK(mip_lambda(3.0 / 256.0, 4.0 / 128.0, 0.0, 1.0 / 128.0, 256, 128) == Approx(std::log2(5.0)));
    CHECK(mip_lambda(0.0, 0.0, 0.0, 0.0, 16, 16) == -kInfinity);  // degenerate uv: magnified, level 0
    CHECK(mip_lambda(kInfinity, 0.0, 0.0, 0.0, 16, 16) == kInfinity);
    CHECK(mip_lambda(0.0, 0.0, std::nan(""), 0.0, 16, 16) == kInfinity);
    CHECK(mip_lambda(std::nan(""), 0.0, 0.0, 0.0, 16, 16) == kInfinity);

    detail::KernelTexture texture;
    texture.rows = texture.columns = 256;
    CHECK(detail::texture_lambda<float>(texture, 1.0f / 64.0f, 0.0f, 0.0f, 1.0f / 64.0f) == 2.0f);
    CHECK(detail::texture_lambda<double>(texture, 0.0, 1.0 / 32.0, 1.0 / 64.0, 0.0) == 3.0);
    CHECK(detail::texture_lambda<float>(texture, 0.0f, 0.0f, 0.0f, 0.0f) == -std::numeric_limits<float>::infinity());
    CHECK(detail::texture_lambda<float>(texture, 1e30f, 0.0f, 0.0f, 0.0f) == std::numeric_limits<float>::infinity());
    CHECK(detail::texture_lambda<float>(texture, 0.0f, std::nanf(""), 0.0f, 0.0f) ==
          std::numeric_limits<float>::infinity());
    CHECK(detail::texture_lambda<float>(texture, 0.0f, 0.0f, 0.0f, -std::numeric_limits<float>::infinity()) ==
          std::numeric_limits<float>::infinity());
}

namespace {

template <typename Real>
void check_lookup_matches_reference(TextureWrap wrap_s, TextureWrap wrap_t, double tolerance) {
    const auto image = random_texture(16, 8, 3);
    const TextureMap map = map_of(image, wrap_s, wrap_t);
    const std::vector<MipLevel>& levels = image->mip_levels();
    detail::KernelTexture texture;
    texture.texels = image->texels.data();
    texture.rows = image->rows;
    texture.columns = image->columns;
    texture.wrap_s = wrap_s;
    texture.wrap_t = wrap_t;
    texture.filter = TextureFilter::trilinear;
    texture.mip_levels = levels.data();
    texture.mip_level_count = static_cast<int>(levels.size());
    detail::KernelTexture bilinear = texture;
    bilinear.filter = TextureFilter::bilinear;
    const double lambdas[] = {-kInfinity, -1.0, 0.0, 0.25, 1.0, 1.5, 2.75, 3.5, 4.0, 7.0, kInfinity, std::nan("")};
    double largest = 0.0;
    int off_by_a_level = 0;
    for (double lambda : lambdas) {
        for (double s = -1.3; s <= 2.3; s += 0.07) {
            for (double t = -1.1; t <= 2.1; t += 0.09) {
                const Vec3<Real> value =
                    detail::texture_at_trilinear<Real>(texture, Real(s), Real(t), static_cast<Real>(lambda));
                const glm::dvec3 expected = sample_trilinear(map, double(Real(s)), double(Real(t)), lambda);
                largest = std::max(largest, largest_difference(glm::dvec3(value), expected));
                if (lambda <= 0.0) {
                    // Magnified: the bilinear lookup on level 0, bit for bit.
                    const Vec3<Real> level0 = detail::texture_at<Real>(bilinear, Real(s), Real(t));
                    if (std::memcmp(&value, &level0, sizeof value) != 0) ++off_by_a_level;
                }
            }
        }
    }
    CHECK(largest <= tolerance);
    CHECK(off_by_a_level == 0);
    // The levels differ, so these checks could fail: level 1 is not level 0, nor 4 (1 x 1) level 3.
    CHECK(largest_difference(sample_trilinear(map, 0.3, 0.6, 0.0), sample_trilinear(map, 0.3, 0.6, 1.0)) > 1e-3);
    // The last level (1 x 1, the image's mean) wherever one looks.
    CHECK(largest_difference(sample_trilinear(map, 0.3, 0.6, 4.0), sample_trilinear(map, 0.9, 0.1, 9.0)) < 1e-12);
    CHECK(sample_trilinear(map, 0.3, 0.6, std::nan("")) == sample_trilinear(map, 0.3, 0.6, 4.0));
    // Halfway between two levels: the mean of both.
    const glm::dvec3 halfway = sample_trilinear(map, 0.3, 0.6, 1.5);
    CHECK(largest_difference(halfway, 0.5 * (sample_trilinear(map, 0.3, 0.6, 1.0) + sample_trilinear(map, 0.3, 0.6, 2.0))) <
          1e-12);
}

}  // namespace

TEST_CASE("the kernels' trilinear lookup against the double reference, each wrap mode, every level") {
    for (TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat}) {
        check_lookup_matches_reference<float>(wrap, TextureWrap::repeat, 2e-6);
        check_lookup_matches_reference<double>(TextureWrap::repeat, wrap, 1e-12);
    }
}

TEST_CASE("a screen-aligned quad minified 4 times: every pixel is level 2, with 2 x 2 samples level 1 at each sample") {
    const int size = 64;
    const TextureMap map = map_of(random_texture(256, 256, 11));
    const Scene scene = screen_quad(map, size, 1.0f);  // 256 texels over 64 pixels
    RenderOptions options = RenderOptions::exact();
    options.texture_filter = TextureFilter::trilinear;
    for (Precision precision : {Precision::single_float, Precision::double_float}) {
        options.precision = precision;
        const Image image = render(scene, options).image;
        double largest = 0.0, from_bilinear = 0.0;
        for (int i = 0; i < size; ++i) {
            for (int j = 0; j < size; ++j) {
                const double s = (j + 0.5) / size, t = 1.0 - (i + 0.5) / size;
                const glm::dvec3 pixel(image.at(i, j));
                largest = std::max(largest, largest_difference(pixel, sample_trilinear(map, s, t, 2.0)));
                from_bilinear = std::max(from_bilinear, largest_difference(pixel, sample_bilinear(map, s, t)));
            }
        }
        CHECK(largest < 1e-5);
        CHECK(from_bilinear > 0.1);  // level 2 is not level 0: the check above could fail
    }
    // Supersampled, each sample's footprint is its share of the pixel: 2 texels, lambda 1,
    // on the ordered grid (one render at twice the size) and the rotated grid (four renders with offsets).
    options.precision = Precision::single_float;
    options.samples_per_axis = 2;
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        options.sample_pattern = pattern;
        const Image image = render(scene, options).image;
        double largest = 0.0;
        for (int i = 0; i < size; ++i) {
            for (int j = 0; j < size; ++j) {
                glm::dvec3 sum(0.0);
                for (int a = 0; a < 2; ++a) {
                    for (int b = 0; b < 2; ++b) {
                        const glm::dvec2 offset = pattern == SamplePattern::ordered_grid
                                                      ? glm::dvec2(0.5 * b - 0.25, 0.5 * a - 0.25)
                                                      : detail::rotated_grid_offset(a, b, 2);
                        const double s = (j + 0.5 + offset.x) / size, t = 1.0 - (i + 0.5 + offset.y) / size;
                        sum += sample_trilinear(map, s, t, 1.0);
                    }
                }
                largest = std::max(largest, largest_difference(glm::dvec3(image.at(i, j)), sum / 4.0));
            }
        }
        INFO((pattern == SamplePattern::ordered_grid ? "ordered grid" : "rotated grid"));
        CHECK(largest < 1e-5);
    }
}

namespace {

/// For the slanted floor: per pixel, lambda from central differences of the
/// uv output (-infinity where a neighbour is not on the quad, or, with
/// `same_triangle`, not on the same triangle).
std::vector<double> lambda_from_uv(const RenderResult& result, const TextureImage& image, bool same_triangle) {
    const int rows = result.image.rows, columns = result.image.columns;
    std::vector<double> lambda(result.image.pixels.size(), -kInfinity);
    const auto at = [&](int i, int j) { return std::size_t(i) * std::size_t(columns) + std::size_t(j); };
    for (int i = 1; i + 1 < rows; ++i) {
        for (int j = 1; j + 1 < columns; ++j) {
            const std::int32_t id = result.aovs.id[at(i, j)];
            bool usable = id >= 0;
            for (std::size_t n : {at(i - 1, j), at(i + 1, j), at(i, j - 1), at(i, j + 1)}) {
                usable = usable && result.aovs.id[n] >= 0 && (!same_triangle || result.aovs.id[n] == id);
            }
            if (!usable) continue;
            const glm::dvec2 dx = 0.5 * (glm::dvec2(result.aovs.uv[at(i, j + 1)]) - glm::dvec2(result.aovs.uv[at(i, j - 1)]));
            const glm::dvec2 dy = 0.5 * (glm::dvec2(result.aovs.uv[at(i + 1, j)]) - glm::dvec2(result.aovs.uv[at(i - 1, j)]));
            lambda[at(i, j)] = mip_lambda(dx.x, dx.y, dy.x, dy.y, image.columns, image.rows);
        }
    }
    return lambda;
}

}  // namespace

TEST_CASE("a floor seen at an angle: lambda follows the derivatives of (s, t), exact and seed mode") {
    const int size = 96;
    const auto texture = random_texture(32, 32, 5);
    const TextureMap map = map_of(texture);
    const Scene scene = slanted_floor(map, size);
    for (bool seed : {false, true}) {
        INFO((seed ? "seed" : "exact"));
        RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
        options.texture_filter = TextureFilter::trilinear;
        options.precision = Precision::double_float;
        options.aovs.uv = options.aovs.id = true;
        const RenderResult result = render(scene, options);
        // Seed mode's (s, t) is linear per triangle: its derivatives change at the diagonal.
        const std::vector<double> lambda = lambda_from_uv(result, *texture, seed);
        int magnified = 0, minified = 0, checked = 0;
        double lowest = kInfinity, highest = -kInfinity;
        double largest = 0.0;
        for (std::size_t p = 0; p < lambda.size(); ++p) {
            if (lambda[p] == -kInfinity) continue;
            ++checked;
            lowest = std::min(lowest, lambda[p]);
            highest = std::max(highest, lambda[p]);
            magnified += lambda[p] < -0.2;
            minified += lambda[p] > 0.5;
            const glm::vec2 st = result.aovs.uv[p];
            const glm::dvec3 expected = sample_trilinear(map, st.x, st.y, lambda[p]);
            largest = std::max(largest, largest_difference(glm::dvec3(result.image.pixels[p]), expected));
        }
        INFO("pixels checked " << checked << ", magnified " << magnified << ", minified " << minified
                                << ", largest difference " << std::scientific << largest << ", lambda "
                                << lowest << " to " << highest);
        CHECK(checked > 1000);
        if (seed) {
            // One lambda per triangle, both between levels 0 and 1; the
            // differences are exact there (the uv output is linear too).
            CHECK(lowest > 0.0);
            CHECK(highest - lowest > 0.05);
            CHECK(largest < 1e-5);
        } else {
            CHECK(magnified > 100);  // the near part is magnified ...
            CHECK(minified > 100);   // ... the far part minified
            // Central differences of a perspective division differ a little from its derivative.
            CHECK(largest < 1e-3);
        }
    }
}

TEST_CASE("the floor at an angle: the magnified foreground is bilinear bit for bit, the far part is not") {
    const int size = 96;
    const auto texture = random_texture(32, 32, 5);
    const TextureMap map = map_of(texture);
    const Scene scene = slanted_floor(map, size);
    RenderOptions options = RenderOptions::exact();
    options.aovs.uv = options.aovs.id = true;
    const RenderResult bilinear = render(scene, options);
    options.texture_filter = TextureFilter::trilinear;
    const RenderResult trilinear = render(scene, options);
    CHECK(trilinear.stats.nonfinite_values_replaced == 0);
    const std::vector<double> lambda = lambda_from_uv(bilinear, *texture, false);
    int near_same = 0, near_differ = 0, far_same = 0, far_differ = 0;
    for (std::size_t p = 0; p < lambda.size(); ++p) {
        const bool same = same_bits(bilinear.image.pixels[p], trilinear.image.pixels[p]);
        if (lambda[p] != -kInfinity && lambda[p] < -0.05) (same ? near_same : near_differ) += 1;
        if (lambda[p] > 0.5) (same ? far_same : far_differ) += 1;
        // Off the quad (the background) both are the same.
        if (bilinear.aovs.id[p] < 0) CHECK(same);
    }
    CHECK(near_same > 100);
    CHECK(near_differ == 0);
    CHECK(far_differ > 100);
    CHECK(far_same < far_differ / 20);
}

TEST_CASE("Gouraud and flat draw trilinear textures as Phong does: T x A + S with T from the same lookup") {
    const TextureMap map = map_of(random_texture(32, 32, 9));
    Scene scene = slanted_floor(map, 48);
    for (bool seed : {false, true}) {
        RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
        options.texture_filter = TextureFilter::trilinear;
        CHECK_NOTHROW(validate_render(scene, options));
        scene.shader = Shader::phong;
        const Image phong = render(scene, options).image;
        RenderOptions bilinear_options = options;
        bilinear_options.texture_filter = TextureFilter::bilinear;
        const Image bilinear = render(scene, bilinear_options).image;
        for (Shader shader : {Shader::gouraud, Shader::flat}) {
            INFO(to_string(shader) << (seed ? ", seed" : ", exact"));
            scene.shader = shader;
            const RenderResult result = render(scene, options);
            CHECK(result.stats.nonfinite_values_replaced == 0);
            double largest = 0.0, from_bilinear = 0.0;
            for (std::size_t p = 0; p < phong.pixels.size(); ++p) {
                // Only ambient light: A = 1 (interpolated, for Gouraud: within rounding), S = 0.
                largest = std::max(largest, largest_difference(glm::dvec3(result.image.pixels[p]), glm::dvec3(phong.pixels[p])));
                from_bilinear = std::max(from_bilinear, largest_difference(glm::dvec3(result.image.pixels[p]),
                                                                           glm::dvec3(bilinear.pixels[p])));
            }
            CHECK(largest < 1e-5);
            CHECK(from_bilinear > 0.05);
        }
    }
}

TEST_CASE("trilinear on degenerate and huge texture coordinates: level 0, the last level, never NaN") {
    const TextureMap map = map_of(random_texture(16, 16, 13));
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    RenderOptions options = RenderOptions::exact();
    options.texture_filter = TextureFilter::trilinear;
    RenderOptions bilinear = RenderOptions::exact();
    // Every corner at the same (s, t): zero derivatives, lambda -infinity, level 0: bilinear's picture.
    const glm::vec2 same[4] = {{0.3f, 0.7f}, {0.3f, 0.7f}, {0.3f, 0.7f}, {0.3f, 0.7f}};
    const Scene degenerate = textured_quad_scene(corners, same, map, 16);
    const RenderResult flat = render(degenerate, options);
    CHECK(flat.image.pixels == render(degenerate, bilinear).image.pixels);
    CHECK(flat.stats.nonfinite_values_replaced == 0);
    // Coordinates near float's limit: derivatives overflow to infinity, lambda
    // +infinity, the last level (1 x 1: the image's mean) or T = 1 where s W overflows.
    const glm::vec2 huge[4] = {{-3e38f, 0.0f}, {3e38f, 0.0f}, {3e38f, 3e38f}, {-3e38f, 3e38f}};
    const Scene overflowing = textured_quad_scene(corners, huge, map, 16);
    const RenderResult result = render(overflowing, options);
    CHECK(result.stats.nonfinite_values_replaced == 0);
    const glm::dvec3 mean = sample_trilinear(map, 0.5, 0.5, kInfinity);
    for (const glm::vec3& pixel : result.image.pixels) {
        REQUIRE(std::isfinite(pixel.x + pixel.y + pixel.z));
        const bool last_level = largest_difference(glm::dvec3(pixel), mean) < 1e-5;
        CHECK((last_level || pixel == glm::vec3(1.0f)));
    }
    // Moderately large ones (a texture repeated a million times over 16 pixels): the last level everywhere.
    const glm::vec2 repeated[4] = {{0.0f, 0.0f}, {1e6f, 0.0f}, {1e6f, 1e6f}, {0.0f, 1e6f}};
    const Image far = render(textured_quad_scene(corners, repeated, map, 16), options).image;
    for (const glm::vec3& pixel : far.pixels) CHECK(largest_difference(glm::dvec3(pixel), mean) < 1e-5);
}
