// The flags `render` and `sheet` share, and how they change a scene.
#ifndef PHONGRAST_APPS_COMMAND_LINE_HPP
#define PHONGRAST_APPS_COMMAND_LINE_HPP

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "phongrast/io/mesh_file.hpp"

namespace phongrast::cli {

struct SceneFlags {
    std::string input;   ///< scene .json or mesh .obj; empty: the default scene
    std::string output;  ///< image path; empty: a name in the current folder
    std::string mesh;
    std::string shader;
    std::string lighting;
    /// The named options (phongrast/option_names.hpp: mode, visibility,
    /// overdraw, precision, sample_pattern, back_faces, texture_filter) by key;
    /// absent or empty: the default.
    std::map<std::string, std::string> options;
    std::string size;  ///< "WxH"
    std::vector<double> eye, lookat, up, sensor;
    double focal = 0.0;
    /// The contract's other cameras (docs/scene-format.md, "Camera"):
    std::string camera_file;      ///< --camera: a camera JSON replacing the scene's camera
    std::string projection;       ///< --projection perspective|orthographic (look-at fields)
    std::vector<double> K;        ///< --K fx,fy,cx,cy[,skew]
    std::vector<double> world_to_camera;  ///< --world-to-camera: 12 or 16 numbers, row by row
    std::vector<double> camera_to_world;  ///< --camera-to-world: the same, inverted
    int threads = 0;
    int samples = 1;
    std::string smooth = "index";  ///< which corners share a normal: "index" (the contract) or "position"
    double crease = 180.0;         ///< degrees; sharper edges keep separate normals
    bool quiet = false;
    /// Reads a mesh file; empty: io::read_mesh. The batch command passes a
    /// reader that keeps parsed meshes (MeshFileCache), for jobs that share them.
    std::function<std::shared_ptr<const io::MeshFile>(const std::string& path)> read_mesh;
};

/// Adds the positional input, -o and every scene/override flag to `command`.
void add_scene_flags(CLI::App& command, SceneFlags& flags, const std::string& output_help);

/// "640x480" -> {640, 480} (width, height). Throws std::invalid_argument naming --size.
std::pair<int, int> parse_size(const std::string& text);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_COMMAND_LINE_HPP
