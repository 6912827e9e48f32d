// The pinhole look-at camera of docs/scene-format.md ("Camera"):
//
//   f = normalize(lookat - eye), r = normalize(cross(f, up)), u = cross(r, f)
//   camera coordinates of p:  x_c = r.(p-eye), y_c = u.(p-eye), z_c = f.(p-eye)
//   image plane:              x = focal x_c / z_c,  y = focal y_c / z_c
//   pixels:                   column = (x + W/2) / W * N,  row = (H/2 - y) / H * M
//
// Row 0 is the top of the image and column 0 its left; pixel (i, j) is sampled
// at (j + 0.5, i + 0.5).
#ifndef PHONGRAST_CAMERA_HPP
#define PHONGRAST_CAMERA_HPP

#include <glm/vec3.hpp>

namespace phongrast {

/// What a scene file says about the camera (all in world units).
struct Camera {
    glm::dvec3 eye{0.0, 0.0, 1.0};
    glm::dvec3 lookat{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double focal = 1.0;          ///< distance from the centre of projection to the image plane
    double sensor_height = 1.0;  ///< H: physical height of the image plane
    double sensor_width = 1.0;   ///< W: physical width of the image plane
};

/// A point in continuous pixel coordinates plus its camera depth z_c.
struct ProjectedPoint {
    double column = 0.0;
    double row = 0.0;
    double depth = 0.0;  ///< z_c: positive in front of the eye
};

/// The camera's orthonormal basis and the pixel mapping for an M x N image.
/// Built only through make_camera_frame, which validates the camera.
struct CameraFrame {
    glm::dvec3 eye{0.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    double focal = 1.0;
    double sensor_height = 1.0;
    double sensor_width = 1.0;
    int rows = 1;
    int columns = 1;

    /// (x_c, y_c, z_c) of a world point.
    glm::dvec3 camera_from_world(const glm::dvec3& point_world) const;
    /// (x_c, y_c, z_c) of a world direction (no translation).
    glm::dvec3 camera_from_world_direction(const glm::dvec3& direction_world) const;
    /// Continuous pixel coordinates of a camera-space point with z_c != 0.
    ProjectedPoint pixel_from_camera(const glm::dvec3& point_camera) const;
    /// Continuous pixel coordinates and depth of a world point. For z_c <= 0 the
    /// point is not in front of the eye: column and row are then meaningless
    /// (but finite), and callers must look at `depth`.
    ProjectedPoint project(const glm::dvec3& point_world) const;
};

/// Validates the camera and builds its frame for an image of `rows` x `columns`.
/// Throws std::invalid_argument naming the field for: eye equal to lookat,
/// up parallel to the view direction (or zero), focal or sensor not a positive
/// finite number, non-finite vectors, rows or columns below 1.
CameraFrame make_camera_frame(const Camera& camera, int rows, int columns);

}  // namespace phongrast

#endif  // PHONGRAST_CAMERA_HPP
