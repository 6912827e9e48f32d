// The cameras of docs/scene-format.md ("Camera"), contract version 2.
//
// Look-at (perspective), the original camera:
//   f = normalize(lookat - eye), r = normalize(cross(f, up)), u = cross(r, f)
//   camera coordinates of p:  x_c = r.(p-eye), y_c = u.(p-eye), z_c = f.(p-eye)
//   image plane:              x = focal x_c / z_c,  y = focal y_c / z_c
//   pixels:                   column = (x + W/2) / W * N,  row = (H/2 - y) / H * M
//
// OpenCV: K = [[fx, s, cx], [0, fy, cy], [0, 0, 1]] in pixels and
// world_to_camera = [R | t] (x right, y down, z forward):
//   [X, Y, Z] = R p + t,  z_c = Z
//   column = (fx X + s Y) / Z + cx + 0.5,  row = fy Y / Z + cy + 0.5
// (OpenCV's pixel centres are whole numbers, this contract's are at +0.5.)
//
// Orthographic: the look-at basis without the division: x = x_c, y = y_c,
// then column and row as for the look-at camera; the viewer is at infinity
// (V = -f in the lighting).
//
// Row 0 is the top of the image and column 0 its left; pixel (i, j) is sampled
// at (j + 0.5, i + 0.5).
#ifndef PHONGRAST_CAMERA_HPP
#define PHONGRAST_CAMERA_HPP

#include <array>

#include <glm/vec3.hpp>

namespace phongrast {

/// Which of the contract's cameras a Camera is.
enum class CameraModel {
    look_at,       ///< perspective: eye, lookat, up, focal, sensor
    opencv,        ///< perspective: Camera::opencv (K and world_to_camera)
    orthographic,  ///< parallel: eye, lookat, up, sensor (focal unused)
};

/// A 3x4 matrix [R | t] as rows: world_to_camera[i][j] is row i, column j.
using Matrix3x4 = std::array<std::array<double, 4>, 3>;
/// A 4x4 matrix as rows (the last row of a rigid pose is [0, 0, 0, 1]).
using Matrix4x4 = std::array<std::array<double, 4>, 4>;
/// A 3x3 matrix as rows.
using Matrix3x3 = std::array<std::array<double, 3>, 3>;

/// Largest |entry of R R^T - I| and |det R - 1| accepted for a rotation
/// (the contract's "orthonormal, determinant +1, to 1e-6").
constexpr double kRotationTolerance = 1e-6;

/// An OpenCV camera: intrinsics in pixels of the scene's image, and the pose
/// as world_to_camera = [R | t] in OpenCV's axes (x right, y down, z forward).
struct OpenCvCamera {
    double fx = 1.0;    ///< focal length in pixels, along the columns
    double fy = 1.0;    ///< focal length in pixels, along the rows
    double cx = 0.0;    ///< principal point's column, OpenCV convention (pixel centres at whole numbers)
    double cy = 0.0;    ///< principal point's row, OpenCV convention
    double skew = 0.0;  ///< K[0][1]
    Matrix3x4 world_to_camera{{{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}};

    /// K as a 3x3 matrix: [[fx, skew, cx], [0, fy, cy], [0, 0, 1]].
    Matrix3x3 K() const;
    /// world_to_camera as a 4x4 matrix (last row [0, 0, 0, 1]).
    Matrix4x4 world_to_camera_4x4() const;
    /// The inverse pose, camera_to_world = [R^T | -R^T t] (4x4).
    Matrix4x4 camera_to_world() const;
    /// The centre of projection, -R^T t.
    glm::dvec3 eye() const;
};

/// What a scene file says about the camera (all in world units). The
/// look-at fields are the camera of `model == look_at` and `orthographic`;
/// `opencv` is the camera of `model == opencv`, and then they are unused.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, 1.0};
    glm::dvec3 lookat{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double focal = 1.0;          ///< distance from the centre of projection to the image plane
    double sensor_height = 1.0;  ///< H: physical height of the image plane
    double sensor_width = 1.0;   ///< W: physical width of the image plane
    CameraModel model = CameraModel::look_at;
    OpenCvCamera opencv;  ///< read only when model == CameraModel::opencv

    /// The look-at camera (what a default-constructed Camera with these fields set is).
    static Camera look_at(const glm::dvec3& eye, const glm::dvec3& lookat, const glm::dvec3& up, double focal,
                          double sensor_height, double sensor_width);
    /// The orthographic camera: sensor_height x sensor_width world units of the
    /// plane through `eye` perpendicular to lookat - eye fill the image.
    static Camera orthographic(const glm::dvec3& eye, const glm::dvec3& lookat, const glm::dvec3& up,
                               double sensor_height, double sensor_width);
    /// An OpenCV camera from K (3x3, rows; K[1][0], K[2][0], K[2][1] must be 0
    /// and K[2][2] 1) and world_to_camera [R | t]. Validated: throws
    /// std::invalid_argument naming the member (camera.opencv.fx, ...).
    static Camera from_opencv(const Matrix3x3& K, const Matrix3x4& world_to_camera);
    /// The same from camera_to_world (its inverse; R must be a rotation).
    static Camera from_opencv_camera_to_world(const Matrix3x3& K, const Matrix3x4& camera_to_world);
};

/// The OpenCV form of a look-at camera for an image of `rows` x `columns`
/// (docs/scene-format.md: R's rows are r, -u, f; t = -R eye; fx = focal N / W,
/// fy = focal M / H, (cx, cy) = (N/2 - 0.5, M/2 - 0.5), skew 0); an OpenCV
/// camera is returned as it is. Throws std::invalid_argument for an
/// orthographic camera (it has no K) and for what make_camera_frame refuses.
OpenCvCamera opencv_form(const Camera& camera, int rows, int columns);

/// world_to_camera from camera_to_world = [Rc | c]: [Rc^T | -Rc^T c]. Throws
/// std::invalid_argument naming `field` when Rc is not a rotation or a
/// number is not finite.
Matrix3x4 invert_pose(const Matrix3x4& camera_to_world, const char* field);

/// Checks that the 3x3 part of `pose` is a rotation within
/// kRotationTolerance and that every entry is finite; throws
/// std::invalid_argument starting with `field` otherwise.
void validate_pose(const Matrix3x4& pose, const char* field);

/// A point in continuous pixel coordinates plus its camera depth z_c.
struct ProjectedPoint {
    double column = 0.0;
    double row = 0.0;
    double depth = 0.0;  ///< z_c: positive in front of the eye
};

/// The camera's orthonormal basis and the pixel mapping for an M x N image.
/// Built only through make_camera_frame, which validates the camera.
///
/// Camera space is the look-at camera's for every model: x right, y up on the
/// image, z forward (an OpenCV camera's y is negated), with the eye at the
/// origin.
struct CameraFrame {
    glm::dvec3 eye{0.0};  ///< centre of projection (orthographic: the point on the axis the sensor is centred at)
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    double focal = 1.0;
    double sensor_height = 1.0;
    double sensor_width = 1.0;
    int rows = 1;
    int columns = 1;
    CameraModel model = CameraModel::look_at;
    /// OpenCV: K, the translation of world_to_camera in camera space
    /// (t_x, -t_y, t_z), and the frame's samples per image pixel.
    OpenCvCamera opencv;
    glm::dvec3 translation{0.0};
    double samples_per_pixel = 1.0;

