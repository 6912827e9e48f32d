// Renders one scene of the llvmpipe comparison (bench/llvmpipe/scenes.cpp and
// asset_scenes.cpp) K times and prints the median, minimum and maximum render
// time and the peak resident memory. With --repeat 1 --warmup 0 it is the
// program to run under valgrind --tool=callgrind (instruction counts do not
// depend on what else the machine is doing), which is how the "Speed (issue
// 8)" section of docs/performance.md compares the renderer before and after.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "asset_scenes.hpp"
// Internal: detail::override_kernel_isa, to time the instruction sets in one
// process. bench/run_speed.sh --baseline also builds this file against older
// renderers, which have no such header: --steps and --isa are then absent.
#if __has_include("fill_types.hpp")
#include "fill_types.hpp"
#define PHONGRAST_SPEED_HAS_ISA 1
#endif
// phongrast::Renderer (frames after the first allocate nothing) came with this internal header.
#if __has_include("normals_scratch.hpp")
#define PHONGRAST_SPEED_HAS_RENDERER 1
#endif
#include "phongrast/render.hpp"
#include "scenes.hpp"

namespace {

llvmpipe_compare::NamedScene find_scene(const std::string& name, int rows) {
    if (name == "icosphere-9.7k") return llvmpipe_compare::icosphere_scene(name, 22, rows > 0 ? rows : 512);
    if (name == "icosphere-1.3M") return llvmpipe_compare::icosphere_scene(name, 256, rows > 0 ? rows : 1024);
    for (llvmpipe_compare::NamedScene& scene : llvmpipe_compare::asset_scenes(rows > 0 ? rows : 512)) {
        if (scene.name == name) return scene;
    }
    throw std::invalid_argument("--scene: expected icosphere-9.7k, icosphere-1.3M or a mesh of ../shared/assets, got '" +
                                name + "'");
}

#ifdef PHONGRAST_SPEED_HAS_ISA
/// One way of rendering that --steps compares.
struct Variant {
    const char* name;
    phongrast::Overdraw overdraw;
    phongrast::detail::KernelIsa isa;
};

/// --steps: the speed steps of docs/performance.md one by one, timed in one
/// process, round-robin (each round renders every variant once, so load hits
/// all alike); prints a Markdown row of medians and ratios to the first.
void time_steps(const phongrast::Scene& scene, phongrast::RenderOptions options, int repeat, int warmup,
                const std::string& label) {
    using phongrast::Overdraw;
    using phongrast::detail::KernelIsa;
    std::vector<Variant> variants = {{"every layer, baseline", Overdraw::shade_all, KernelIsa::baseline},
                                     {"automatic, baseline", Overdraw::automatic, KernelIsa::baseline}};
    if (phongrast::detail::kernel_isa_available(KernelIsa::avx2)) {
        variants.push_back({"automatic, AVX2", Overdraw::automatic, KernelIsa::avx2});
    }
    std::vector<std::vector<double>> ms(variants.size());
    std::vector<std::uint64_t> shaded(variants.size());
#ifdef PHONGRAST_SPEED_HAS_RENDERER
    std::vector<phongrast::Renderer> renderers;
    for (const Variant& variant : variants) {
        options.overdraw = variant.overdraw;
        renderers.emplace_back(options);
    }
#endif
    for (int round = -warmup; round < repeat; ++round) {
        for (std::size_t v = 0; v < variants.size(); ++v) {
            options.overdraw = variants[v].overdraw;
            phongrast::detail::override_kernel_isa(variants[v].isa);
            const auto start = std::chrono::steady_clock::now();
#ifdef PHONGRAST_SPEED_HAS_RENDERER
            const phongrast::RenderResult& result = renderers[v].render(scene);
#else
            const phongrast::RenderResult result = phongrast::render(scene, options);
#endif
            const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (round >= 0) ms[v].push_back(elapsed);
            shaded[v] = result.stats.samples_shaded;
        }
    }
    phongrast::detail::override_kernel_isa(std::nullopt);
    std::vector<double> median(variants.size());
    for (std::size_t v = 0; v < variants.size(); ++v) {
        std::sort(ms[v].begin(), ms[v].end());
        median[v] = ms[v][ms[v].size() / 2];
    }
    std::printf("| %s |", label.c_str());
    for (std::size_t v = 0; v < variants.size(); ++v) std::printf(" %.3f |", median[v]);
    for (std::size_t v = 1; v < variants.size(); ++v) std::printf(" %.2f |", median[v] / median[0]);
    std::printf(" %llu / %llu |\n", static_cast<unsigned long long>(shaded[0]),
                static_cast<unsigned long long>(shaded[variants.size() - 1]));
}

#endif

double peak_rss_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Render one llvmpipe-comparison scene with phongrast and time it"};
    std::string name = "icosphere-9.7k", shader = "phong", mode = "exact";
    std::string dump, precision = "float";
    int rows = 0, threads = 1, repeat = 5, warmup = 1;
    app.add_option("--scene", name, "icosphere-9.7k, icosphere-1.3M, or a mesh name of ../shared/assets (suzanne, ...)");
    app.add_option("--rows", rows, "image side in pixels (default: the comparison's)");
    app.add_option("--shader", shader, "flat, gouraud or phong");
    app.add_option("--mode", mode, "exact or seed")->check(CLI::IsMember({"exact", "seed"}));
    app.add_option("--threads", threads, "RenderOptions::threads");
    app.add_option("--repeat", repeat, "timed renders")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", warmup, "untimed renders first")->check(CLI::Range(0, 100));
    app.add_option("--precision", precision, "float or double")->check(CLI::IsMember({"float", "double"}));
#ifdef PHONGRAST_SPEED_HAS_ISA
    std::string overdraw = "auto", isa = "best";
    bool steps = false;
    app.add_option("--overdraw", overdraw, "RenderOptions::overdraw: auto, visible or all")
        ->check(CLI::IsMember({"auto", "visible", "all"}));
    app.add_option("--isa", isa, "fill kernels: best (the default choice), baseline or avx2")
        ->check(CLI::IsMember({"best", "baseline", "avx2"}));
    app.add_flag("--steps", steps,
                 "time every layer + baseline kernels, automatic overdraw + baseline, automatic + AVX2 "
                 "round-robin in this process; print a Markdown row (medians in ms, ratios to the first)");
#endif
    app.add_option("--dump", dump, "write the last image's raw float RGB pixels here (to compare two builds with cmp)");
    CLI11_PARSE(app, argc, argv);
    try {
        llvmpipe_compare::NamedScene named = find_scene(name, rows);
        named.scene.shader = phongrast::parse_shader(shader);
        phongrast::RenderOptions options =
            mode == "seed" ? phongrast::RenderOptions::seed() : phongrast::RenderOptions::exact();
        options.threads = threads;
        options.precision =
            precision == "double" ? phongrast::Precision::double_float : phongrast::Precision::single_float;
#ifdef PHONGRAST_SPEED_HAS_ISA
        options.overdraw = overdraw == "all"       ? phongrast::Overdraw::shade_all
                           : overdraw == "visible" ? phongrast::Overdraw::shade_visible
                                                   : phongrast::Overdraw::automatic;
        if (isa != "best") {
            phongrast::detail::override_kernel_isa(isa == "avx2" ? phongrast::detail::KernelIsa::avx2
                                                                 : phongrast::detail::KernelIsa::baseline);
        }
        if (steps) {
            time_steps(named.scene, options, repeat, warmup,
                       name + " | " + shader + " | " + mode + " | " + std::to_string(threads));
            return 0;
        }
#endif
        const double rss_scene = peak_rss_mib();
        std::vector<double> ms;
#ifdef PHONGRAST_SPEED_HAS_RENDERER
        phongrast::Renderer renderer(options);  // as an application renders frame after frame
        const auto render_once = [&]() -> const phongrast::RenderResult& { return renderer.render(named.scene); };
#else
        const auto render_once = [&] { return phongrast::render(named.scene, options); };
#endif
        for (int i = 0; i < warmup; ++i) render_once();
        phongrast::RenderResult result;
        for (int i = 0; i < repeat; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const auto& frame = render_once();
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            if (i + 1 == repeat) result = frame;
        }
        const phongrast::RenderStats& stats = result.stats;
        if (!dump.empty()) {
            std::FILE* file = std::fopen(dump.c_str(), "wb");
            if (!file) throw std::runtime_error("--dump: cannot write " + dump);
            std::fwrite(result.image.pixels.data(), sizeof(glm::vec3), result.image.pixels.size(), file);
            std::fclose(file);
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%s %dx%d %s %s threads=%d: median %.3f ms, min %.3f, max %.3f (%d renders); "
                    "%llu triangles drawn, %llu samples; peak RSS %.1f MiB (%.1f MiB before rendering)\n",
                    name.c_str(), named.scene.image.columns, named.scene.image.rows, shader.c_str(), mode.c_str(),
                    threads, ms[ms.size() / 2], ms.front(), ms.back(), repeat,
                    static_cast<unsigned long long>(stats.triangles_drawn),
                    static_cast<unsigned long long>(stats.samples_shaded), peak_rss_mib(), rss_scene);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "speed_once: %s\n", error.what());
        return 1;
    }
    return 0;
}
