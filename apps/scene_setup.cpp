#include "scene_setup.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
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

/// A pose flag's 12 or 16 numbers, row by row, as [R | t] (a 4th row must be 0,0,0,1).
Matrix3x4 pose_from_flag(const std::vector<double>& numbers, const std::string& flag) {
    if (numbers.size() != 12 && numbers.size() != 16) {
        throw std::invalid_argument(flag + ": expected 12 or 16 numbers (3 or 4 rows of 4, row by row), got " +
                                    std::to_string(numbers.size()));
    }
    if (numbers.size() == 16 && !(numbers[12] == 0.0 && numbers[13] == 0.0 && numbers[14] == 0.0 && numbers[15] == 1.0)) {
        throw std::invalid_argument(flag + ": expected the last row 0,0,0,1");
    }
    Matrix3x4 pose{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) pose[i][j] = numbers[static_cast<std::size_t>(i * 4 + j)];
    }
    return pose;
}

/// --camera, --projection, the look-at flags, then --K and the pose flags.
void apply_camera_flags(Scene& scene, const SceneFlags& flags, const Messages& messages) {
    Camera& camera = scene.camera;
    if (!flags.camera_file.empty()) {
        std::vector<std::string> warnings;
        camera = io::read_camera_file(flags.camera_file, &warnings);
        for (const std::string& warning : warnings) messages.warning(warning);
    }
    const bool look_at_flags = !flags.eye.empty() || !flags.lookat.empty() || !flags.up.empty() || flags.focal > 0.0 ||
                               !flags.sensor.empty();
    const bool opencv_flags = !flags.K.empty() || !flags.world_to_camera.empty() || !flags.camera_to_world.empty();
    if (!flags.world_to_camera.empty() && !flags.camera_to_world.empty()) {
        throw std::invalid_argument("--world-to-camera, --camera-to-world: give one of the two, not both");
    }
    if (opencv_flags && look_at_flags) {
        throw std::invalid_argument("--K/--world-to-camera/--camera-to-world and --eye/--lookat/--up/--focal/--sensor: "
                                    "an OpenCV camera is placed by its matrices; give one kind of camera flags");
    }
    if (!flags.projection.empty()) {
        const bool orthographic = flags.projection == "orthographic";
        if (camera.model == CameraModel::opencv || opencv_flags) {
            if (orthographic) {
                throw std::invalid_argument("--projection orthographic: an OpenCV camera (K) is a perspective camera; "
                                            "an orthographic one is given by --eye, --lookat, --up and --sensor");
            }
        } else {
            camera.model = orthographic ? CameraModel::orthographic : CameraModel::look_at;
        }
    }
    if (look_at_flags && camera.model == CameraModel::opencv) {
        throw std::invalid_argument("--eye/--lookat/--up/--focal/--sensor: the camera is an OpenCV camera (K), placed "
                                    "by its matrices; use --K and --world-to-camera, or --camera");
    }
    if (!flags.eye.empty()) camera.eye = to_vector(flags.eye);
    if (!flags.lookat.empty()) camera.lookat = to_vector(flags.lookat);
    if (!flags.up.empty()) camera.up = to_vector(flags.up);
    if (flags.focal > 0.0) camera.focal = flags.focal;
    if (!flags.sensor.empty()) {
        camera.sensor_height = flags.sensor[0];
        camera.sensor_width = flags.sensor[1];
    }
    if (!opencv_flags) return;

    // What the flags do not give comes from the scene's camera (its OpenCV form for a look-at one).
    OpenCvCamera cv;
    try {
        cv = opencv_form(camera, scene.image.rows, scene.image.columns);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("--K/--world-to-camera: the scene's camera: ") + error.what());
    }
    if (!flags.K.empty()) {
        if (flags.K.size() != 4 && flags.K.size() != 5) {
            throw std::invalid_argument("--K: expected fx,fy,cx,cy or fx,fy,cx,cy,skew, got " +
                                        std::to_string(flags.K.size()) + " numbers");
        }
        for (std::size_t i = 0; i < 2; ++i) {
            if (!(flags.K[i] > 0.0) || !std::isfinite(flags.K[i])) {
                throw std::invalid_argument(std::string("--K: ") + (i == 0 ? "fx" : "fy") +
                                            " must be a positive finite number of pixels, got " +
                                            std::to_string(flags.K[i]));
            }
        }
        cv.fx = flags.K[0];
        cv.fy = flags.K[1];
        cv.cx = flags.K[2];
        cv.cy = flags.K[3];
        cv.skew = flags.K.size() == 5 ? flags.K[4] : 0.0;
    }
    if (!flags.world_to_camera.empty()) {
        cv.world_to_camera = pose_from_flag(flags.world_to_camera, "--world-to-camera");
        validate_pose(cv.world_to_camera, "--world-to-camera");
    }
    if (!flags.camera_to_world.empty()) {
        cv.world_to_camera = invert_pose(pose_from_flag(flags.camera_to_world, "--camera-to-world"), "--camera-to-world");
    }
    camera.model = CameraModel::opencv;
    camera.opencv = cv;
}

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
    apply_camera_flags(scene, flags, messages);
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
