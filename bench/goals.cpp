// bench_goals: phongrast alone on one speed scene (support/speed_scenes.hpp),
// for the measures of the speed goals that llvmpipe must not share a process
// with:
//   - peak resident memory, mesh included, against the budget of 200 bytes per
//     triangle plus 32 bytes per pixel: the count restarts once the scene is
//     built (the mesh generator's scratch is gone), so it holds the program, the
//     scene with its mesh and normals, and the renderer's working memory;
//   - ambient-only lighting against full lighting: Phong full, Phong ambient,
//     Gouraud ambient and flat ambient in interleaved rounds in this process,
//     so a change in the machine's load hits all four alike.
// Prints one Markdown row per thread count; bench/report.py summary joins the
// rows with bench_llvmpipe's tables (bench/run.sh goals, bench/run.sh all).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

// Internal: detail::set_mesh_order_walk_choice and set_mesh_order_walks, for --banded-ambient and --one-walk.
#include "fill_driver.hpp"
#include "phongrast/render.hpp"
#include "mesh_orders.hpp"
#include "support/speed_scenes.hpp"
#include "support/timing.hpp"

namespace {

namespace support = phongrast::support;
using phongrast::Lighting;
using phongrast::Shader;

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kBudgetPerTriangle = 200.0, kBudgetPerPixel = 32.0;
constexpr int kMaxRounds = 101;

struct Settings {
    std::string scene = "icosphere-9.7k", mode = "exact", order = "generator";
    std::vector<int> threads = {1, 2};
    int rows = 0, repeat = 5;
    double seconds = 2.0;
    bool header = false, list = false, banded_ambient = false, one_walk = false;
    support::SpeedSceneSelection selection;
};

/// --list: the selected speed scenes' names, one a line (bench/run.sh runs one process per scene).
void list_scenes(const support::SpeedSceneSelection& selection) {
    std::vector<std::string> notes;
    for (const std::string& name : support::speed_scene_names(selection, notes)) std::printf("%s\n", name.c_str());
    for (const std::string& note : notes) std::fprintf(stderr, "bench_goals: %s\n", note.c_str());
}

phongrast::RenderOptions options_for(const std::string& mode, int threads) {
    phongrast::RenderOptions options = mode == "seed" ? phongrast::RenderOptions::seed() : phongrast::RenderOptions::exact();
    options.threads = threads;
    return options;
}

/// The largest peak resident memory of one render, over Gouraud and Phong with
/// full lighting in both modes, each with a fresh Renderer, counted from what
/// was resident before it (program + scene).
struct PeakMemory {
    std::uint64_t bytes = 0;
    std::string at;  ///< which render reached it
};

PeakMemory peak_memory(phongrast::Scene& scene, int threads) {
    PeakMemory peak;
    for (Shader shader : {Shader::gouraud, Shader::phong}) {
        for (const char* mode : {"exact", "seed"}) {
            scene.shader = shader;
            scene.lighting = Lighting::full();
            support::restart_peak_resident();
            {
                phongrast::Renderer renderer(options_for(mode, threads));
                renderer.render(scene);
            }
            const std::uint64_t bytes = support::peak_resident_bytes();
            if (bytes > peak.bytes) peak = {bytes, std::string(phongrast::to_string(shader)) + " " + mode};
        }
    }
    return peak;
}

/// Medians in ms of Phong full, Phong ambient, Gouraud ambient, flat ambient, in interleaved rounds.
/// With `banded_ambient`, a fifth: Phong ambient through set-up, sort, bins
/// and bands (the fill in mesh order forbidden), as every thread count did before it.
std::vector<double> ambient_and_full_ms(phongrast::Scene& scene, const phongrast::RenderOptions& options, int repeat,
                                        double seconds, bool banded_ambient = false, bool one_walk = false) {
    struct Case {
        Shader shader;
        Lighting lighting;
    };
    const std::vector<Case> cases = {{Shader::phong, Lighting::full()},
                                     {Shader::phong, Lighting::only_ambient()},
                                     {Shader::gouraud, Lighting::only_ambient()},
                                     {Shader::flat, Lighting::only_ambient()}};
    // A Renderer per case, each in the steady state of rendering its case frame
    // after frame, nothing carried over from another case's frame. Four sets of
    // buffers: about 6 GB for the 8M mesh.
    std::vector<phongrast::Renderer> renderers;
    const std::size_t extra = (banded_ambient ? 1 : 0) + (one_walk ? 1 : 0);
    for (std::size_t k = 0; k < cases.size() + extra; ++k) renderers.emplace_back(options);
    std::vector<std::function<double()>> contenders;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        contenders.push_back([&, k] {
            scene.shader = cases[k].shader;  // outside the timed part, no copy of the mesh
            scene.lighting = cases[k].lighting;
            return support::time_ms([&] { renderers[k].render(scene); });
        });
    }
    if (banded_ambient) {
        contenders.push_back([&] {
            scene.shader = Shader::phong;
            scene.lighting = Lighting::only_ambient();
            const auto allowed = phongrast::detail::set_mesh_order_walk_choice(phongrast::detail::WalkChoice::never);
            const double ms = support::time_ms([&] { renderers[cases.size()].render(scene); });
            phongrast::detail::set_mesh_order_walk_choice(allowed);
            return ms;
        });
    }
    if (one_walk) {
        contenders.push_back([&] {
            scene.shader = Shader::phong;
            scene.lighting = Lighting::only_ambient();
            const int walks = phongrast::detail::set_mesh_order_walks(1);
            const double ms = support::time_ms([&] { renderers.back().render(scene); });
            phongrast::detail::set_mesh_order_walks(walks);
            return ms;
        });
    }
    return support::interleaved_medians_filling(seconds, repeat, std::max(repeat, kMaxRounds), contenders);
}

