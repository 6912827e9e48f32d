#include "phongrast/camera.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "validation.hpp"

namespace phongrast {

glm::dvec3 CameraFrame::camera_from_world_direction(const glm::dvec3& direction_world) const {
    return {glm::dot(right, direction_world), glm::dot(up, direction_world),
            glm::dot(forward, direction_world)};
}

glm::dvec3 CameraFrame::camera_from_world(const glm::dvec3& point_world) const {
    return camera_from_world_direction(point_world - eye);
}

ProjectedPoint CameraFrame::pixel_from_camera(const glm::dvec3& point_camera) const {
    const double x = focal * point_camera.x / point_camera.z;
    const double y = focal * point_camera.y / point_camera.z;
    ProjectedPoint result;
    result.column = (x + sensor_width / 2.0) / sensor_width * columns;
    result.row = (sensor_height / 2.0 - y) / sensor_height * rows;
    result.depth = point_camera.z;
    return result;
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
    detail::validate_camera(camera);
    if (rows < 1) throw std::invalid_argument("image.rows: expected at least 1 row, got " + std::to_string(rows));
    if (columns < 1) throw std::invalid_argument("image.columns: expected at least 1 column, got " + std::to_string(columns));

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

    CameraFrame frame;
    frame.eye = camera.eye;
    frame.forward = forward;
    frame.right = side / side_length;
    frame.up = glm::cross(frame.right, forward);
    frame.focal = camera.focal;
    frame.sensor_height = camera.sensor_height;
    frame.sensor_width = camera.sensor_width;
    frame.rows = rows;
    frame.columns = columns;
    return frame;
}

}  // namespace phongrast