    /// (x_c, y_c, z_c) of a world point.
    glm::dvec3 camera_from_world(const glm::dvec3& point_world) const;
    /// (x_c, y_c, z_c) of a world direction (no translation).
    glm::dvec3 camera_from_world_direction(const glm::dvec3& direction_world) const;
    /// Continuous pixel coordinates of a camera-space point (perspective
    /// models: z_c != 0).
    ProjectedPoint pixel_from_camera(const glm::dvec3& point_camera) const;
    /// The inverse of pixel_from_camera for a point of depth 1: the camera-space
    /// direction (x_c / z_c, y_c / z_c, 1) of the ray through the continuous
    /// pixel coordinates (column, row) of this frame (for an OpenCV camera in
    /// samples: divided by samples_per_pixel first, skew included). A point of
    /// depth z_c seen there is z_c times it, at distance z_c |camera_ray| from
    /// the eye. Orthographic: (0, 0, 1) everywhere (parallel rays).
    glm::dvec3 camera_ray(double column, double row) const;
    /// Continuous pixel coordinates and depth of a world point. For z_c <= 0 the
    /// point is not in front of the eye: column and row are then meaningless
    /// (but finite), and callers must look at `depth`.
    ProjectedPoint project(const glm::dvec3& point_world) const;
    /// Whether perspective divides by z_c (look-at and OpenCV), not orthographic.
    bool perspective() const { return model != CameraModel::orthographic; }
};

/// Validates the camera and builds its frame for an image of `rows` x `columns`.
/// Throws std::invalid_argument naming the field for: eye equal to lookat,
/// up parallel to the view direction (or zero), focal or sensor not a positive
/// finite number, non-finite vectors, rows or columns below 1; for an OpenCV
/// camera: fx or fy not positive finite, cx, cy, skew not finite, a pose that
/// is not a rotation and translation.
CameraFrame make_camera_frame(const Camera& camera, int rows, int columns);

/// The same for a render pass of `samples_per_pixel` samples per image pixel
/// along each axis (rows and columns in samples): an OpenCV camera's K is in
/// image pixels, so its pixel coordinates are scaled by it.
CameraFrame make_camera_frame(const Camera& camera, int rows, int columns, int samples_per_pixel);

}  // namespace phongrast

#endif  // PHONGRAST_CAMERA_HPP
