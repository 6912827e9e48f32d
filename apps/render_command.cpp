// phongrast render: one scene to one PNG/EXR, optionally timed over --repeat runs.
#include <chrono>
#include <filesystem>
#include <optional>
#include <cstdio>

#include "commands.hpp"
#include "interrupt.hpp"
#include "process_exit.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/camera_record.hpp"
#include "phongrast/io/dataset_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/text_file.hpp"
#include "report.hpp"
#include "scene_setup.hpp"

namespace phongrast::cli {
namespace {

std::string milliseconds(double seconds) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f ms", seconds * 1e3);
    return buffer;
}

}  // namespace

void add_render_command(CLI::App& app, RenderCommand& command) {
    CLI::App* render = app.add_subcommand(
        "render",
        "Render a scene file or a mesh to PNG (8-bit, clamped, no gamma) or EXR (linear float). "
        "With no input, renders the default scene to ./default.png.");
    add_scene_flags(*render, command.scene,
                    "Output image, .png or .exr. Default: NAME.png (NAME.exr with --aov) in the current folder, "
                    "NAME being the input file's name without its extension (default for no input)");
    render->add_option("--repeat", command.repeat,
                       "Render K times after one warm-up and print the median, minimum and maximum render time "
                       "(loading and writing excluded)")
        ->check(CLI::Range(1, 100000));
    render->add_option("--stats-json", command.stats_json,
                       "Write the render times and statistics to this JSON file");
    render->add_option("--aov", command.aovs,
                       "Extra outputs next to the colour, written into the one .exr as channels: depth (Z), normal "
                       "(N.X, N.Y, N.Z), id (triangle index, unsigned), alpha (A); comma-separated, or all");
    render->add_option("--camera-out", command.camera_out,
                       "Write the image's camera to this JSON file: file name, width, height, K (OpenCV), "
                       "world_to_camera (OpenCV axes), camera_to_world_opengl (OpenGL/Blender axes), the look-at "
                       "form and the near plane; its \"camera\" is readable by --camera");
    add_png_compression_flag(*render, command.png_compression);
    add_dataset_file_flags(*render, command.dataset_files, command.depth_scale);
    render->add_flag("--transparent", command.transparent,
                     "Write a PNG with an alpha channel: the background transparent, edges partly so");
}

