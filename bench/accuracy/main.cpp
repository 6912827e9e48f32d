// phongrast_accuracy: what accuracy costs in time.
//
// For each scene: renders the reference (Phong, exact preset, depth buffer,
// 8x8 samples, double), screens every combination of the accuracy options
// once, then times (median of --runs after a warm-up, 1 thread and all
// threads) the seed and exact presets, every option switched alone away from
// each, and the combinations on the screening's Pareto front. Writes a CSV per
// scene, one Markdown file of tables, an error-vs-time plot and a strip of
// error heat maps per scene.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <tbb/info.h>

#include "phongrast/render.hpp"
#include "pictures.hpp"
#include "support/accuracy_configurations.hpp"
#include "support/image_compare.hpp"
#include "support/pareto.hpp"
#include "support/scenes.hpp"
#include "support/shared_scenes.hpp"
#include "support/timing.hpp"
#include "texture_filters.hpp"

namespace fs = std::filesystem;
using namespace phongrast;
using namespace phongrast::support;
using namespace phongrast_bench;

namespace {

struct Settings {
    int size = 256;
    int runs = 5;
    std::string out = "accuracy-report";
    std::string images;  ///< defaults to out
    std::vector<std::string> only_scenes;
    bool shared_meshes = true;
    /// Above this many triangles only the timed configurations are rendered (no screening of all 480).
    std::size_t screen_max_triangles = 20000;
    std::string shared_assets = shared_assets_folder();
    std::string default_scene = PHONGRAST_PROJECT_ASSETS_DIR "/default.json";
    bool texture_filters = true;
};

struct Row {
    std::string name;  ///< "seed + gouraud", "front", or "" for screened-only
    Configuration configuration;
    ErrorMetrics error;
    double screen_ms = NAN;  ///< one unwarmed run, 1 thread
    double ms_one = NAN;     ///< median, 1 thread
    double ms_all = NAN;     ///< median, all threads
    bool measured = false, on_front = false;
    PointKind kind = PointKind::screened;
};

Image render_as(Scene scene, const Configuration& c, int threads, double* ms = nullptr) {
    scene.shader = c.shader;
    RenderOptions options = c.options;
    options.threads = threads;
    Image image;
    const double elapsed = time_ms([&] { image = render(scene, options).image; });
    if (ms) *ms = elapsed;
    return image;
}

double median_ms(const Scene& scene, const Configuration& c, int threads, int runs) {
    render_as(scene, c, threads);  // warm-up
    std::vector<double> times(static_cast<std::size_t>(runs));
    for (double& t : times) render_as(scene, c, threads, &t);
    return median(times);
}

std::string fixed(double value, int digits) {
    if (std::isinf(value)) return "inf";
    if (std::isnan(value)) return "";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

std::string general(double value) {
    if (std::isinf(value)) return "inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
    return buffer;
}

std::vector<NamedScene> load_scenes(const Settings& s) {
    std::vector<NamedScene> scenes;
    if (fs::exists(s.default_scene)) {
        NamedScene named{"default", "the default scene (assets/default.json)", read_scene_with_mesh(s.default_scene)};
        named.scene.image.rows = named.scene.image.columns = s.size;
        scenes.push_back(std::move(named));
    } else {
        std::cerr << "note: " << s.default_scene << " not found: skipping the default scene\n";
    }
    for (NamedScene& generated : generated_scenes(s.size)) scenes.push_back(std::move(generated));
    if (s.shared_meshes) {
        std::vector<std::string> notes;
        for (NamedScene& named : shared_scenes(s.shared_assets, s.size, s.size, {}, notes)) {
            scenes.push_back(std::move(named));
        }
        for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
    }
    if (!s.only_scenes.empty()) {
        std::vector<NamedScene> kept;
        for (NamedScene& scene : scenes) {
            if (std::find(s.only_scenes.begin(), s.only_scenes.end(), scene.name) != s.only_scenes.end()) {
                kept.push_back(std::move(scene));
            }
        }
        scenes = std::move(kept);
    }
    return scenes;
}

void write_csv(const std::string& path, const std::string& scene, const std::vector<Row>& rows) {
    std::ofstream out(path + ".tmp");
    out << "scene,name,key,shader,light_vectors,interpolation,visibility,border,samples_per_axis,pattern,"
           "precision,rmse,psnr_db,max_abs,share_off,ms_1_thread,ms_all_threads,screen_ms_1_thread,on_front\n";
    for (const Row& r : rows) {
        const RenderOptions& o = r.configuration.options;
        out << scene << ',' << r.name << ',' << key(r.configuration) << ',' << to_string(r.configuration.shader) << ','
            << (o.light_vectors == LightVectors::triangle_centroid ? "triangle_centroid" : "shaded_point") << ','
            << (o.interpolation == Interpolation::screen_affine ? "screen_affine" : "perspective_correct") << ','
            << (o.visibility == Visibility::painter ? "painter" : "depth_buffer") << ','
            << (o.border == BorderPolicy::drop_triangle ? "drop_triangle" : "clip") << ',' << o.samples_per_axis << ','
            << (o.sample_pattern == SamplePattern::ordered_grid ? "ordered_grid" : "rotated_grid") << ','
            << (o.precision == Precision::single_float ? "single_float" : "double_float") << ','
            << general(r.error.rmse) << ',' << fixed(r.error.psnr_db, 2) << ',' << general(r.error.max_abs) << ','
            << fixed(r.error.share_off, 5) << ',' << fixed(r.ms_one, 3) << ',' << fixed(r.ms_all, 3) << ','
            << fixed(r.screen_ms, 3) << ',' << (r.on_front ? 1 : 0) << '\n';
    }
    out.close();
    fs::rename(path + ".tmp", path);
}

std::string markdown_table(const std::vector<const Row*>& rows, double seed_ms) {
    std::ostringstream md;
    md << "| configuration | RMSE | PSNR dB | max err | px > 1/255 | ms, 1 thread | ms, all threads | x seed time | front |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (const Row* r : rows) {
        md << "| " << r->name << " | " << general(r->error.rmse) << " | " << fixed(r->error.psnr_db, 1) << " | "
           << general(r->error.max_abs) << " | " << fixed(100.0 * r->error.share_off, 1) << "% | "
           << fixed(r->ms_one, 2) << " | " << fixed(r->ms_all, 2) << " | " << fixed(r->ms_one / seed_ms, 2) << " | "
           << (r->on_front ? "*" : "") << " |\n";
    }
    return md.str();
}

std::string run_scene(const NamedScene& named, const Settings& s) {
    const Scene& scene = named.scene;
    const auto scene_start = std::chrono::steady_clock::now();
    std::cerr << "== " << named.name << ": " << named.description << "\n";

    const Configuration reference_config = reference_configuration();
    double reference_ms = 0.0;
    const Image reference = render_as(scene, reference_config, 0, &reference_ms);
    Configuration coarser = reference_config;
    coarser.options.samples_per_axis = 4;
    const ErrorMetrics convergence = compare(render_as(scene, coarser, 0), reference);

    // Screening: every combination once, 1 thread; the error is exact, the time rough.
    // Large meshes screen only the presets and their single switches (time budget).
    const bool screen_all = scene.mesh.triangles.size() <= s.screen_max_triangles;
    std::vector<Configuration> screened;
    if (screen_all) {
        screened = every_combination();
    } else {
        std::map<std::string, Configuration> unique;
        for (const auto& base : {one_switch_away("seed", seed_configuration(scene.shader)),
                                 one_switch_away("exact", exact_configuration(scene.shader))}) {
            for (const NamedConfiguration& c : base) unique.emplace(key(c.configuration), c.configuration);
        }
        for (const auto& entry : unique) screened.push_back(entry.second);
    }
    std::vector<Row> rows;
    std::map<std::string, std::size_t> by_key;
    std::map<std::string, Image> images;  // kept for the heat maps
    for (const Configuration& c : screened) {
        Row row;
        row.configuration = c;
        const Image image = render_as(scene, c, 1, &row.screen_ms);
        row.error = compare(image, reference);
        by_key[key(c)] = rows.size();
        rows.push_back(row);
        images[key(c)] = image;
    }
    std::vector<double> screen_times, screen_errors;
    for (const Row& r : rows) {
        screen_times.push_back(r.screen_ms);
        screen_errors.push_back(r.error.rmse);
    }
    const std::vector<std::size_t> screen_front = pareto_front(screen_times, screen_errors);

    // What gets timed properly: both presets, one switch away from each, the screening front.
    std::vector<std::size_t> measured;
    const auto mark = [&](const NamedConfiguration& named_config, PointKind kind) {
        Row& row = rows[by_key.at(key(named_config.configuration))];
        if (row.measured) return;
        row.measured = true;
        row.name = named_config.name;
        row.kind = kind;
        measured.push_back(by_key.at(key(named_config.configuration)));
    };
    for (const NamedConfiguration& c : one_switch_away("seed", seed_configuration(scene.shader))) mark(c, PointKind::from_seed);
    for (const NamedConfiguration& c : one_switch_away("exact", exact_configuration(scene.shader))) mark(c, PointKind::from_exact);
    for (std::size_t index : screen_front) mark({key(rows[index].configuration), rows[index].configuration}, PointKind::front_only);

    for (std::size_t index : measured) {
        Row& row = rows[index];
        row.ms_one = median_ms(scene, row.configuration, 1, s.runs);
        row.ms_all = median_ms(scene, row.configuration, 0, s.runs);
    }
    std::vector<double> times, errors;
    for (std::size_t index : measured) {
        times.push_back(rows[index].ms_one);
        errors.push_back(rows[index].error.rmse);
    }
    std::vector<std::size_t> front;
    for (std::size_t k : pareto_front(times, errors)) {
        rows[measured[k]].on_front = true;
        front.push_back(measured[k]);
    }

    fs::create_directories(s.out);
    write_csv(s.out + "/accuracy_" + named.name + ".csv", named.name, rows);

    // Plot: every screened point, and the measured ones at their medians.
    std::vector<PlotPoint> points;
    std::vector<std::size_t> front_points;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        if (!r.measured) points.push_back({r.screen_ms, r.error.rmse, PointKind::screened, ""});
    }
    for (std::size_t index : measured) {
        const Row& r = rows[index];
        // Every point of the front is named by its configuration, and so are the two presets.
        const bool on_front = std::find(front.begin(), front.end(), index) != front.end();
        if (on_front) front_points.push_back(points.size());
        points.push_back({r.ms_one, r.error.rmse, r.kind, on_front || r.name == "seed" || r.name == "exact" ? r.name : ""});
    }
    std::sort(front_points.begin(), front_points.end(),
              [&](std::size_t a, std::size_t b) { return points[a].milliseconds < points[b].milliseconds; });
    const std::string images_dir = s.images.empty() ? s.out : s.images;
    fs::create_directories(images_dir);
    write_error_time_plot(images_dir + "/accuracy_" + named.name + "_plot.png",
                          named.name + ": error vs time, " + std::to_string(scene.image.columns) + "x" +
                              std::to_string(scene.image.rows),
                          points, front_points);

