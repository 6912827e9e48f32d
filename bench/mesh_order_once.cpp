// bench_mesh_order: what the order a mesh comes in costs, and what the
// renderer's reordering (src/mesh_order.hpp) wins back. One process renders
// one speed scene's mesh in the orders of mesh_orders.hpp in interleaved
// rounds, with the reordering on (a Renderer pays it once per mesh; render()
// on every call) and off (the mesh in the caller's order), and prints
// medians and their ratio to the spatially ordered mesh ("on" is the
// library's default: thresholds and locality test). --sweep instead times
// icospheres of several sizes with every mesh reordered, whatever its
// order, against none, to place the threshold of triangles.
#include <cstdio>
#include <ctime>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

// Internal: detail::set_mesh_order_walk_choice, for --walk.
#include "fill_driver.hpp"
#include "mesh_order.hpp"
#include "mesh_orders.hpp"
#include "phongrast/render.hpp"
#include "stage_table.hpp"
#include "stage_times.hpp"
#include "support/scenes.hpp"
#include "support/speed_scenes.hpp"
#include "support/timing.hpp"

namespace {

namespace support = phongrast::support;
using phongrast_bench::in_mesh_order;

constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

struct Settings {
    std::string scene = "icosphere-1.3M", shader = "gouraud";
    int threads = 1, repeat = 5, rows = 0;
    bool computed_normals = false, sweep = false;
    /// Only a Renderer with the reordering on (no "not reordered", no render()):
    /// the goal's ratio in a third of the time, and a profile of that path alone.
    bool renderer_only = false;
    /// The orders timed (default: all of mesh_order_names()).
    std::vector<std::string> orders;
    /// Prefix of the files of each contender's last image (empty: none).
    std::string dump;
    /// Each render timed by the process's CPU time, not the wall clock.
    bool cpu_time = false;
    /// The fill in mesh order's choice: auto, always or never (fill_driver.hpp).
    std::string walk = "auto";
    /// Each contender's stage medians (src/stage_times.hpp) after the table.
    bool stages = false;
};

bool g_cpu_time = false;

/// `work`'s wall time in milliseconds, or with --cpu-time the CPU time the process spent in it.
double time_work_ms(const std::function<void()>& work) {
    if (!g_cpu_time) return support::time_ms(work);
    const double start = support::process_cpu_ms();
    work();
    return support::process_cpu_ms() - start;
}

/// One way of rendering: an order, reordering on or off, Renderer or render().
struct Contender {
    std::string label;
    phongrast::Scene scene;
    bool reorder = true, one_off = false;
};

/// --stages: each contender's recorded passes (not its warm-up round's).
struct ContenderStages {
    std::vector<phongrast::detail::PassStageTimes> passes;
    int calls = 0;
};

/// The image's raw float RGB pixels written to `path` (to compare builds and orders with cmp).
void dump_pixels(const std::string& path, const phongrast::Image& image) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error("--dump: cannot write " + path);
    std::fwrite(image.pixels.data(), sizeof(glm::vec3), image.pixels.size(), file);
    std::fclose(file);
}

/// `label` as a file name: "shuffled, Renderer, not reordered" -> "shuffled-Renderer-not-reordered".
std::string file_name_of(const std::string& label) {
    std::string name;
    for (char c : label) {
        if (c == ',' || c == '(' || c == ')') continue;
        name += c == ' ' ? '-' : c;
    }
    return name;
}

