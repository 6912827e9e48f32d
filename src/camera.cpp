#include "phongrast/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "validation.hpp"

namespace phongrast {
namespace {

/// Shortest round-trip text of a number, for error messages.
std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

glm::dvec3 row_of(const Matrix3x4& m, int i) { return {m[i][0], m[i][1], m[i][2]}; }

}  // namespace

Matrix3x3 OpenCvCamera::K() const { return {{{fx, skew, cx}, {0.0, fy, cy}, {0.0, 0.0, 1.0}}}; }

Matrix4x4 OpenCvCamera::world_to_camera_4x4() const {
    const Matrix3x4& m = world_to_camera;
    return {{m[0], m[1], m[2], {0.0, 0.0, 0.0, 1.0}}};
}

glm::dvec3 OpenCvCamera::eye() const {
    const Matrix3x4& m = world_to_camera;
    // -R^T t
    return -(row_of(m, 0) * m[0][3] + row_of(m, 1) * m[1][3] + row_of(m, 2) * m[2][3]);
}

Matrix4x4 OpenCvCamera::camera_to_world() const {
    const Matrix3x4& m = world_to_camera;
    const glm::dvec3 c = eye();
    return {{{m[0][0], m[1][0], m[2][0], c.x},
             {m[0][1], m[1][1], m[2][1], c.y},
             {m[0][2], m[1][2], m[2][2], c.z},
             {0.0, 0.0, 0.0, 1.0}}};
}

void validate_pose(const Matrix3x4& pose, const char* field) {
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            if (!std::isfinite(pose[i][j])) {
                throw std::invalid_argument(std::string(field) + "[" + std::to_string(i) + "][" + std::to_string(j) +
                                            "]: expected a finite number, got " + number_text(pose[i][j]));
            }
        }
    }
    double worst = 0.0;  // largest |R R^T - I|
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double dot = glm::dot(row_of(pose, i), row_of(pose, j));
            worst = std::max(worst, std::abs(dot - (i == j ? 1.0 : 0.0)));
        }
    }
    const double det = glm::dot(row_of(pose, 0), glm::cross(row_of(pose, 1), row_of(pose, 2)));
    if (!(worst <= kRotationTolerance)) {
        throw std::invalid_argument(std::string(field) + ": the 3x3 part is not a rotation (R R^T differs from I by " +
                                    number_text(worst) + ", more than " + number_text(kRotationTolerance) +
                                    "); expected orthonormal rows");
    }
    if (!(std::abs(det - 1.0) <= kRotationTolerance)) {
        throw std::invalid_argument(std::string(field) + ": the 3x3 part has determinant " + number_text(det) +
                                    ", expected +1 (a rotation, not a mirror)");
    }
}

Matrix3x4 invert_pose(const Matrix3x4& camera_to_world, const char* field) {
    validate_pose(camera_to_world, field);
    const Matrix3x4& c = camera_to_world;
    const glm::dvec3 centre{c[0][3], c[1][3], c[2][3]};
    Matrix3x4 out{};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 row{c[0][i], c[1][i], c[2][i]};  // row i of R = column i of Rc
        out[i] = {row.x, row.y, row.z, -glm::dot(row, centre)};
    }
    return out;
}

Camera Camera::look_at(const glm::dvec3& eye, const glm::dvec3& lookat, const glm::dvec3& up, double focal,
                       double sensor_height, double sensor_width) {
    Camera camera;
    camera.eye = eye;
    camera.lookat = lookat;
    camera.up = up;
    camera.focal = focal;
    camera.sensor_height = sensor_height;
    camera.sensor_width = sensor_width;
    return camera;
}

Camera Camera::orthographic(const glm::dvec3& eye, const glm::dvec3& lookat, const glm::dvec3& up,
                            double sensor_height, double sensor_width) {
    Camera camera = look_at(eye, lookat, up, 1.0, sensor_height, sensor_width);
    camera.model = CameraModel::orthographic;
    return camera;
}

