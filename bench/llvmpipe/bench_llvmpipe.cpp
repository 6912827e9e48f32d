// bench_llvmpipe: phongrast against Mesa's llvmpipe (through OSMesa) on the
// same scenes, same camera, same painter's order: times and image agreement.
//
// One process measures one thread count, because llvmpipe reads
// LP_NUM_THREADS once, when its first context is created; bench/run.sh llvmpipe runs 1 and 2.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "mesh_orders.hpp"
#include "pictures.hpp"
#include "support/image_compare.hpp"
#include "support/llvmpipe_renderer.hpp"
#include "support/speed_scenes.hpp"
#include "support/timing.hpp"

namespace {

namespace support = phongrast::support;
using support::NamedScene;

constexpr int kMaxRounds = 101;

struct Settings {
    int threads = 1;
    int repeat = 5;
    int huge_repeat = 3;
    double seconds = 2.0;
    support::SpeedSceneSelection selection;
    std::string images_dir;
    std::string order = "generator";  ///< the meshes' order (bench/mesh_orders.hpp)
    bool warm_too = false;  ///< also time phongrast exact right after its own frame (warm_lines)
};

/// phongrast (exact and seed) and llvmpipe on one scene and shader, in
/// interleaved rounds: prints the table row, returns the image agreement line.
/// With `warm_line`, each round also times phongrast exact again right after
/// its own frame (the exact frame of the table follows llvmpipe's, whose
/// work leaves the caches and branch predictors to it) and writes the two
/// medians there.
std::string compare(support::LlvmpipeRenderer& llvmpipe, NamedScene& named, phongrast::Shader shader, int threads,
                    int repeat, double fill_seconds, int max_rounds, const std::string& images_dir,
                    std::string* warm_line) {
    phongrast::Scene& scene = named.scene;
    scene.shader = shader;
    phongrast::RenderOptions exact = phongrast::RenderOptions::exact();
    phongrast::RenderOptions seed = phongrast::RenderOptions::seed();
    exact.threads = seed.threads = threads;

    // Like llvmpipe's context, a Renderer keeps its buffers between frames.
    phongrast::Renderer exact_renderer(exact), seed_renderer(seed);
    const auto time_phongrast = [&scene](phongrast::Renderer& renderer, phongrast::Image* keep) {
        const auto start = std::chrono::steady_clock::now();
        const phongrast::RenderResult& result = renderer.render(scene);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (keep) *keep = result.image;  // outside the timed part
        return seconds;
    };
    phongrast::Image phongrast_image;
    std::vector<double> sort_s;
    llvmpipe.load(scene);
    std::vector<std::function<double()>> contenders{
        [&] { return time_phongrast(exact_renderer, &phongrast_image); },
        [&] { return time_phongrast(seed_renderer, nullptr); },
        [&] {
            const support::FrameTimes times = llvmpipe.draw();
            sort_s.push_back(times.sort);
            return times.total;
        }};
    if (warm_line != nullptr) {
        contenders.insert(contenders.begin() + 1, [&] { return time_phongrast(exact_renderer, nullptr); });
    }
    std::vector<double> medians = support::interleaved_medians_filling(fill_seconds, repeat, max_rounds, contenders);
    const double exact_warm_s = warm_line != nullptr ? medians[1] : 0.0;
    if (warm_line != nullptr) medians.erase(medians.begin() + 1);
    const double exact_s = medians[0], seed_s = medians[1], llvmpipe_s = medians[2];
    sort_s.erase(sort_s.begin());  // the warm-up frame
    const phongrast::Image llvmpipe_image = llvmpipe.image();

    const double exact_ratio = exact_s / llvmpipe_s;
    if (warm_line != nullptr) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "%s %s: exact %.2f ms after llvmpipe's frame, %.2f right after its own (x %.2f); "
                      "warm / llvmpipe %.3f",
                      named.name.c_str(), phongrast::to_string(shader), 1e3 * exact_s, 1e3 * exact_warm_s,
                      exact_s / exact_warm_s, exact_warm_s / llvmpipe_s);
        *warm_line = text;
    }
    const double seed_ratio = seed_s / llvmpipe_s;
    std::printf("| %s | %zu | %dx%d | %s | %d | %.2f | %.2f | %.2f (%.2f) | %.3f | %.3f | %s |\n", named.name.c_str(),
                scene.mesh.triangles.size(), scene.image.columns, scene.image.rows, phongrast::to_string(shader),
                threads, 1e3 * exact_s, 1e3 * seed_s, 1e3 * llvmpipe_s, 1e3 * support::median(sort_s), exact_ratio,
                seed_ratio,
                exact_ratio <= 0.25 && seed_ratio <= 0.25 ? "met"
                : exact_ratio <= 0.25 || seed_ratio <= 0.25 ? (exact_ratio <= 0.25 ? "exact only" : "seed only")
                                                            : "not met");
    std::fflush(stdout);

    if (!images_dir.empty()) {
        std::filesystem::create_directories(images_dir);
        const std::string stem = images_dir + "/" + named.name + "-" + phongrast::to_string(shader);
        phongrast_bench::write_png(stem + "-phongrast.png", phongrast_image);
        phongrast_bench::write_png(stem + "-llvmpipe.png", llvmpipe_image);
        phongrast_bench::write_difference_map(stem + "-difference.png", phongrast_image, llvmpipe_image,
                                              scene.image.background);
    }
    const support::ImageAgreement agreement = support::agreement(phongrast_image, llvmpipe_image, scene.image.background);
    return named.name + " " + phongrast::to_string(shader) +
           " (first = phongrast exact, second = llvmpipe): " + support::summary(agreement);
}