int run_render(const RenderCommand& command) {
    const Messages messages(command.scene.quiet);
    PreparedScene prepared = prepare_scene(command.scene, messages);
    // Extra outputs only fit an EXR: without -o they go to NAME.exr.
    const std::string output =
        choose_output(command.scene.output, prepared.name + (command.aovs.empty() ? ".png" : ".exr"), messages);
    const io::ImageFormat format = io::image_format_for(output);
    if (!command.aovs.empty()) {
        try {
            prepared.options.aovs = parse_aovs(command.aovs);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument(std::string("--") + error.what());
        }
        if (format != io::ImageFormat::exr) {
            throw std::invalid_argument("--aov: the extra outputs go into an EXR file; give -o NAME.exr, not " + output);
        }
    }
    if (command.transparent) {
        if (format != io::ImageFormat::png) {
            throw std::invalid_argument("--transparent: writes a PNG with alpha; give -o NAME.png, not " + output);
        }
        prepared.options.aovs.alpha = true;
    }
    io::DatasetFiles dataset_files;
    io::DatasetFileOptions dataset_options;
    dataset_options.depth_scale = command.depth_scale;
    dataset_options.png_compression = io::parse_png_compression(command.png_compression);
    if (!command.dataset_files.empty()) {
        try {
            dataset_files = io::parse_dataset_files(command.dataset_files);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument(std::string("--") + error.what());
        }
        try {
            io::check_dataset_files(dataset_files, dataset_options, prepared.scene);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument(std::string("--") + error.what());
        }
        dataset_files.add_planes_to(prepared.options.aovs);
    }
    if (!command.camera_out.empty()) {
        // Refused before rendering: a missing folder, a folder in the way.
        const std::filesystem::path folder = std::filesystem::path(command.camera_out).parent_path();
        std::error_code error;
        if (!folder.empty() && !std::filesystem::is_directory(folder, error)) {
            throw io::FileError(command.camera_out + ": --camera-out folder '" + folder.string() + "' does not exist");
        }
        if (std::filesystem::is_directory(command.camera_out, error)) {
            throw io::FileError(command.camera_out + ": --camera-out is a folder; expected a .json file name");
        }
    }
    stop_if_interrupted();

    using Clock = std::chrono::steady_clock;
    Timing timing;
    timing.load_seconds = prepared.load_seconds;
    const int runs = command.repeat > 0 ? command.repeat : 1;
    timing.warm_up = command.repeat > 0;
    // One Renderer for the warm-up and every timed run: after the first
    // frame the repeats allocate nothing, so --repeat times the steady state.
    const bool show_bar = messages.shows_progress() && command.repeat == 0;
    prepared.options.progress = progress_bar(show_bar, "rendering");
    // One frame (no --repeat) is a one-off render(), drawn into `one_off`'s
    // image (no copy out of render()'s kept memory): a Renderer would also
    // make what only later frames reuse, such as a reordered copy of a mesh
    // under 2^18 triangles, which one frame does not pay back.
    std::optional<Renderer> renderer;
    if (command.repeat > 0) renderer.emplace(prepared.options);
    if (timing.warm_up) {
        messages.progress(0, runs, "warm-up");
        const Clock::time_point start = Clock::now();
        renderer->render(prepared.scene);
        timing.warm_up_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    }
    RenderResult one_off;
    const RenderResult* last = &one_off;
    for (int run = 0; run < runs; ++run) {
        if (runs > 1) messages.progress(run + 1, runs, "rendering");
        const Clock::time_point start = Clock::now();
        if (renderer) {
            last = &renderer->render(prepared.scene);
        } else {
            render(prepared.scene, prepared.options, one_off);
        }
        timing.seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    const RenderResult& result = *last;
    clear_progress_bar(show_bar);
    messages.progress_done();
    if (result.stats.empty_scene) messages.warning("the mesh has no triangles: the image is the background alone");

    stop_if_interrupted();
    io::ImageWriteOptions image_options;
    image_options.png_compression = io::parse_png_compression(command.png_compression);
    // The dataset files first: the colour image, written last, marks the whole set as done (batch resumes by it).
    if (dataset_files.any()) {
        io::write_dataset_files(result.aovs, io::object_first_triangles(prepared.scene), output, dataset_files,
                                dataset_options);
    }
    if (!command.aovs.empty() && format == io::ImageFormat::exr) {
        io::write_exr_with_aovs(result.image, result.aovs, output);
    } else if (command.transparent) {
        io::write_png_with_alpha(result.image, result.aovs.alpha, prepared.scene.image.background, output,
                                 image_options);
    } else {
        io::write_image(result.image, output, image_options);
    }
    messages.result(summary_line(result.stats, timing.seconds.back(), prepared.load_seconds));
    if (command.repeat > 0) {
        messages.result("render time over " + std::to_string(runs) + " runs after 1 warm-up: median " +
                        milliseconds(timing.median()) + ", min " + milliseconds(timing.min()) + ", max " +
                        milliseconds(timing.max()));
    }
    if (!command.stats_json.empty()) {
        io::write_text_file(command.stats_json,
                            stats_json(timing, result.stats, prepared.scene, prepared.options));
    }
    std::string written = std::filesystem::absolute(output).lexically_normal().string();
    for (const std::string& file : io::dataset_file_paths(output, dataset_files)) {
        written += ", " + std::filesystem::path(file).filename().string();
    }
    messages.result("wrote " + written);
    if (!command.camera_out.empty()) {
        io::write_text_file(command.camera_out, io::camera_records_json({io::camera_record(
                                                    prepared.scene, output, command.camera_out)}));
        messages.result("wrote " + std::filesystem::absolute(command.camera_out).lexically_normal().string());
    }
    return end_one_off_process(0);
}

}  // namespace phongrast::cli