std::uint64_t mesh_bytes(const phongrast::Mesh& mesh) {
    return mesh.positions.size() * sizeof(mesh.positions[0]) + mesh.colors.size() * sizeof(mesh.colors[0]) +
           mesh.normals.size() * sizeof(mesh.normals[0]) + mesh.triangles.size() * sizeof(mesh.triangles[0]);
}

void print_header(int repeat, double seconds, const std::string& mode, bool restarted) {
    std::printf("phongrast alone, RenderOptions::%s(); times: medians of interleaved rounds after 1 warm-up, at least "
                "%d, more (up to %d) to fill about %.1f s per thread count; "
                "peak memory: the largest of one render each of Gouraud and Phong, exact and seed, full lighting, "
                "%s; budget: %.0f B x triangles + %.0f B x pixels\n\n",
                mode.c_str(), repeat, kMaxRounds, seconds,
                restarted ? "counted from after the scene was built (program + mesh + render)"
                          : "counted since the process started (the peak could not be restarted here)",
                kBudgetPerTriangle, kBudgetPerPixel);
    std::printf("| scene | class | triangles | image | threads | Phong full ms | Phong ambient ms | Gouraud ambient ms "
                "| flat ambient ms | Phong ambient / full | Gouraud ambient / Phong ambient | flat ambient / Phong ambient "
                "| program MiB | mesh MiB | peak MiB | peak at | peak B / triangle | budget B / triangle | memory goal |\n");
    std::printf("|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---|\n");
}