void run(const Settings& settings) {
    support::LlvmpipeRenderer llvmpipe;
    std::printf("llvmpipe: %s, LP_NUM_THREADS=%s; phongrast threads=%d; median of interleaved rounds after 1 warm-up: "
                "at least %d, more (up to %d) to fill about %.1f s per row; %d for icosphere-8M\n\n",
                llvmpipe.description().c_str(), std::getenv("LP_NUM_THREADS"), settings.threads, settings.repeat,
                std::max(settings.repeat, kMaxRounds), settings.seconds, std::min(settings.repeat, settings.huge_repeat));

    std::printf("| scene | triangles | image | shader | threads | phongrast exact ms | phongrast seed ms | "
                "llvmpipe ms (of which sort) | exact / llvmpipe | seed / llvmpipe | goal <= 0.25 |\n");
    std::printf("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    std::vector<std::string> notes, agreement_lines, warm_lines;
    // One scene in memory at a time: the 8M-triangle mesh alone is about 0.4 GB.
    for (const std::string& name : support::speed_scene_names(settings.selection, notes)) {
        NamedScene named = support::speed_scene(name);
        if (settings.order != "generator") {
            // The same mesh in another order: the same pictures, the goals read per order
            // (bench_goals names its rows alike, so that bench/report.py joins them).
            named.scene.mesh = phongrast_bench::in_mesh_order(named.scene.mesh, settings.order);
            named.name += " (" + settings.order + ")";
        }
        const bool huge = name == "icosphere-8M";
        const int repeat = huge ? std::min(settings.repeat, settings.huge_repeat) : settings.repeat;
        const int max_rounds = huge ? repeat : std::max(repeat, kMaxRounds);
        for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
            std::string warm_line;
            agreement_lines.push_back(compare(llvmpipe, named, shader, settings.threads, repeat, settings.seconds,
                                              max_rounds, settings.images_dir,
                                              settings.warm_too ? &warm_line : nullptr));
            if (settings.warm_too) warm_lines.push_back(warm_line);
        }
    }
    for (const std::string& note : notes) std::cerr << "bench_llvmpipe: " << note << "\n";
    if (settings.warm_too) {
        std::printf("\nphongrast exact after llvmpipe's frame (the table) and right after its own frame (--warm-too):\n");
        for (const std::string& line : warm_lines) std::printf("- %s\n", line.c_str());
    }
    std::printf("\nImage agreement, phongrast RenderOptions::exact() against llvmpipe, colours clamped to [0,1]:\n");
    for (const std::string& line : agreement_lines) std::printf("- %s\n", line.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"phongrast against Mesa llvmpipe (OSMesa): frame times and image agreement"};
    Settings settings;
    bool no_large = false, no_assets = false, no_huge = false;
    app.add_option("--threads", settings.threads, "threads for phongrast and for llvmpipe (LP_NUM_THREADS)")
        ->check(CLI::Range(1, 256));
    app.add_option("--repeat", settings.repeat, "timed runs per measurement (median), after one warm-up")
        ->check(CLI::Range(1, 1000));
    app.add_option("--seconds", settings.seconds,
                   "more rounds (up to 101) while the timed rounds of a row would take less than this")
        ->check(CLI::Range(0.0, 600.0));
    app.add_option("--huge-repeat", settings.huge_repeat, "at most this many timed runs for icosphere-8M")
        ->check(CLI::Range(1, 1000));
    app.add_flag("--no-large", no_large, "skip the 1.3M-triangle 1024x1024 icosphere");
    app.add_flag("--no-huge", no_huge, "skip the 8M-triangle 2048x2048 icosphere (seconds per frame)");
    app.add_flag("--no-assets", no_assets, "skip the meshes of ../shared/assets");
    app.add_option("--images", settings.images_dir, "write each scene's two renders and a difference heat map here");
    app.add_option("--order", settings.order, "the meshes' order: generator, spatial or shuffled (bench/mesh_orders.hpp)")
        ->check(CLI::IsMember(phongrast_bench::mesh_order_names()));
    app.add_flag("--warm-too", settings.warm_too,
                 "also time phongrast exact right after its own frame in each round, and list both medians");
    CLI11_PARSE(app, argc, argv);
    settings.selection.large = !no_large;
    settings.selection.huge = !no_huge;
    settings.selection.assets = !no_assets;

    // Must happen before the first OSMesa context exists; overrides the caller's value
    // so that both renderers really use the same number of threads.
    setenv("LP_NUM_THREADS", std::to_string(settings.threads).c_str(), 1);
    try {
        run(settings);
    } catch (const std::exception& error) {
        std::cerr << "bench_llvmpipe: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
