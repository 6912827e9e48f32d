// The stage clock behind `bench_speed_once --stages` (stage_times.hpp):
// off, nothing is recorded; on, each render pass records the stages it ran
// (set-up, painter's order, binning and fill for the sorted fill, the walks
// for the fill in mesh order, the extra outputs when asked) and none it
// skipped, one record per pass, and the picture is the one it paints off.
#include <algorithm>
#include <cstring>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_driver.hpp"
#include "stage_times.hpp"
#include "support/scenes.hpp"

using namespace phongrast;
using detail::PassStageTimes;
using detail::Stage;

namespace {

double seconds_of(const PassStageTimes& pass, Stage stage) { return pass[static_cast<std::size_t>(stage)]; }

/// Records the passes of one render, with the recording on for it only.
std::vector<PassStageTimes> passes_of(const Scene& scene, const RenderOptions& options, RenderResult& result) {
    detail::take_stage_times();
    const bool was = detail::record_stage_times(true);
    result = render(scene, options);
    detail::record_stage_times(was);
    return detail::take_stage_times();
}

bool same_pixels(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

}  // namespace

TEST_CASE("the stage clock records nothing while off") {
    const Scene scene = support::sphere_scene(64).scene;
    detail::record_stage_times(false);
    detail::take_stage_times();
    render(scene, RenderOptions::exact());
    CHECK(detail::take_stage_times().empty());
}

TEST_CASE("the stage clock records each pass's stages, only those it ran, and changes no pixel") {
    Scene scene = support::sphere_scene(64).scene;
    scene.shader = Shader::phong;
    RenderOptions options = RenderOptions::exact();
    const Image unclocked = render(scene, options).image;
    RenderResult clocked;

    SECTION("the sorted fill: set-up, painter's order, binning, fill; no walk, no extra outputs") {
        const std::vector<PassStageTimes> passes = passes_of(scene, options, clocked);
        REQUIRE(passes.size() == 1);
        for (Stage stage : {Stage::vertices, Stage::setup, Stage::painter_order, Stage::binning, Stage::fill}) {
            INFO(detail::stage_name(stage));
            CHECK(seconds_of(passes[0], stage) > 0.0);
        }
        CHECK(seconds_of(passes[0], Stage::walk) == 0.0);
        CHECK(seconds_of(passes[0], Stage::extra_outputs) == 0.0);
        CHECK(same_pixels(clocked.image, unclocked));
    }
    SECTION("extra outputs asked for: their pass is timed too") {
        options.aovs.depth = true;
        const std::vector<PassStageTimes> passes = passes_of(scene, options, clocked);
        REQUIRE(passes.size() == 1);
        CHECK(seconds_of(passes[0], Stage::extra_outputs) > 0.0);
        CHECK(same_pixels(clocked.image, unclocked));
    }
    SECTION("the fill in mesh order: walks, and no set-up, sort, binning or fill of its own") {
        scene.lighting = Lighting::only_ambient();
        const Image ambient = render(scene, options).image;
        const auto was = detail::set_mesh_order_walk_choice(detail::WalkChoice::always);
        const std::vector<PassStageTimes> passes = passes_of(scene, options, clocked);
        detail::set_mesh_order_walk_choice(was);
        REQUIRE(passes.size() == 1);
        CHECK(seconds_of(passes[0], Stage::walk) > 0.0);
        for (Stage stage : {Stage::setup, Stage::painter_order, Stage::binning, Stage::fill}) {
            INFO(detail::stage_name(stage));
            CHECK(seconds_of(passes[0], stage) == 0.0);
        }
        CHECK(same_pixels(clocked.image, ambient));
    }
    SECTION("supersampled on a rotated grid: one record per pass") {
        options.samples_per_axis = 2;
        options.sample_pattern = SamplePattern::rotated_grid;
        const std::vector<PassStageTimes> passes = passes_of(scene, options, clocked);
        CHECK(passes.size() == 4);
        CHECK(std::all_of(passes.begin(), passes.end(),
                          [](const PassStageTimes& pass) { return seconds_of(pass, Stage::fill) > 0.0; }));
    }
}