/// Reordering as the library does it by default (both thresholds, the locality test).
/// With `dump`, each contender's last image is written to dump + its label + ".rgb".
/// With `stages` (one per contender), each contender's passes are recorded there.
std::vector<double> time_contenders(std::vector<Contender>& contenders, const phongrast::RenderOptions& options,
                                   int repeat, const std::string& dump = {},
                                   std::vector<ContenderStages>* stages = nullptr) {
    const std::size_t defaults = phongrast::detail::set_reorder_min_triangles(0);
    phongrast::detail::set_reorder_min_triangles(defaults);
    std::vector<phongrast::Renderer> renderers;
    for (std::size_t k = 0; k < contenders.size(); ++k) renderers.emplace_back(options);
    std::vector<std::function<double()>> calls;
    for (std::size_t k = 0; k < contenders.size(); ++k) {
        calls.push_back([&, k] {
            const Contender& c = contenders[k];
            const std::size_t previous = phongrast::detail::set_reorder_min_triangles(c.reorder ? defaults : kNever);
            if (stages != nullptr) phongrast::detail::record_stage_times(true);
            phongrast::RenderResult one_off;  // render()'s, kept for --dump (destroyed after the timing)
            const phongrast::RenderResult* last = &one_off;
            const double ms = time_work_ms([&] {
                if (c.one_off) {
                    one_off = phongrast::render(c.scene, options);
                } else {
                    last = &renderers[k].render(c.scene);
                }
            });
            phongrast::detail::set_reorder_min_triangles(previous);
            if (stages != nullptr) {
                phongrast::detail::record_stage_times(false);
                const std::vector<phongrast::detail::PassStageTimes> passes = phongrast::detail::take_stage_times();
                ContenderStages& mine = (*stages)[k];
                if (mine.calls++ > 0) mine.passes.insert(mine.passes.end(), passes.begin(), passes.end());
            }
            if (!dump.empty()) dump_pixels(dump + file_name_of(c.label) + ".rgb", last->image);
            return ms;
        });
    }
    return support::interleaved_medians(repeat, 1, calls);
}

phongrast::RenderOptions options_for(const Settings& s) {
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = s.threads;
    return options;
}

phongrast::Scene base_scene(const Settings& s, const std::string& name, int rows) {
    phongrast::Scene scene = support::speed_scene(name, rows).scene;
    scene.shader = phongrast::parse_shader(s.shader);
    if (s.computed_normals) scene.mesh.normals.clear();  // computed on every frame, as for a file without normals
    return scene;
}

void run_orders(const Settings& s) {
    const phongrast::Scene base = base_scene(s, s.scene, s.rows);
    std::vector<Contender> contenders;
    std::size_t spatial_index = 0;  // the ratios' baseline: spatial, Renderer (else the first contender)
    for (const std::string& order : s.orders.empty() ? phongrast_bench::mesh_order_names() : s.orders) {
        phongrast::Scene scene = base;
        scene.mesh = in_mesh_order(base.mesh, order);
        if (order == "spatial") spatial_index = contenders.size();
        contenders.push_back({order + ", Renderer", scene, true, false});
        if (s.renderer_only) continue;
        contenders.push_back({order + ", Renderer, not reordered", scene, false, false});
        contenders.push_back({order + ", render()", scene, true, true});
        contenders.push_back({order + ", render(), not reordered", scene, false, true});
    }
    std::vector<ContenderStages> stages(contenders.size());
    const std::vector<double> ms =
        time_contenders(contenders, options_for(s), s.repeat, s.dump, s.stages ? &stages : nullptr);
    const double spatial = ms[spatial_index];
    std::printf("\n%s, %zu triangles, %dx%d, %s, %s normals, %d thread(s), median of %d interleaved rounds%s\n\n",
                s.scene.c_str(), base.mesh.triangles.size(), base.image.columns, base.image.rows, s.shader.c_str(),
                s.computed_normals ? "computed" : "given", s.threads, s.repeat, s.cpu_time ? ", CPU time" : "");
    std::printf("| mesh order, how | %s | / spatial (Renderer) |\n|---|---:|---:|\n", s.cpu_time ? "CPU ms" : "ms");
    for (std::size_t k = 0; k < contenders.size(); ++k) {
        std::printf("| %s | %.1f | %.3f |\n", contenders[k].label.c_str(), ms[k], ms[k] / spatial);
    }
    if (!s.stages) return;
    std::printf("\n");
    for (std::size_t k = 0; k < contenders.size(); ++k) {
        std::printf("%s: %s\n", contenders[k].label.c_str(),
                    phongrast_bench::stage_medians_line(stages[k].passes, ms[k]).c_str());
    }
}

