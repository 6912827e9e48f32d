#include "scene_setup.hpp"

#include <chrono>
#include <filesystem>
#include <sstream>

#include "phongrast/camera.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/smooth_normals.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

/// Reads a mesh in any supported format (through the batch command's cache
/// when it passes one); `seconds` is the time it took.
io::MeshFile load_mesh(const std::string& path, const SceneFlags& flags, const Messages& messages, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    io::MeshFile mesh = flags.read_mesh ? flags.read_mesh(path) : io::read_mesh(path);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const std::string& warning : mesh.warnings) messages.warning(warning);
    return mesh;
}

std::string describe(const PhongMaterial& m) {
    std::ostringstream out;
    out << "ka " << m.ka.x << ", kd " << m.kd.x << ", ks " << m.ks.x << ", n " << m.n;
    return out.str();
}

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

std::string choose_output(const std::string& output, const std::string& default_name) {
    const std::string path = output.empty() ? default_name : output;
    io::image_format_for(path);  // an unknown extension is an error before any rendering
    const fs::path folder = fs::path(path).parent_path();
    std::error_code error;
    if (!folder.empty() && !fs::is_directory(folder, error)) {
        throw io::FileError(path + ": output folder '" + folder.string() + "' does not exist");
    }
    // Refused now, not after the render, when the rename would fail.
    if (fs::is_directory(path, error)) throw io::FileError(path + ": is a folder; expected an image file name");
    return path;
}

namespace {

/// The scene branch of prepare_scene: the parsed file with its mesh loaded
/// and its material resolved (scene, then MTL, then defaults).
Scene scene_from_file(io::SceneFile file, const std::string& input, const std::string& mesh_override,
                      const SceneFlags& flags, const Messages& messages, double& load_seconds) {
    if (!mesh_override.empty()) {
        file.mesh_path = mesh_override;
    } else if (file.mesh_path.empty()) {
        throw io::FileError(input + ": /mesh: missing required field; expected a mesh file name (.obj, .ply, .stl, .gltf, .glb; or give --mesh)");
    }
    std::error_code error;
    if (mesh_override.empty() && !fs::exists(file.mesh_path, error)) {
        // Name the scene field too: the path was resolved against the scene's folder.
        throw io::FileError(input + ": /mesh: " + file.mesh_path +
                            ": mesh not found (no such file; a relative \"mesh\" is relative to the scene file)");
    }
    io::MeshFile obj = load_mesh(file.mesh_path, flags, messages, load_seconds);
    Scene scene = std::move(file.scene);
    scene.mesh = std::move(obj.mesh);
    std::vector<std::string> defaults_used;
    scene.material = io::resolve_material(file.material, obj.material, &defaults_used);
    if (!defaults_used.empty()) {
        std::string names;
        for (const std::string& name : defaults_used) names += (names.empty() ? "" : ", ") + name;
        messages.note("no " + names + " in " + input + (obj.material ? " or the mesh's MTL" : " (and the mesh has no MTL)") +
                      "; using the defaults, material: " + describe(scene.material));
    }
    if (!flags.size.empty()) {
        const auto [columns, rows] = parse_size(flags.size);
        scene.image.rows = rows;
        scene.image.columns = columns;
    }
    return scene;
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
    if (!normals.is_contract()) scene.mesh = with_normals(scene.mesh, normals);
    try {
        make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("command line: ") + error.what());
    }

    prepared.options = flags.mode == "seed" ? RenderOptions::seed() : RenderOptions::exact();
    prepared.options.threads = flags.threads;
    prepared.options.visibility = flags.visibility == "depth-buffer" ? Visibility::depth_buffer : Visibility::painter;
    prepared.options.overdraw = flags.overdraw == "visible" ? Overdraw::shade_visible
                                : flags.overdraw == "all"   ? Overdraw::shade_all
                                                            : Overdraw::automatic;
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

    bool auto_framed = false;
    if (input.empty()) {
        // Only a mesh: frame it and tell the user what was chosen.
        int rows = 512;
        int columns = 512;
        if (!flags.size.empty()) std::tie(columns, rows) = parse_size(flags.size);
        io::MeshFile obj = load_mesh(mesh_path, flags, messages, prepared.load_seconds);
        const std::optional<PhongMaterial> mtl = obj.material;
        prepared.scene = io::frame_mesh(std::move(obj.mesh), rows, columns);
        if (mtl) prepared.scene.material = *mtl;
        prepared.name = fs::path(mesh_path).stem().string();
        auto_framed = true;
    } else {
        if (!flags.size.empty()) parse_size(flags.size);  // a bad --size is reported before the files
        io::SceneFile file = io::read_scene_file(input);
        for (const std::string& warning : file.warnings) messages.warning(warning);
        const std::string mesh_override = mesh_path;
        if (mesh_path.empty()) mesh_path = file.mesh_path;
        prepared.scene = scene_from_file(std::move(file), input, mesh_override, flags, messages, prepared.load_seconds);
        prepared.name = fs::path(input).stem().string();
    }
    apply_flags(prepared, flags, messages);
    validate_prepared(prepared, input.empty() ? mesh_path : input + " (mesh " + mesh_path + ")");

    if (auto_framed && !messages.quiet()) {
        std::ostringstream normal_flags;
        if (!normal_options(flags).is_contract()) normal_flags << " with --smooth " << flags.smooth << " --crease " << flags.crease;
        messages.note("no scene file: framed " + mesh_path + " automatically. This scene file reproduces the picture" +
                      normal_flags.str() + ":\n" +
                      io::scene_to_json(prepared.scene, fs::absolute(mesh_path).lexically_normal().string()));
    }
    return prepared;
}

PreparedScene prepare_parsed_scene(io::SceneFile file, const std::string& name, const SceneFlags& flags,
                                   const Messages& messages) {
    for (const std::string& warning : file.warnings) messages.warning(warning);
    PreparedScene prepared;
    prepared.scene = scene_from_file(std::move(file), name, "", flags, messages, prepared.load_seconds);
    prepared.name = name;
    apply_flags(prepared, flags, messages);
    validate_prepared(prepared, name);
    return prepared;
}

}  // namespace phongrast::cli
