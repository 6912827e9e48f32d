// Renders one scene of the llvmpipe comparison (tests/support/scenes.cpp and
// tests/support/shared_scenes.cpp) K times and prints the median, minimum and
// maximum render time and the peak resident memory. With --repeat 1 --warmup 0
// it is the program to run under valgrind --tool=callgrind (instruction counts
// do not depend on what else the machine is doing). --steps times the speed
// steps of docs/performance.md against each other in one process.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

// Internal: detail::override_kernel_isa, to time the instruction sets in one process.
#include "fill_dispatch.hpp"
// Internal: detail::set_mesh_order_walk_choice, for --walk and --walk-against-sorted.
#include "fill_driver.hpp"
// Internal: detail::use_coverage_screen, for --screen-against-none.
#include "coverage_screen.hpp"
#include "phongrast/render.hpp"
// Internal: detail::record_stage_times, for --stages.
#include "stage_table.hpp"
#include "stage_times.hpp"
#include "support/speed_scenes.hpp"
#include "support/timing.hpp"

namespace {

namespace support = phongrast::support;

/// One way of rendering that --steps compares.
struct Variant {
    const char* name;
    phongrast::Overdraw overdraw;
    phongrast::detail::KernelIsa isa;
};

/// --steps: the speed steps of docs/performance.md one by one, timed in one
/// process in interleaved rounds; prints a Markdown row of medians and ratios to the first.
void time_steps(const phongrast::Scene& scene, phongrast::RenderOptions options, int repeat, int warmup,
                const std::string& label) {
    using phongrast::Overdraw;
    using phongrast::detail::KernelIsa;
    std::vector<Variant> variants = {{"every layer, baseline", Overdraw::shade_all, KernelIsa::baseline},
                                     {"automatic, baseline", Overdraw::automatic, KernelIsa::baseline}};
    if (phongrast::detail::kernel_isa_available(KernelIsa::avx2)) {
        variants.push_back({"automatic, AVX2", Overdraw::automatic, KernelIsa::avx2});
    }
    std::vector<phongrast::Renderer> renderers;
    for (const Variant& variant : variants) {
        options.overdraw = variant.overdraw;
        renderers.emplace_back(options);
    }
    std::vector<std::uint64_t> shaded(variants.size());
    std::vector<std::function<double()>> contenders;
    for (std::size_t v = 0; v < variants.size(); ++v) {
        contenders.push_back([&, v] {
            phongrast::detail::override_kernel_isa(variants[v].isa);
            return support::time_ms([&] { shaded[v] = renderers[v].render(scene).stats.samples_shaded; });
        });
    }
    const std::vector<double> median = support::interleaved_medians(repeat, warmup, contenders);
    phongrast::detail::override_kernel_isa(std::nullopt);
    std::printf("| %s |", label.c_str());
    for (double ms : median) std::printf(" %.3f |", ms);
    for (std::size_t v = 1; v < variants.size(); ++v) std::printf(" %.2f |", median[v] / median[0]);
    std::printf(" %llu / %llu |\n", static_cast<unsigned long long>(shaded[0]),
                static_cast<unsigned long long>(shaded[variants.size() - 1]));
}

/// --walk-against-sorted: the fill in mesh order (walks, when the scene
/// allows it) and the sorted fill (set-up records, painter's sort, bins)
/// timed in one process in interleaved rounds; prints a Markdown row of
/// medians, their ratio, and whether the two images are the same bits.
void time_walk_against_sorted(const phongrast::Scene& scene, const phongrast::RenderOptions& options, int repeat,
                              int warmup, const std::string& label) {
    phongrast::Renderer walking(options), sorting(options);
    phongrast::Image walked, sorted;
    std::uint64_t walked_passes = 0;
    const std::vector<std::function<double()>> contenders = {
        [&] {
            const std::uint64_t before = phongrast::detail::passes_filled_in_mesh_order();
            const double ms = support::time_ms([&] { walked = walking.render(scene).image; });
            walked_passes += phongrast::detail::passes_filled_in_mesh_order() - before;
            return ms;
        },
        [&] {
            const auto was = phongrast::detail::set_mesh_order_walk_choice(phongrast::detail::WalkChoice::never);
            const double ms = support::time_ms([&] { sorted = sorting.render(scene).image; });
            phongrast::detail::set_mesh_order_walk_choice(was);
            return ms;
        }};
    const std::vector<double> median = support::interleaved_medians(repeat, warmup, contenders);
    const bool same = walked.pixels.size() == sorted.pixels.size() &&
                      std::memcmp(walked.pixels.data(), sorted.pixels.data(),
                                  walked.pixels.size() * sizeof(glm::vec3)) == 0;
    std::printf("| %s | %.3f | %.3f | %.3f | %s | %s |\n", label.c_str(), median[0], median[1], median[0] / median[1],
                walked_passes > 0 ? "yes" : "no (sorted both)", same ? "yes" : "NO");
}

/// --screen-against-none: set-up with the coverage screen (coverage_screen.hpp;
/// in the fill in mesh order also its tiny draws, filled with no set-up)
/// against set-up of every triangle, timed in one process in rounds that
/// alternate which goes first (after a render of a large mesh the next one
/// starts with the other's memory in the caches); prints a Markdown row:
/// wall and CPU-time medians in ms and their ratios, the share of triangles
/// that cover no sample, whether the images and the triangle counts are the same.
void time_screen_against_none(const phongrast::Scene& scene, const phongrast::RenderOptions& options, int repeat,
                              int warmup, const std::string& label) {
    // One Renderer for both: the screen allocates nothing, and two would each
    // have their own memory, which on large meshes made one of them 0.7-1.8x
    // slower than the other for a whole process (huge pages or not, cache colouring).
    phongrast::Renderer renderer(options);
    phongrast::RenderResult results[2];
    std::vector<double> wall[2], cpu[2];
    for (int round = 0; round < warmup + repeat; ++round) {
        for (int k = 0; k < 2; ++k) {
            const int which = (round % 2 == 0) ? k : 1 - k;  // 0: screened, 1: not
            const bool was = phongrast::detail::use_coverage_screen(which == 0);
            const double cpu_start = support::process_cpu_ms();
            const double ms = support::time_ms([&] { results[which] = renderer.render(scene); });
            const double cpu_ms = support::process_cpu_ms() - cpu_start;
            phongrast::detail::use_coverage_screen(was);
            if (round < warmup) continue;
            wall[which].push_back(ms);
            cpu[which].push_back(cpu_ms);
        }
    }
    const double wall_median[2] = {support::median(wall[0]), support::median(wall[1])};
    const double cpu_median[2] = {support::median(cpu[0]), support::median(cpu[1])};
    const phongrast::Image& a = results[0].image;
    const phongrast::Image& b = results[1].image;
    const bool same = a.pixels.size() == b.pixels.size() &&
                      std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
    const phongrast::RenderStats& x = results[0].stats;
    const phongrast::RenderStats& y = results[1].stats;
    const bool same_counts = x.triangles_drawn == y.triangles_drawn &&
                             x.triangles_between_samples == y.triangles_between_samples &&
                             x.triangles_degenerate == y.triangles_degenerate && x.samples_shaded == y.samples_shaded;
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f%% | %s |\n", label.c_str(), wall_median[0],
                wall_median[1], wall_median[0] / wall_median[1], cpu_median[0], cpu_median[1],
                cpu_median[0] / cpu_median[1],
                100.0 * double(x.triangles_between_samples + x.triangles_degenerate) /
                    double(std::max<std::size_t>(1, scene.mesh.triangles.size())),
                same && same_counts ? "yes" : "NO");
}