Camera Camera::from_opencv(const Matrix3x3& K, const Matrix3x4& world_to_camera) {
    if (!(K[1][0] == 0.0 && K[2][0] == 0.0 && K[2][1] == 0.0 && K[2][2] == 1.0)) {
        throw std::invalid_argument("camera.K: expected [[fx, s, cx], [0, fy, cy], [0, 0, 1]], got last rows [" +
                                    number_text(K[1][0]) + ", " + number_text(K[1][1]) + ", " + number_text(K[1][2]) +
                                    "], [" + number_text(K[2][0]) + ", " + number_text(K[2][1]) + ", " +
                                    number_text(K[2][2]) + "]");
    }
    Camera camera;
    camera.model = CameraModel::opencv;
    camera.opencv.fx = K[0][0];
    camera.opencv.skew = K[0][1];
    camera.opencv.cx = K[0][2];
    camera.opencv.fy = K[1][1];
    camera.opencv.cy = K[1][2];
    camera.opencv.world_to_camera = world_to_camera;
    detail::validate_camera(camera);
    return camera;
}

Camera Camera::from_opencv_camera_to_world(const Matrix3x3& K, const Matrix3x4& camera_to_world) {
    return from_opencv(K, invert_pose(camera_to_world, "camera.camera_to_world"));
}

OpenCvCamera opencv_form(const Camera& camera, int rows, int columns) {
    if (camera.model == CameraModel::opencv) {
        detail::validate_camera(camera);
        return camera.opencv;
    }
    if (camera.model == CameraModel::orthographic) {
        throw std::invalid_argument("camera: an orthographic camera has no OpenCV form (K is a perspective projection)");
    }
    const CameraFrame frame = make_camera_frame(camera, rows, columns);
    OpenCvCamera out;
    out.fx = camera.focal * columns / camera.sensor_width;
    out.fy = camera.focal * rows / camera.sensor_height;
    out.cx = columns / 2.0 - 0.5;
    out.cy = rows / 2.0 - 0.5;
    const glm::dvec3 rows_of_R[3] = {frame.right, -frame.up, frame.forward};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3& r = rows_of_R[i];
        out.world_to_camera[i] = {r.x, r.y, r.z, -glm::dot(r, camera.eye)};
    }
    return out;
}

glm::dvec3 CameraFrame::camera_from_world_direction(const glm::dvec3& direction_world) const {
    return {glm::dot(right, direction_world), glm::dot(up, direction_world),
            glm::dot(forward, direction_world)};
}

glm::dvec3 CameraFrame::camera_from_world(const glm::dvec3& point_world) const {
    // OpenCV: R p + t as the contract writes it (up = -R's second row, so y is -(R p + t)_y).
    if (model == CameraModel::opencv) return camera_from_world_direction(point_world) + translation;
    return camera_from_world_direction(point_world - eye);
}

ProjectedPoint CameraFrame::pixel_from_camera(const glm::dvec3& point_camera) const {
    ProjectedPoint result;
    result.depth = point_camera.z;
    if (model == CameraModel::opencv) {
        const double X = point_camera.x, Y = -point_camera.y, Z = point_camera.z;
        result.column = ((opencv.fx * X + opencv.skew * Y) / Z + opencv.cx + 0.5) * samples_per_pixel;
        result.row = (opencv.fy * Y / Z + opencv.cy + 0.5) * samples_per_pixel;
        return result;
    }
    double x = point_camera.x, y = point_camera.y;
    if (model == CameraModel::look_at) {
        x = focal * point_camera.x / point_camera.z;
        y = focal * point_camera.y / point_camera.z;
    }
    result.column = (x + sensor_width / 2.0) / sensor_width * columns;
    result.row = (sensor_height / 2.0 - y) / sensor_height * rows;
    return result;
}

