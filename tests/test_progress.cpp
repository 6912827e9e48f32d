// RenderOptions::progress: reports from the calling thread, cancellation by
// returning false (RenderCancelled), and a Renderer that stays usable after it.
#include <catch2/catch.hpp>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

// Big enough to take a few hundred milliseconds: many reports.
Scene long_scene() {
    Scene scene;
    scene.mesh = test_meshes::torus(600, 300, 1.2, 0.45);  // 360,000 triangles
    scene.camera.eye = {0.5, 2.5, 4.0};
    scene.camera.lookat = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.image.rows = scene.image.columns = 512;
    scene.lights = {{{2.0, 3.0, 6.0}, glm::vec3(1.0f)}, {{-3.0, 1.0, 2.0}, glm::vec3(0.5f)}};
    scene.shader = Shader::phong;
    return scene;
}

struct Report {
    double fraction;
    std::thread::id thread;
    std::chrono::steady_clock::time_point when;
};

}  // namespace

TEST_CASE("progress is reported from the calling thread, in order, ending at 1") {
    const Scene scene = long_scene();
    std::vector<Report> reports;
    RenderOptions options = RenderOptions::exact();
    options.samples_per_axis = 2;
    options.progress = [&](double fraction) {
        reports.push_back({fraction, std::this_thread::get_id(), std::chrono::steady_clock::now()});
        return true;
    };
    const auto start = std::chrono::steady_clock::now();
    const RenderResult result = render(scene, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    REQUIRE_FALSE(reports.empty());
    CHECK(reports.back().fraction == 1.0);
    double longest_gap = std::chrono::duration<double>(reports.front().when - start).count();
    for (std::size_t i = 0; i < reports.size(); ++i) {
        CHECK(reports[i].thread == std::this_thread::get_id());
        CHECK(reports[i].fraction >= 0.0);
        CHECK(reports[i].fraction <= 1.0);
        if (i > 0) {
            CHECK(reports[i].fraction >= reports[i - 1].fraction);
            longest_gap = std::max(longest_gap, std::chrono::duration<double>(reports[i].when - reports[i - 1].when).count());
        }
    }
    // A render of this size reports many times; the gap is printed, not asserted (timing depends on the machine).
    INFO(reports.size() << " reports over " << seconds * 1e3 << " ms, longest gap " << longest_gap * 1e3 << " ms");
    if (seconds > 0.2) CHECK(reports.size() >= 3);
    // The same picture as without a callback.
    RenderOptions silent = options;
    silent.progress = nullptr;
    CHECK(render(scene, silent).image.pixels == result.image.pixels);
}

TEST_CASE("returning false cancels with RenderCancelled, and the Renderer renders the next frame as if new") {
    const Scene scene = long_scene();
    RenderOptions options = RenderOptions::exact();
    options.aovs = AovRequest::all();
    const RenderResult expected = render(scene, options);

    for (int cancel_at : {1, 3}) {
        INFO("cancelled at report " << cancel_at);
        int reports = 0;
        RenderOptions cancelling = options;
        cancelling.progress = [&](double) { return ++reports < cancel_at; };
        Renderer renderer(cancelling);
        CHECK_THROWS_AS(renderer.render(scene), RenderCancelled);
        CHECK(reports == cancel_at);  // no report after the one that cancelled

        renderer.set_options(options);
        const RenderResult& again = renderer.render(scene);
        CHECK(again.image.pixels == expected.image.pixels);
        CHECK(again.aovs.id == expected.aovs.id);
        CHECK(again.stats.samples_shaded == expected.stats.samples_shaded);
    }
}

TEST_CASE("an exception from the callback reaches the caller, and the Renderer stays usable") {
    Scene scene = long_scene();
    scene.image.rows = scene.image.columns = 128;
    RenderOptions options = RenderOptions::exact();
    options.progress = [](double) -> bool { throw std::runtime_error("stop from the callback"); };
    Renderer renderer(options);
    CHECK_THROWS_WITH(renderer.render(scene), "stop from the callback");
    options.progress = nullptr;
    renderer.set_options(options);
    CHECK(renderer.render(scene).image.pixels == render(scene, options).image.pixels);
}