/// --after-idle MS: the frame that follows MS ms of sleep (as a thumbnail
/// after its file is read, or a benchmark's frame after another renderer's)
/// against a frame in a run of frames, in rounds of one process (sleep, idle
/// frame, 8 untimed frames, busy frame); prints a Markdown row: medians in
/// ms, idle / busy. One Renderer: both frames find the same memory; what the
/// sleep costs is what the machine does meanwhile (caches other work fills,
/// a pool's threads that stopped waiting for work: the frame right after the
/// idle one was as slow on the Xeon, hence the untimed frames between).
void time_after_idle(const phongrast::Scene& scene, const phongrast::RenderOptions& options, int repeat, int warmup,
                     int idle_ms, const std::string& label) {
    phongrast::Renderer renderer(options);
    std::vector<double> idle, busy;
    for (int round = 0; round < warmup + repeat; ++round) {
        std::this_thread::sleep_for(std::chrono::milliseconds(idle_ms));
        const double after_idle = support::time_ms([&] { (void)renderer.render(scene); });
        for (int frame = 0; frame < 8; ++frame) (void)renderer.render(scene);
        const double in_a_run = support::time_ms([&] { (void)renderer.render(scene); });
        if (round < warmup) continue;
        idle.push_back(after_idle);
        busy.push_back(in_a_run);
    }
    std::printf("| %s | %d | %.3f | %.3f | %.2f |\n", label.c_str(), idle_ms, support::median(idle),
                support::median(busy), support::median(idle) / support::median(busy));
}