    // Heat maps of the main configurations.
    const auto config_of = [&](const std::string& name) -> const Row& {
        for (std::size_t index : measured) {
            if (rows[index].name == name) return rows[index];
        }
        throw std::logic_error("no configuration named " + name);
    };
    std::vector<Panel> panels{{"reference", reference, {}}};
    const Row& seed_row = config_of("seed");
    panels.push_back({"seed", images.at(key(seed_row.configuration)), {}});
    // seed, exact, Gouraud (the seed's claim), the two single switches away
    // from exact that cost the most accuracy here, and 4x4 samples.
    std::vector<std::string> shown{"seed", "exact", "exact + gouraud"};
    std::vector<const Row*> worst;
    for (std::size_t index : measured) {
        const std::string& name = rows[index].name;
        if (name.rfind("exact + ", 0) == 0 && name != "exact + flat" && name != "exact + gouraud") {
            worst.push_back(&rows[index]);
        }
    }
    std::sort(worst.begin(), worst.end(), [](const Row* a, const Row* b) { return a->error.rmse > b->error.rmse; });
    for (std::size_t k = 0; k < worst.size() && k < 2; ++k) shown.push_back(worst[k]->name);
    shown.push_back("exact + 4x4 ordered");
    for (const std::string& name : shown) {
        const Row& r = config_of(name);
        panels.push_back({std::string("error: ") + name, reference, error_map(images.at(key(r.configuration)), reference)});
    }
    write_panels(images_dir + "/accuracy_" + named.name + "_errors.png", panels);

