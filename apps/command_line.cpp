#include "command_line.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "phongrast/image.hpp"

#include "phongrast/option_names.hpp"

namespace phongrast::cli {

void add_scene_flags(CLI::App& command, SceneFlags& flags, const std::string& output_help) {
    command.add_option("input", flags.input,
                       "Scene file (.json, docs/scene-format.md) or a mesh (.obj, .ply, .stl, .gltf, .glb) to frame automatically. "
                       "Default: the project's default scene (assets/default.json)");
    command.add_option("-o,--output", flags.output, output_help);
    command.add_option("--mesh", flags.mesh, "Mesh (OBJ, PLY, STL, glTF/GLB) to render instead of the scene's \"mesh\"");
    command.add_option("--shader", flags.shader, "flat, gouraud or phong (overrides the scene)");
    command.add_option("--lighting", flags.lighting,
                       "ambient, diffuse, specular, full, or several joined with '+' (overrides the scene)");
    // The named options, from the library's one table (so that every spelling
    // Python accepts, such as depth_buffer, is accepted here too).
    for (const NamedOption& option : named_options()) {
        command
            .add_option(option_flag(option), flags.options[option.key],
                        option.help + " (default: " + option.default_name + ")")
            ->check(CLI::IsMember(accepted_names(option)));
    }
    command.add_option("--size", flags.size, "Image size WxH in pixels, e.g. 640x480 (overrides the scene)");
    command.add_option("--eye", flags.eye, "Camera position x,y,z")->expected(3)->delimiter(',');
    command.add_option("--lookat", flags.lookat, "Point the camera looks at x,y,z")->expected(3)->delimiter(',');
    command.add_option("--up", flags.up, "Camera up direction x,y,z")->expected(3)->delimiter(',');
    command.add_option("--focal", flags.focal, "Focal distance (world units)")->check(CLI::PositiveNumber);
    command.add_option("--sensor", flags.sensor, "Image plane size H,W (world units)")->expected(2)->delimiter(',');
    command.add_option("--camera", flags.camera_file,
                       "Camera JSON file replacing the scene's camera: a scene's \"camera\" object (look-at, OpenCV "
                       "or orthographic), or a file with a \"camera\" field (--camera-out writes one)");
    command.add_option("--projection", flags.projection,
                       "perspective (the look-at camera) or orthographic (eye, lookat, up, sensor; focal unused)")
        ->check(CLI::IsMember({"perspective", "orthographic"}));
    command.add_option("--K", flags.K,
                       "OpenCV intrinsics fx,fy,cx,cy[,skew] in pixels (OpenCV's pixel centres at whole numbers). "
                       "Without a pose flag the pose is the look-at camera's")
        ->expected(4, 5)
        ->delimiter(',');
    command.add_option("--world-to-camera", flags.world_to_camera,
                       "OpenCV pose [R | t], 12 or 16 numbers row by row (x right, y down, z forward). Without --K, "
                       "K is the look-at camera's")
        ->expected(12, 16)
        ->delimiter(',');
    command.add_option("--camera-to-world", flags.camera_to_world,
                       "The inverse pose, 12 or 16 numbers row by row (OpenCV axes)")
        ->expected(12, 16)
        ->delimiter(',');
    // A range with a small maximum: CLI::NonNegativeNumber's message would print the largest double in full.
    command.add_option("--threads", flags.threads,
                       "Worker threads; 0 = all cores, more than the machine has are clamped (the picture does not change)")
        ->check(CLI::Range(0, 65536))
        ->capture_default_str();
    command.add_option("--samples", flags.samples, "Samples per pixel axis (1 = pixel centres; 4 = 16 samples)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    command.add_option("--smooth", flags.smooth,
                       "Which corners share a vertex normal: index (the contract: corners using the same vertex "
                       "index) or position (corners at the same position, so seams of repeated vertices vanish)")
        ->check(CLI::IsMember({"index", "position"}))
        ->capture_default_str();
    command.add_option("--crease", flags.crease,
                       "Degrees: faces meeting at a sharper angle keep separate normals (30 keeps a cube a cube); "
                       "180 smooths across every edge")
        ->check(CLI::Range(0.0, 180.0))
        ->capture_default_str();
    command.add_flag("-q,--quiet", flags.quiet, "Print nothing but errors");
}

std::pair<int, int> parse_size(const std::string& text) {
    int width = 0;
    int height = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &rest) != 2 || width < 1 || height < 1 ||
        width > kMaxImageSide || height > kMaxImageSide) {
        throw std::invalid_argument("--size: expected WxH with whole numbers from 1 to " +
                                    std::to_string(kMaxImageSide) + ", e.g. 640x480; got '" + text + "'");
    }
    try {
        validate_image_size(height, width, "H", "W");  // the library's limit on the pixel count
    } catch (const std::length_error& error) {
        throw std::invalid_argument("--size " + text + ": " + error.what());
    }
    return {width, height};
}

}  // namespace phongrast::cli
