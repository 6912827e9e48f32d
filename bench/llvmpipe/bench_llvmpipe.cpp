// bench_llvmpipe: phongrast against Mesa's llvmpipe (through OSMesa) on the
// same scenes, same camera, same painter's order: times and image agreement.
//
// One process measures one thread count, because llvmpipe reads
// LP_NUM_THREADS once, when its first context is created; bench/run.sh llvmpipe runs 1 and 2.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pictures.hpp"
#include "support/image_compare.hpp"
#include "support/llvmpipe_renderer.hpp"
#include "support/scenes.hpp"
#include "support/shared_scenes.hpp"
#include "support/timing.hpp"

namespace {

namespace support = phongrast::support;
using support::NamedScene;

struct Settings {
    int threads = 1;
    int repeat = 5;
    bool large = true;
    bool assets = true;
    std::string images_dir;
};

std::vector<NamedScene> make_scenes(const Settings& settings) {
    std::vector<NamedScene> scenes;
    scenes.push_back(support::icosphere_scene("icosphere-9.7k", 22, 512));
    if (settings.assets) {
        std::vector<std::string> notes;
        for (NamedScene& scene : support::comparison_scenes(512, notes)) scenes.push_back(std::move(scene));
        for (const std::string& note : notes) std::cerr << "bench_llvmpipe: " << note << "\n";
    }
    if (settings.large) scenes.push_back(support::icosphere_scene("icosphere-1.3M", 256, 1024));
    return scenes;
}

void run(const Settings& settings) {
    support::LlvmpipeRenderer llvmpipe;
    std::printf("llvmpipe: %s, LP_NUM_THREADS=%s; phongrast threads=%d; median of %d interleaved rounds after 1 warm-up\n\n",
                llvmpipe.description().c_str(), std::getenv("LP_NUM_THREADS"), settings.threads, settings.repeat);

    std::printf("| scene | triangles | image | shader | threads | phongrast exact ms | phongrast seed ms | "
                "llvmpipe ms (of which sort) | exact / llvmpipe | seed / llvmpipe | goal <= 0.25 |\n");
    std::printf("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    std::vector<std::string> agreement_lines;

    for (NamedScene& named : make_scenes(settings)) {
        phongrast::Scene& scene = named.scene;
        for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
            scene.shader = shader;
            phongrast::RenderOptions exact = phongrast::RenderOptions::exact();
            phongrast::RenderOptions seed = phongrast::RenderOptions::seed();
            exact.threads = seed.threads = settings.threads;

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
            const std::vector<double> medians = support::interleaved_medians(
                settings.repeat, 1, {[&] { return time_phongrast(exact_renderer, &phongrast_image); },
                                  [&] { return time_phongrast(seed_renderer, nullptr); },
                                  [&] {
                                      const support::FrameTimes times = llvmpipe.draw();
                                      sort_s.push_back(times.sort);
                                      return times.total;
                                  }});
            const double exact_s = medians[0], seed_s = medians[1], llvmpipe_s = medians[2];
            sort_s.erase(sort_s.begin());  // the warm-up frame
            const phongrast::Image llvmpipe_image = llvmpipe.image();

            const double exact_ratio = exact_s / llvmpipe_s;
            const double seed_ratio = seed_s / llvmpipe_s;
            std::printf("| %s | %zu | %dx%d | %s | %d | %.2f | %.2f | %.2f (%.2f) | %.3f | %.3f | %s |\n",
                        named.name.c_str(), scene.mesh.triangles.size(), scene.image.columns, scene.image.rows,
                        phongrast::to_string(shader), settings.threads, 1e3 * exact_s, 1e3 * seed_s,
                        1e3 * llvmpipe_s, 1e3 * support::median(sort_s), exact_ratio, seed_ratio,
                        exact_ratio <= 0.25 && seed_ratio <= 0.25 ? "met"
                        : exact_ratio <= 0.25 || seed_ratio <= 0.25 ? (exact_ratio <= 0.25 ? "exact only" : "seed only")
                                                                    : "not met");
            std::fflush(stdout);

            const support::ImageAgreement agreement =
                support::agreement(phongrast_image, llvmpipe_image, scene.image.background);
            agreement_lines.push_back(named.name + " " + phongrast::to_string(shader) +
                                      " (first = phongrast exact, second = llvmpipe): " +
                                      support::summary(agreement));

            if (!settings.images_dir.empty()) {
                std::filesystem::create_directories(settings.images_dir);
                const std::string stem = settings.images_dir + "/" + named.name + "-" + phongrast::to_string(shader);
                phongrast_bench::write_png(stem + "-phongrast.png", phongrast_image);
                phongrast_bench::write_png(stem + "-llvmpipe.png", llvmpipe_image);
                phongrast_bench::write_difference_map(stem + "-difference.png", phongrast_image, llvmpipe_image,
                                                 scene.image.background);
            }
        }
    }
    std::printf("\nImage agreement, phongrast RenderOptions::exact() against llvmpipe, colours clamped to [0,1]:\n");
    for (const std::string& line : agreement_lines) std::printf("- %s\n", line.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"phongrast against Mesa llvmpipe (OSMesa): frame times and image agreement"};
    Settings settings;
    bool no_large = false;
    bool no_assets = false;
    app.add_option("--threads", settings.threads, "threads for phongrast and for llvmpipe (LP_NUM_THREADS)")
        ->check(CLI::Range(1, 256));
    app.add_option("--repeat", settings.repeat, "timed runs per measurement (median), after one warm-up")
        ->check(CLI::Range(1, 1000));
    app.add_flag("--no-large", no_large, "skip the 1.3M-triangle 1024x1024 icosphere");
    app.add_flag("--no-assets", no_assets, "skip the meshes of ../shared/assets");
    app.add_option("--images", settings.images_dir, "write each scene's two renders and a difference heat map here");
    CLI11_PARSE(app, argc, argv);
    settings.large = !no_large;
    settings.assets = !no_assets;

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
