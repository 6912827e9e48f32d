// The accuracy report's machinery (tests/support/: image_compare, pareto, accuracy_configurations, scenes): error metrics,
// Pareto front, configuration enumeration, and three properties of the
// report on small images.
#include <algorithm>
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"
#include "support/accuracy_configurations.hpp"
#include "support/image_compare.hpp"
#include "support/pareto.hpp"
#include "support/scenes.hpp"

using namespace phongrast;
using namespace phongrast::support;

namespace {

Image render_configuration(Scene scene, const Configuration& c) {
    scene.shader = c.shader;
    return render(scene, c.options).image;
}

}  // namespace

TEST_CASE("metrics: identical images have zero error and infinite PSNR") {
    const Image image(4, 5, glm::vec3(0.3f, 0.6f, 0.9f));
    const ErrorMetrics m = compare(image, image);
    CHECK(m.rmse == 0.0);
    CHECK(m.max_abs == 0.0);
    CHECK(m.share_off == 0.0);
    CHECK(m.psnr_db == std::numeric_limits<double>::infinity());
}

TEST_CASE("metrics: one pixel off by 0.5 in one channel of a 2x2 image") {
    const Image reference(2, 2, glm::vec3(0.25f));
    Image image = reference;
    image.at(1, 0).y = 0.75f;
    const ErrorMetrics m = compare(image, reference);
    // Twelve channel values, one off by 0.5: RMSE = sqrt(0.25 / 12).
    CHECK(m.rmse == Approx(std::sqrt(0.25 / 12.0)));
    CHECK(m.psnr_db == Approx(20.0 * std::log10(1.0 / std::sqrt(0.25 / 12.0))));
    CHECK(m.max_abs == Approx(0.5));
    CHECK(m.share_off == Approx(0.25));
    const std::vector<double> map = error_map(image, reference);
    CHECK(map[2] == Approx(0.5));
    CHECK(map[0] == 0.0);
}

TEST_CASE("metrics: values are compared as displayed, clamped to [0, 1], and 1/255 is not 'off'") {
    const Image reference(1, 2, glm::vec3(1.0f));
    Image image(1, 2, glm::vec3(3.0f));   // over-exposed: shows as 1
    image.at(0, 1) = glm::vec3(1.0f - 0.9f / 255.0f);  // less than one level below
    const ErrorMetrics m = compare(image, reference);
    CHECK(m.share_off == 0.0);
    CHECK(m.max_abs < kOneLevel);
    CHECK(m.max_abs > 0.0);
}

TEST_CASE("pareto front: keeps the non-dominated points, fastest first") {
    //                          0    1    2    3    4    5
    const std::vector<double> time{1.0, 2.0, 2.0, 3.0, 5.0, 4.0};
    const std::vector<double> error{9.0, 5.0, 6.0, 5.0, 1.0, 2.0};
    // 2 is beaten by 1 (same time, less error); 3 by 1 (faster, same error).
    CHECK(pareto_front(time, error) == std::vector<std::size_t>{0, 1, 5, 4});
    CHECK(dominates(2.0, 5.0, 3.0, 5.0));
    CHECK_FALSE(dominates(2.0, 5.0, 2.0, 5.0));
    CHECK(pareto_front({}, {}).empty());
}

TEST_CASE("configurations: one switch away differs in exactly one axis, and the product is complete") {
    const std::vector<NamedConfiguration> seed = one_switch_away("seed", seed_configuration(Shader::phong));
    // seed itself + 2 shaders + vectors + interpolation + visibility + border + 4 samplings + precision.
    CHECK(seed.size() == 1 + 2 + 1 + 1 + 1 + 1 + 4 + 1);
    std::vector<std::string> keys;
    for (const NamedConfiguration& c : seed) keys.push_back(key(c.configuration));
    std::sort(keys.begin(), keys.end());
    CHECK(std::unique(keys.begin(), keys.end()) == keys.end());

    const std::vector<Configuration> all = every_combination();
    CHECK(all.size() == 480);
    std::vector<std::string> all_keys;
    for (const Configuration& c : all) all_keys.push_back(key(c));
    std::sort(all_keys.begin(), all_keys.end());
    CHECK(std::unique(all_keys.begin(), all_keys.end()) == all_keys.end());
    for (const std::string& k : keys) CHECK(std::binary_search(all_keys.begin(), all_keys.end(), k));
}

TEST_CASE("report: the reference against itself has zero error") {
    const Scene scene = sphere_scene(32).scene;
    const Image a = render_configuration(scene, reference_configuration());
    const Image b = render_configuration(scene, reference_configuration());
    CHECK(compare(a, b).rmse == 0.0);
    CHECK(compare(a, b).max_abs == 0.0);
}

TEST_CASE("report: more samples never increase the error on a smooth scene") {
    const Scene scene = sphere_scene(48).scene;
    const Image reference = render_configuration(scene, reference_configuration());
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        double previous = std::numeric_limits<double>::infinity();
        for (int per_axis : {1, 2, 4}) {
            Configuration c = reference_configuration();
            c.options.samples_per_axis = per_axis;
            c.options.sample_pattern = pattern;
            const double rmse = compare(render_configuration(scene, c), reference).rmse;
            INFO("pattern " << int(pattern) << ", " << per_axis << "x" << per_axis << ": RMSE " << rmse);
            CHECK(rmse > 0.0);  // only the reference's own 8x8 grid reaches zero
            CHECK(rmse <= previous);
            previous = rmse;
        }
    }
}

TEST_CASE("report: the exact preset beats the seed preset on the close-up floor") {
    const Scene scene = floor_scene(48).scene;
    const Image reference = render_configuration(scene, reference_configuration());
    const ErrorMetrics seed = compare(render_configuration(scene, seed_configuration(Shader::phong)), reference);
    const ErrorMetrics exact = compare(render_configuration(scene, exact_configuration(Shader::phong)), reference);
    INFO("seed RMSE " << seed.rmse << ", exact RMSE " << exact.rmse);
    CHECK(exact.rmse < seed.rmse);
    CHECK(exact.share_off < seed.share_off);
}