void run(const Settings& s) {
    support::restart_peak_resident();
    const std::uint64_t program_bytes = support::peak_resident_bytes();  // before any scene exists
    support::NamedScene named = support::speed_scene(s.scene, s.rows);
    phongrast::Scene& scene = named.scene;
    const std::string scene_class = support::speed_scene_class(named.name);
    if (s.order != "generator") {
        // The same mesh in another order (mesh_orders.hpp): the same pictures, the goals read per order.
        scene.mesh = phongrast_bench::in_mesh_order(scene.mesh, s.order);
        named.name += " (" + s.order + ")";
    }
    const double triangles = double(scene.mesh.triangles.size());
    const double pixels = double(scene.image.rows) * double(scene.image.columns);
    const double budget = kBudgetPerTriangle * triangles + kBudgetPerPixel * pixels;
    const bool restarted = support::restart_peak_resident();
    if (s.header) print_header(s.repeat, s.seconds, s.mode, restarted);
    for (int threads : s.threads) {
        const PeakMemory peak = peak_memory(scene, threads);
        const std::vector<double> ms =
            ambient_and_full_ms(scene, options_for(s.mode, threads), s.repeat, s.seconds, s.banded_ambient, s.one_walk);
        // On stderr: the table's row (stdout) keeps its columns.
        if (s.banded_ambient) {
            std::fprintf(stderr, "%s, %d thread(s): Phong ambient banded %.2f ms, / full %.3f; in mesh order / banded %.3f\n",
                         named.name.c_str(), threads, ms[4], ms[4] / ms[0], ms[1] / ms[4]);
        }
        if (s.one_walk) {
            const double one = ms.back();
            std::fprintf(stderr, "%s, %d thread(s): Phong ambient in one walk %.2f ms, / full %.3f; walks per thread / one walk %.3f\n",
                         named.name.c_str(), threads, one, one / ms[0], ms[1] / one);
        }
        std::printf("| %s | %s | %.0f | %dx%d | %d | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f | %.3f | %.1f | %.1f | %.1f | %s "
                    "| %.1f | %.1f | %s |\n",
                    named.name.c_str(), scene_class.c_str(), triangles, scene.image.columns,
                    scene.image.rows, threads, ms[0], ms[1], ms[2], ms[3], ms[1] / ms[0], ms[2] / ms[1], ms[3] / ms[1],
                    double(program_bytes) / kMiB, double(mesh_bytes(scene.mesh)) / kMiB, double(peak.bytes) / kMiB, peak.at.c_str(),
                    double(peak.bytes) / triangles, budget / triangles, double(peak.bytes) <= budget ? "met" : "not met");
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"phongrast alone on one speed scene: peak memory against the budget, ambient-only against full lighting"};
    Settings s;
    app.add_option("--scene", s.scene,
                   "icosphere-9.7k, icosphere-125k, icosphere-1.3M, icosphere-8M or a mesh of ../shared/assets");
    app.add_option("--rows", s.rows, "image side in pixels (default: the scene class's)");
    app.add_option("--order", s.order, "the mesh's order: generator, spatial or shuffled (bench/mesh_orders.hpp)")
        ->check(CLI::IsMember(phongrast_bench::mesh_order_names()));
    app.add_option("--mode", s.mode, "RenderOptions: exact or seed")->check(CLI::IsMember({"exact", "seed"}));
    app.add_option("--threads", s.threads, "thread counts, one row each")->check(CLI::Range(1, 256));
    app.add_option("--repeat", s.repeat, "timed rounds (median), at least")->check(CLI::Range(1, 1000));
    app.add_option("--seconds", s.seconds, "more rounds (up to 101) while the timed rounds would take less than this")
        ->check(CLI::Range(0.0, 600.0));
    app.add_flag("--header", s.header, "print the table's title and header first");
    app.add_flag("--banded-ambient", s.banded_ambient,
                 "also time Phong ambient with the fill in mesh order forbidden (sorted, binned, by bands), "
                 "interleaved with the others; its ratios on stderr");
    app.add_flag("--one-walk", s.one_walk,
                 "also time Phong ambient filled in mesh order in one walk whatever the threads (the walk per "
                 "thread forbidden), interleaved with the others; its ratios on stderr");
    bool no_assets = false, no_large = false, no_huge = false;
    app.add_flag("--list", s.list, "print the names of the speed scenes (less those of --no-...) and stop");
    app.add_flag("--no-assets", no_assets, "--list: without the meshes of ../shared/assets");
    app.add_flag("--no-large", no_large, "--list: without icosphere-1.3M");
    app.add_flag("--no-huge", no_huge, "--list: without icosphere-8M");
    CLI11_PARSE(app, argc, argv);
    s.selection = {!no_assets, !no_large, !no_huge};
    try {
        if (s.list) {
            list_scenes(s.selection);
        } else {
            run(s);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_goals: %s\n", error.what());
        return 1;
    }
    return 0;
}
