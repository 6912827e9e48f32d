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

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

io::MeshFile load_mesh(const std::string& path, const Messages& messages, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    io::MeshFile mesh = io::read_mesh(path);
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
    return path;
}

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

    int rows = 512;
    int columns = 512;
    if (!flags.size.empty()) std::tie(columns, rows) = parse_size(flags.size);

    Scene& scene = prepared.scene;
    bool auto_framed = false;
    if (input.empty()) {
        // Only a mesh: frame it and tell the user what was chosen.
        io::MeshFile obj = load_mesh(mesh_path, messages, prepared.load_seconds);
        const std::optional<PhongMaterial> mtl = obj.material;
        scene = io::frame_mesh(std::move(obj.mesh), rows, columns);
        if (mtl) scene.material = *mtl;
        prepared.name = fs::path(mesh_path).stem().string();
        auto_framed = true;
    } else {
        io::SceneFile file = io::read_scene_file(input);
        for (const std::string& warning : file.warnings) messages.warning(warning);
        if (!mesh_path.empty()) {
            file.mesh_path = mesh_path;
        } else if (file.mesh_path.empty()) {
            throw io::FileError(input + ": /mesh: missing required field; expected a mesh file name (.obj, .ply, .stl, .gltf, .glb; or give --mesh)");
        }
        std::error_code error;
        if (mesh_path.empty() && !fs::exists(file.mesh_path, error)) {
            // Name the scene field too: the path was resolved against the scene's folder.
            throw io::FileError(input + ": /mesh: " + file.mesh_path +
                                ": mesh not found (no such file; a relative \"mesh\" is relative to the scene file)");
        }
        io::MeshFile obj = load_mesh(file.mesh_path, messages, prepared.load_seconds);
        scene = std::move(file.scene);
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
            scene.image.rows = rows;
            scene.image.columns = columns;
        }
        mesh_path = file.mesh_path;
        prepared.name = fs::path(input).stem().string();
    }
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

    if (auto_framed && !messages.quiet()) {
        messages.note("no scene file: framed " + mesh_path +
                      " automatically. This scene file reproduces the picture:\n" +
                      io::scene_to_json(scene, fs::absolute(mesh_path).lexically_normal().string()));
    }
    return prepared;
}

}  // namespace phongrast::cli
