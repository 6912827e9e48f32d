// The camera of a rendered image, written out for the tools that consume
// datasets (`phongrast render --camera-out`): K, world_to_camera in OpenCV
// axes, camera_to_world in the OpenGL/Blender axes NeRF-style tools use, the
// look-at form when there is one, and the near plane
// (docs/scene-format.md, "Camera" and "Clipping").
#ifndef PHONGRAST_IO_CAMERA_RECORD_HPP
#define PHONGRAST_IO_CAMERA_RECORD_HPP

#include <string>
#include <vector>

#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"

namespace phongrast::io {

/// One image and the camera that made it.
struct CameraRecord {
    std::string file_path;  ///< the image, relative to the camera file's folder when it can be
    Camera camera;
    int rows = 0;
    int columns = 0;
    double near_depth = 0.0;  ///< z_c of the near plane (0 for orthographic: the eye's plane, excluded)
};

/// The record of `scene`'s camera for the image at `image_path`, whose path
/// in the file is made relative to `camera_file`'s folder. The near plane is
/// the contract's: 1e-4 focal (look-at), 1e-4 of the largest vertex z_c
/// (OpenCV; every object's vertices, placed by its transform), 0 (orthographic).
CameraRecord camera_record(const Scene& scene, const std::string& image_path, const std::string& camera_file);

/// The camera file's JSON: {"camera": the first record's camera as a scene's
/// "camera" object (so `--camera FILE` reads it back), "images": [one object
/// per record: file_path, width, height, projection, K (3x3, null for
/// orthographic), world_to_camera (4x4, OpenCV axes: x right, y down, z
/// forward), camera_to_world_opengl (4x4: x right, y up, z backward),
/// look_at ({eye, lookat, up, focal, sensor}; null for an OpenCV camera),
/// near]}.
std::string camera_records_json(const std::vector<CameraRecord>& records);

/// The same records as a `transforms.json` in the layout instant-ngp and
/// nerfstudio read: "camera_model": "OPENCV", fl_x, fl_y, cx, cy (pixel
/// centres at +0.5, as this contract and those tools have them: OpenCV's
/// cx + 0.5), w, h, camera_angle_x and camera_angle_y of the first record,
/// then "frames": [{file_path (as in the record: relative to the
/// transforms file), transform_matrix (camera_to_world, OpenGL axes)}]; a
/// frame whose intrinsics differ from the first's carries its own fl_x, fl_y,
/// cx, cy, w, h. Throws std::invalid_argument for an empty list, an
/// orthographic camera (no K) or a skewed K (the layout has no skew).
std::string transforms_json(const std::vector<CameraRecord>& records);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_CAMERA_RECORD_HPP