struct Settings {
    std::string name = "icosphere-9.7k", shader = "phong", mode = "exact", precision = "float";
    std::string overdraw = "auto", isa = "best", lighting, dump, walk = "auto";
    int rows = 0, threads = 1, repeat = 5, warmup = 1, after_idle_ms = -1;
    bool steps = false, walk_against_sorted = false, screen_against_none = false, stages = false;
};

phongrast::RenderOptions options_for(const Settings& s) {
    phongrast::RenderOptions options = s.mode == "seed" ? phongrast::RenderOptions::seed() : phongrast::RenderOptions::exact();
    options.threads = s.threads;
    options.precision = s.precision == "double" ? phongrast::Precision::double_float : phongrast::Precision::single_float;
    options.overdraw = s.overdraw == "all"       ? phongrast::Overdraw::shade_all
                       : s.overdraw == "visible" ? phongrast::Overdraw::shade_visible
                                                 : phongrast::Overdraw::automatic;
    return options;
}

void dump_pixels(const std::string& path, const phongrast::Image& image) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error("--dump: cannot write " + path);
    std::fwrite(image.pixels.data(), sizeof(glm::vec3), image.pixels.size(), file);
    std::fclose(file);
}

/// Renders `repeat` times after `warmup` with one Renderer (as an application
/// renders frame after frame) and prints the times, counts and memory.
void time_renders(const Settings& s, const support::NamedScene& named, const phongrast::RenderOptions& options) {
    // What is counted from here: the program, the scene with its mesh, the renderer.
    support::restart_peak_resident();
    const double rss_scene = double(support::peak_resident_bytes()) / (1 << 20);
    phongrast::Renderer renderer(options);
    for (int i = 0; i < s.warmup; ++i) renderer.render(named.scene);
    std::vector<double> ms;
    phongrast::RenderResult result;
    if (s.stages) {
        phongrast::detail::take_stage_times();  // the warm-up's
        phongrast::detail::record_stage_times(true);
    }
    for (int i = 0; i < s.repeat; ++i) {
        ms.push_back(support::time_ms([&] {
            const phongrast::RenderResult& frame = renderer.render(named.scene);
            if (i + 1 == s.repeat) result = frame;
        }));
    }
    if (!s.dump.empty()) dump_pixels(s.dump, result.image);
    if (s.stages) {
        phongrast::detail::record_stage_times(false);
        std::printf("%s\n",
                    phongrast_bench::stage_medians_line(phongrast::detail::take_stage_times(), support::median(ms)).c_str());
    }
    std::printf("%s %dx%d %s %s threads=%d: median %.3f ms, min %.3f, max %.3f (%d renders); "
                "%llu triangles drawn (%llu between samples, %llu degenerate), %llu samples; peak RSS %.1f MiB (%.1f MiB before rendering)\n",
                s.name.c_str(), named.scene.image.columns, named.scene.image.rows, s.shader.c_str(), s.mode.c_str(),
                s.threads, support::median(ms), *std::min_element(ms.begin(), ms.end()),
                *std::max_element(ms.begin(), ms.end()), s.repeat,
                static_cast<unsigned long long>(result.stats.triangles_drawn),
                static_cast<unsigned long long>(result.stats.triangles_between_samples),
                static_cast<unsigned long long>(result.stats.triangles_degenerate),
                static_cast<unsigned long long>(result.stats.samples_shaded),
                double(support::peak_resident_bytes()) / (1 << 20), rss_scene);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Render one llvmpipe-comparison scene with phongrast and time it"};
    Settings s;
    app.add_option("--scene", s.name, "icosphere-9.7k, icosphere-125k, icosphere-1.3M, icosphere-8M, or a mesh name of ../shared/assets (suzanne, ...)");
    app.add_option("--rows", s.rows, "image side in pixels (default: the comparison's)");
    app.add_option("--shader", s.shader, "flat, gouraud or phong");
    app.add_option("--mode", s.mode, "exact or seed")->check(CLI::IsMember({"exact", "seed"}));
    app.add_option("--threads", s.threads, "RenderOptions::threads");
    app.add_option("--repeat", s.repeat, "timed renders")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", s.warmup, "untimed renders first")->check(CLI::Range(0, 100));
    app.add_option("--precision", s.precision, "float or double")->check(CLI::IsMember({"float", "double"}));
    app.add_option("--overdraw", s.overdraw, "RenderOptions::overdraw: auto, visible or all")
        ->check(CLI::IsMember({"auto", "visible", "all"}));
    app.add_option("--isa", s.isa, "fill kernels: best (the default choice), baseline or avx2")
        ->check(CLI::IsMember({"best", "baseline", "avx2"}));
    app.add_flag("--steps", s.steps,
                 "time every layer + baseline kernels, automatic overdraw + baseline, automatic + AVX2 "
                 "in interleaved rounds in this process; print a Markdown row (medians in ms, ratios to the first)");
    app.add_option("--walk", s.walk,
                   "the fill in mesh order: auto (the render's choice), always (whenever nothing is lit per sample) "
                   "or never")
        ->check(CLI::IsMember({"auto", "always", "never"}));
    app.add_flag("--walk-against-sorted", s.walk_against_sorted,
                 "time the fill in mesh order against the sorted fill in interleaved rounds in this process; print a "
                 "Markdown row: medians in ms, walk / sorted, whether it walked, same image");
    app.add_flag("--screen-against-none", s.screen_against_none,
                 "time set-up with the coverage screen (and the walk's tiny draws) against set-up of every "
                 "triangle in interleaved rounds in "
                 "this process; print a Markdown row: wall and CPU-time medians in ms, screened / not, triangles that "
                 "cover no sample, same image and counts");
    app.add_option("--after-idle", s.after_idle_ms,
                   "time the frame after MS ms of sleep against one in a run of frames, in rounds in this process; "
                   "print a Markdown row: idle ms, medians in ms, idle / busy")
        ->check(CLI::Range(0, 10000));
    app.add_flag("--stages", s.stages,
                 "also print the median time of each stage of the render pass (vertices, set-up, painter's order, "
                 "binning, fill, walks, ...) and the rest of the frame");
    app.add_option("--lighting", s.lighting, "the scene's lighting instead of its own, as the command names it (ambient, full, ...)");
    app.add_option("--dump", s.dump, "write the last image's raw float RGB pixels here (to compare two builds with cmp)");
    CLI11_PARSE(app, argc, argv);
    try {
        support::NamedScene named = support::speed_scene(s.name, s.rows);
        named.scene.shader = phongrast::parse_shader(s.shader);
        if (!s.lighting.empty()) named.scene.lighting = phongrast::parse_lighting(s.lighting);
        const phongrast::RenderOptions options = options_for(s);
        if (s.walk != "auto") {
            phongrast::detail::set_mesh_order_walk_choice(s.walk == "always" ? phongrast::detail::WalkChoice::always
                                                                             : phongrast::detail::WalkChoice::never);
        }
        if (s.isa != "best") {
            phongrast::detail::override_kernel_isa(s.isa == "avx2" ? phongrast::detail::KernelIsa::avx2
                                                                   : phongrast::detail::KernelIsa::baseline);
        }
        if (s.walk_against_sorted) {
            time_walk_against_sorted(named.scene, options, s.repeat, s.warmup,
                                     s.name + " | " + s.shader + " | " + s.mode + " | " + std::to_string(s.threads));
        } else if (s.screen_against_none) {
            time_screen_against_none(named.scene, options, s.repeat, s.warmup,
                                     s.name + " | " + s.shader + " | " + s.mode + " | " + std::to_string(s.threads));
        } else if (s.after_idle_ms >= 0) {
            time_after_idle(named.scene, options, s.repeat, s.warmup, s.after_idle_ms,
                            s.name + " | " + s.shader + " | " + s.mode + " | " + std::to_string(s.threads));
        } else if (s.steps) {
            time_steps(named.scene, options, s.repeat, s.warmup,
                       s.name + " | " + s.shader + " | " + s.mode + " | " + std::to_string(s.threads));
        } else {
            time_renders(s, named, options);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "speed_once: %s\n", error.what());
        return 1;
    }
    return 0;
}