glm::dvec3 CameraFrame::camera_ray(double column, double row) const {
    if (model == CameraModel::opencv) {
        // column = (fx X + s Y) / Z + cx + 0.5 and row = fy Y / Z + cy + 0.5, in image pixels, solved for
        // X / Z and Y / Z; camera space's y is OpenCV's -Y.
        const double Y = (row / samples_per_pixel - opencv.cy - 0.5) / opencv.fy;
        const double X = (column / samples_per_pixel - opencv.cx - 0.5 - opencv.skew * Y) / opencv.fx;
        return {X, -Y, 1.0};
    }
    if (model == CameraModel::orthographic) return {0.0, 0.0, 1.0};
    // column = (x + W/2) / W N and row = (H/2 - y) / H M, with x = focal x_c / z_c and y = focal y_c / z_c.
    const double x = column / columns * sensor_width - sensor_width / 2.0;
    const double y = sensor_height / 2.0 - row / rows * sensor_height;
    return {x / focal, y / focal, 1.0};
}

ProjectedPoint CameraFrame::project(const glm::dvec3& point_world) const {
    const glm::dvec3 point_camera = camera_from_world(point_world);
    if (!(point_camera.z > 0.0)) {
        ProjectedPoint behind;
        behind.depth = point_camera.z;
        return behind;
    }
    return pixel_from_camera(point_camera);
}

CameraFrame make_camera_frame(const Camera& camera, int rows, int columns) {
    return make_camera_frame(camera, rows, columns, 1);
}

CameraFrame make_camera_frame(const Camera& camera, int rows, int columns, int samples_per_pixel) {
    detail::validate_camera(camera);
    if (rows < 1) throw std::invalid_argument("image.rows: expected at least 1 row, got " + std::to_string(rows));
    if (columns < 1) throw std::invalid_argument("image.columns: expected at least 1 column, got " + std::to_string(columns));
    if (samples_per_pixel < 1) {
        throw std::invalid_argument("samples_per_pixel: expected at least 1, got " + std::to_string(samples_per_pixel));
    }

    CameraFrame frame;
    frame.model = camera.model;
    frame.rows = rows;
    frame.columns = columns;
    frame.samples_per_pixel = samples_per_pixel;
    if (camera.model == CameraModel::opencv) {
        const Matrix3x4& m = camera.opencv.world_to_camera;
        frame.opencv = camera.opencv;
        frame.eye = camera.opencv.eye();
        frame.right = row_of(m, 0);
        frame.up = -row_of(m, 1);
        frame.forward = row_of(m, 2);
        frame.translation = {m[0][3], -m[1][3], m[2][3]};
        // The equivalent look-at camera's focal and sensor (docs/scene-format.md), for callers that read them.
        frame.focal = camera.opencv.fy;
        frame.sensor_height = rows / static_cast<double>(samples_per_pixel);
        frame.sensor_width = columns / static_cast<double>(samples_per_pixel) * camera.opencv.fy / camera.opencv.fx;
        return frame;
    }

    const glm::dvec3 view = camera.lookat - camera.eye;
    const double view_length = glm::length(view);
    if (!(view_length > 0.0) || !std::isfinite(view_length)) {
        throw std::invalid_argument("camera.lookat: must differ from camera.eye");
    }
    const glm::dvec3 forward = view / view_length;
    const double up_length = glm::length(camera.up);
    if (!(up_length > 0.0)) throw std::invalid_argument("camera.up: must not be the zero vector");
    const glm::dvec3 side = glm::cross(forward, camera.up / up_length);
    // |side| = sin(angle between up and the view direction); below ~1e-9 the
    // basis would be dominated by rounding, so treat it as parallel.
    const double side_length = glm::length(side);
    if (!(side_length > 1e-9)) {
        throw std::invalid_argument("camera.up: must not be parallel to the view direction (lookat - eye)");
    }

    frame.eye = camera.eye;
    frame.forward = forward;
    frame.right = side / side_length;
    frame.up = glm::cross(frame.right, forward);
    frame.focal = camera.focal;
    frame.sensor_height = camera.sensor_height;
    frame.sensor_width = camera.sensor_width;
    return frame;
}

}  // namespace phongrast