/// Icospheres of several sizes at 512x512: reordering on against off, for a
/// Renderer and for one-off render() calls, in the generator's order and shuffled.
void run_sweep(const Settings& s) {
    std::printf("\n| triangles | order | off ms | Renderer on / off | render() on / off |\n|---:|---|---:|---:|---:|\n");
    for (int frequency : {16, 32, 57, 80, 128, 181, 256}) {
        support::NamedScene named = support::icosphere_scene("sweep", frequency, 512);
        named.scene.shader = phongrast::parse_shader(s.shader);
        if (s.computed_normals) named.scene.mesh.normals.clear();
        for (const std::string order : {"generator", "shuffled"}) {
            phongrast::Scene scene = named.scene;
            scene.mesh = in_mesh_order(named.scene.mesh, order);
            // Threshold 0 for "on": every size is reordered.
            std::vector<Contender> contenders = {{"off", scene, false, false}, {"on", scene, true, false},
                                                 {"off, render()", scene, false, true},
                                                 {"on, render()", scene, true, true}};
            const std::size_t previous = phongrast::detail::set_reorder_min_triangles(0);
            const bool previous_always = phongrast::detail::set_reorder_always(true);  // no locality test
            std::vector<phongrast::Renderer> renderers;
            std::vector<std::function<double()>> calls;
            const phongrast::RenderOptions options = options_for(s);
            for (std::size_t k = 0; k < contenders.size(); ++k) renderers.emplace_back(options);
            for (std::size_t k = 0; k < contenders.size(); ++k) {
                calls.push_back([&, k] {
                    const Contender& c = contenders[k];
                    phongrast::detail::set_reorder_min_triangles(c.reorder ? 0 : kNever);
                    return support::time_ms([&] {
                        if (c.one_off) {
                            phongrast::render(c.scene, options);
                        } else {
                            renderers[k].render(c.scene);
                        }
                    });
                });
            }
            const std::vector<double> ms = support::interleaved_medians(s.repeat, 1, calls);
            phongrast::detail::set_reorder_min_triangles(previous);
            phongrast::detail::set_reorder_always(previous_always);
            std::printf("| %zu | %s | %.2f | %.3f | %.3f |\n", scene.mesh.triangles.size(), order.c_str(), ms[0],
                        ms[1] / ms[0], ms[3] / ms[2]);
            std::fflush(stdout);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"what a mesh's order costs, and what the renderer's reordering wins back"};
    Settings s;
    app.add_option("--scene", s.scene, "speed scene (support/speed_scenes.hpp)");
    app.add_option("--rows", s.rows, "image side in pixels (default: the scene class's)");
    app.add_option("--shader", s.shader, "flat, gouraud or phong");
    app.add_option("--threads", s.threads, "threads")->check(CLI::Range(1, 256));
    app.add_option("--repeat", s.repeat, "timed rounds (median)")->check(CLI::Range(1, 1000));
    app.add_flag("--computed-normals", s.computed_normals, "drop the mesh's normals: computed on every frame");
    app.add_flag("--renderer-only", s.renderer_only, "only a Renderer with the reordering on, for each order");
    app.add_option("--orders", s.orders, "orders to time (generator, spatial, shuffled; default all)")
        ->delimiter(',');
    app.add_option("--dump", s.dump,
                   "write each contender's last image's raw float RGB pixels to this prefix + its label + .rgb");
    app.add_flag("--cpu-time", s.cpu_time,
                 "time each render by the process's CPU time (less disturbed by other work on a loaded machine)");
    app.add_flag("--sweep", s.sweep, "icospheres of 5k-1.3M triangles: where reordering starts to pay");
    app.add_option("--walk", s.walk, "the fill in mesh order: auto (the render's choice), always or never")
        ->check(CLI::IsMember({"auto", "always", "never"}));
    app.add_flag("--stages", s.stages,
                 "also print each contender's median time per render-pass stage (vertices, walks, ...) and the rest of "
                 "the frame");
    CLI11_PARSE(app, argc, argv);
    g_cpu_time = s.cpu_time;
    if (s.walk != "auto") {
        phongrast::detail::set_mesh_order_walk_choice(s.walk == "always" ? phongrast::detail::WalkChoice::always
                                                                         : phongrast::detail::WalkChoice::never);
    }
    try {
        if (s.sweep) {
            run_sweep(s);
        } else {
            run_orders(s);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_mesh_order: %s\n", error.what());
        return 1;
    }
    return 0;
}
