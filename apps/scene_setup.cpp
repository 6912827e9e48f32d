#include "scene_setup.hpp"

#include <filesystem>
#include <sstream>

#include "phongrast/camera.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/io/scene_load.hpp"
#include "phongrast/option_names.hpp"
#include "phongrast/smooth_normals.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

glm::dvec3 to_vector(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

}  // namespace

std::string find_default_scene() {
    // An installed copy moved to another prefix still finds its assets next to
    // itself: <prefix>/bin/phongrast -> <prefix>/share/phongrast.
    std::error_code ignored;
    const fs::path executable = fs::read_symlink("/proc/self/exe", ignored);
    const std::string candidates[] = {
        "assets/default.json",
        std::string(PHONGRAST_SOURCE_ASSETS_DIR) + "/default.json",
        (executable.parent_path().parent_path() / "share/phongrast/default.json").string(),
        std::string(PHONGRAST_INSTALLED_ASSETS_DIR) + "/default.json",
    };
    std::string tried;
    for (const std::string& candidate : candidates) {
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return candidate;
        tried += (tried.empty() ? "" : ", ") + candidate;
    }
    throw io::FileError("default scene not found; looked for " + tried +
                        " (give a scene file or a mesh: phongrast render SCENE.json)");
}

std::string choose_output(const std::string& output, const std::string& default_name, const Messages& messages) {
    const std::string path = output.empty() ? default_name : output;
    io::image_format_for(path);  // an unknown extension is an error before any rendering
    const fs::path folder = fs::path(path).parent_path();
    std::error_code error;
    if (!folder.empty() && !fs::is_directory(folder, error)) {
        throw io::FileError(path + ": output folder '" + folder.string() + "' does not exist");
    }
    // Refused now, not after the render, when the rename would fail.
    if (fs::is_directory(path, error)) throw io::FileError(path + ": is a folder; expected an image file name");
    if (output.empty() && fs::exists(path, error)) {
        messages.warning("replacing " + path + ", the default output name for this input (-o names another file)");
    }
    return path;
}

namespace {

/// How the library's scene builder is to load what the flags name: --size
/// (checked before any file is read), --mesh, and the batch's mesh reader.
io::SceneLoadOptions load_options(const SceneFlags& flags, const std::string& mesh_override) {
    io::SceneLoadOptions options;
    if (!flags.size.empty()) std::tie(options.columns, options.rows) = parse_size(flags.size);
    options.mesh_override = mesh_override;
    options.read_mesh = flags.read_mesh;
    return options;
}

/// The builder's result as the commands use it; its warnings and the
/// defaults it used are said now.
PreparedScene prepared_from(io::LoadedScene loaded, const Messages& messages) {
    for (const std::string& warning : loaded.warnings) messages.warning(warning);
    if (!loaded.defaults_note.empty()) messages.note(loaded.defaults_note);
    PreparedScene prepared;
    prepared.scene = std::move(loaded.scene);
    prepared.name = std::move(loaded.name);
    prepared.load_seconds = loaded.load_seconds;
    return prepared;
}

/// --smooth and --crease.
NormalOptions normal_options(const SceneFlags& flags) {
    NormalOptions options;
    options.sharing = flags.smooth == "position" ? NormalSharing::position : NormalSharing::vertex_index;
    options.crease_degrees = flags.crease;
    return options;
}

/// The checks render() makes, before any work, naming where the scene came
/// from: some values are only wrong together (colours, material and lights
/// that could light a pixel past 1e30), so no reader can name them alone.
void validate_prepared(const PreparedScene& prepared, const std::string& source) {
    try {
        validate_render(prepared.scene, prepared.options);
    } catch (const std::logic_error& error) {  // invalid_argument, or length_error for the image size
        throw std::invalid_argument(source + ": " + error.what());
    }
}

/// Shader, lighting and camera overrides, the camera check, and the options.
void apply_flags(PreparedScene& prepared, const SceneFlags& flags, const Messages& messages) {
    Scene& scene = prepared.scene;
    if (scene.lights.empty() && scene.lighting != Lighting::only_ambient()) {
        messages.warning("the scene has no lights: only the ambient term will show");
    }

    if (!flags.shader.empty()) scene.shader = parse_shader(flags.shader);
    if (!flags.lighting.empty()) scene.lighting = parse_lighting(flags.lighting);
    if (!flags.eye.empty()) scene.camera.eye = to_vector(flags.eye);
    if (!flags.lookat.empty()) scene.camera.lookat = to_vector(flags.lookat);
    if (!flags.up.empty()) scene.camera.up = to_vector(flags.up);
    if (flags.focal > 0.0) scene.camera.focal = flags.focal;
    if (!flags.sensor.empty()) {
        scene.camera.sensor_height = flags.sensor[0];
        scene.camera.sensor_width = flags.sensor[1];
    }
    const NormalOptions normals = normal_options(flags);
    if (!normals.is_contract()) {
        if (!scene.objects.empty()) {
            throw std::invalid_argument("--smooth/--crease: apply to a scene of one mesh; this scene places " +
                                        std::to_string(scene.objects.size()) + " objects");
        }
        scene.mesh = with_normals(scene.mesh, normals);
    }
    try {
        make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("command line: ") + error.what());
    }

    prepared.options = options_from_names(flags.options);
    prepared.options.threads = flags.threads;
    prepared.options.samples_per_axis = flags.samples;
}

}  // namespace

PreparedScene prepare_scene(const SceneFlags& flags, const Messages& messages) {
    PreparedScene prepared;
    std::string input = flags.input;
    std::string mesh_path = flags.mesh;
    if (input.empty() && mesh_path.empty()) {
        input = find_default_scene();
        messages.note("rendering the default scene " + input);
    }
    if (!input.empty() && io::has_mesh_extension(input)) {
        if (!mesh_path.empty()) {
            throw std::invalid_argument("--mesh: give either a mesh as the input or --mesh, not both");
        }
        mesh_path = input;
        input.clear();
    }

    if (input.empty()) {
        // Only a mesh: the library frames it; below, the user is told what was chosen.
        prepared = prepared_from(io::load_mesh_scene(mesh_path, load_options(flags, "")), messages);
    } else {
        io::LoadedScene loaded = io::load_scene(input, load_options(flags, mesh_path));
        if (mesh_path.empty()) mesh_path = loaded.mesh_path;
        prepared = prepared_from(std::move(loaded), messages);
    }
    const bool auto_framed = input.empty();
    apply_flags(prepared, flags, messages);
    validate_prepared(prepared, input.empty()      ? mesh_path
                                : mesh_path.empty() ? input
                                                    : input + " (mesh " + mesh_path + ")");

    if (auto_framed && !messages.quiet()) {
        std::ostringstream normal_flags;
        if (!normal_options(flags).is_contract()) normal_flags << " with --smooth " << flags.smooth << " --crease " << flags.crease;
        messages.note("no scene file: framed " + mesh_path + " automatically. This scene file reproduces the picture" +
                      normal_flags.str() + ":\n" +
                      io::scene_to_json(prepared.scene, fs::absolute(mesh_path).lexically_normal().string()));
    }
    return prepared;
}

PreparedScene prepare_scene_text(const std::string& text, const std::string& name, const std::string& folder,
                                 const SceneFlags& flags, const Messages& messages) {
    PreparedScene prepared = prepared_from(io::load_scene_text(text, name, folder, load_options(flags, "")), messages);
    prepared.name = name;
    apply_flags(prepared, flags, messages);
    validate_prepared(prepared, name);
    return prepared;
}

}  // namespace phongrast::cli
