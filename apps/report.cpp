#include "report.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "phongrast/option_names.hpp"

namespace phongrast::cli {

Messages::Messages(bool quiet) : quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0) {}

void Messages::note(const std::string& text) const {
    if (!quiet_) std::cerr << "phongrast: " << text << '\n';
}

void Messages::warning(const std::string& text) const {
    if (!quiet_) std::cerr << "phongrast: warning: " << text << '\n';
}

void Messages::result(const std::string& text) const {
    if (!quiet_) std::cout << text << std::endl;
}

void Messages::progress(int step, int steps, const std::string& what) const {
    if (quiet_ || !terminal_) return;
    std::cerr << "\r\033[K[" << step << '/' << steps << "] " << what << std::flush;
}

void Messages::progress_done() const {
    if (quiet_ || !terminal_) return;
    std::cerr << "\r\033[K" << std::flush;
}

std::string summary_line(const RenderStats& stats, double seconds, double load_seconds) {
    char load[64] = "";
    if (load_seconds >= 0.0) std::snprintf(load, sizeof load, "load %.2f ms, ", load_seconds * 1e3);
    char buffer[576];
    std::snprintf(buffer, sizeof buffer,
                  "%llu triangles in, %llu drawn, %llu dropped, %llu clipped, %llu culled, %llu outside the view, "
                  "%llu out of range, %llu between samples, %llu degenerate; "
                  "%llu samples covered, %llu shaded; %srender %.2f ms",
                  static_cast<unsigned long long>(stats.triangles_in),
                  static_cast<unsigned long long>(stats.triangles_drawn),
                  static_cast<unsigned long long>(stats.triangles_dropped),
                  static_cast<unsigned long long>(stats.triangles_clipped),
                  static_cast<unsigned long long>(stats.triangles_culled),
                  static_cast<unsigned long long>(stats.triangles_outside),
                  static_cast<unsigned long long>(stats.triangles_out_of_range),
                  static_cast<unsigned long long>(stats.triangles_between_samples),
                  static_cast<unsigned long long>(stats.triangles_degenerate),
                  static_cast<unsigned long long>(stats.samples_covered),
                  static_cast<unsigned long long>(stats.samples_shaded), load, seconds * 1e3);
    return buffer;
}

double Timing::median() const {
    if (seconds.empty()) return 0.0;
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t middle = sorted.size() / 2;
    return sorted.size() % 2 == 1 ? sorted[middle] : 0.5 * (sorted[middle - 1] + sorted[middle]);
}

double Timing::min() const { return seconds.empty() ? 0.0 : *std::min_element(seconds.begin(), seconds.end()); }
double Timing::max() const { return seconds.empty() ? 0.0 : *std::max_element(seconds.begin(), seconds.end()); }

std::string stats_json(const Timing& timing, const RenderStats& stats, const Scene& scene,
                       const RenderOptions& options) {
    nlohmann::ordered_json document;
    document["render_seconds"] = {
        {"median", timing.median()}, {"min", timing.min()}, {"max", timing.max()},
        {"runs", timing.seconds},    {"warm_up", timing.warm_up}};
    if (timing.warm_up_seconds >= 0.0) document["render_seconds"]["first"] = timing.warm_up_seconds;
    if (timing.load_seconds >= 0.0) document["load_seconds"] = timing.load_seconds;
    std::size_t triangles = scene.mesh.triangles.size();
    std::size_t vertices = scene.mesh.positions.size();
    for (const SceneObject& object : scene.objects) {  // each placement counts
        triangles += object.mesh->triangles.size();
        vertices += object.mesh->positions.size();
    }
    document["scene"] = {{"triangles", triangles},
                         {"vertices", vertices},
                         {"objects", scene.objects.size()},
                         {"height", scene.image.rows},
                         {"width", scene.image.columns},
                         {"shader", to_string(scene.shader)},
                         {"lighting", to_string(scene.lighting)},
                         {"lights", scene.lights.size()},
                         {"mode", option_name(options, "mode")},
                         {"visibility", option_name(options, "visibility")},
                         {"overdraw", option_name(options, "overdraw")},
                         {"texture_filter", option_name(options, "texture_filter")},
                         {"threads", options.threads},
                         {"samples_per_axis", options.samples_per_axis}};
    nlohmann::ordered_json& counts = document["stats"];
    for (const RenderCounter& counter : render_counters()) counts[counter.name] = stats.*counter.field;
    counts["effects"] = to_string(stats.effects);
    counts["back_faces_culled"] = stats.back_faces_culled;
    counts["empty_scene"] = stats.empty_scene;
    counts["seconds"] = stats.seconds;
    return document.dump(2) + "\n";
}

}  // namespace phongrast::cli