    // Markdown.
    std::vector<const Row*> table;
    for (std::size_t index : measured) table.push_back(&rows[index]);
    double smallest = INFINITY;
    for (const Row* r : table) {
        if (r->error.rmse > 0) smallest = std::min(smallest, r->error.rmse);
    }
    std::ostringstream md;
    md << "### " << named.name << "\n\n" << named.description << ". " << scene.image.columns << "x"
       << scene.image.rows << " pixels, " << scene.mesh.triangles.size() << " triangles, scene shader "
       << to_string(scene.shader) << ".\n\n"
       << "Reference (" << key(reference_config) << ") took " << fixed(reference_ms, 0)
       << " ms. Its convergence: 4x4 against 8x8 samples differ by RMSE " << general(convergence.rmse)
       << " (max " << general(convergence.max_abs) << ", " << fixed(100.0 * convergence.share_off, 2)
       << "% of pixels off by more than 1/255); the smallest non-zero RMSE below is " << general(smallest) << ".\n\n"
       << (screen_all ? "All 480 combinations were screened; the table has the timed ones.\n\n"
                      : "Not screened (more than " + std::to_string(s.screen_max_triangles) +
                            " triangles): the front is among the timed configurations only.\n\n")
       << markdown_table(table, rows[by_key.at(key(seed_configuration(scene.shader)))].ms_one) << "\n"
       << "Pareto front of the timed configurations (fastest first): ";
    for (std::size_t k = 0; k < front.size(); ++k) md << (k ? " -> " : "") << "`" << key(rows[front[k]].configuration) << "`";
    md << ".\n\n![" << named.name << ": error vs time](images/accuracy_" << named.name << "_plot.png)\n\n"
       << "![" << named.name << ": error heat maps](images/accuracy_" << named.name << "_errors.png)\n\n";
    std::cerr << "   " << rows.size() << " screened, " << measured.size() << " timed, " << front.size()
              << " on the front, " << fixed(milliseconds_since(scene_start) / 1000.0, 1) << " s\n";
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    CLI::App app{"phongrast_accuracy: the error and time of every accuracy option against a reference"};
    app.add_option("--size", s.size, "image width and height in pixels")->check(CLI::Range(8, 2048));
    app.add_option("--runs", s.runs, "timed runs per configuration after one warm-up (median)")->check(CLI::Range(1, 100));
    app.add_option("--out", s.out, "folder for the CSV files and the Markdown tables");
    app.add_option("--images", s.images, "folder for the PNG plots and heat maps (default: --out)");
    app.add_option("--scenes", s.only_scenes, "only these scenes (default, sphere, floor, shiny, overlap, suzanne, ...)")
        ->delimiter(',');
    app.add_flag("!--no-shared-meshes", s.shared_meshes, "skip the meshes in ../shared/assets");
    app.add_option("--shared-assets", s.shared_assets, "folder of the shared meshes");
    app.add_flag("!--no-texture-filters", s.texture_filters, "skip the texture filter tables (a floor and a close-up)");
    app.add_option("--screen-max-triangles", s.screen_max_triangles,
                   "screen all 480 combinations only for meshes up to this many triangles");
    CLI11_PARSE(app, argc, argv);

    try {
        const std::vector<NamedScene> scenes = load_scenes(s);
        if (scenes.empty()) {
            std::cerr << "error: no scene to run (check --scenes)\n";
            return 1;
        }
        std::ostringstream md;
        md << "<!-- written by phongrast_accuracy --size " << s.size << " --runs " << s.runs << "; "
           << tbb::info::default_concurrency() << " threads for 'all threads' -->\n\n";
        for (const NamedScene& scene : scenes) md << run_scene(scene, s);
        if (s.texture_filters) md << texture_filter_section(s.size, s.runs);
        fs::create_directories(s.out);
        const std::string path = s.out + "/accuracy_tables.md";
        {
            std::ofstream out(path + ".tmp");
            out << md.str();
        }
        fs::rename(path + ".tmp", path);
        std::cerr << "wrote " << path << "\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
