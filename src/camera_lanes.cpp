#include "camera_lanes.hpp"

namespace phongrast::detail {
namespace {

// glm::dot of two dvec3 is (a.x b.x + a.y b.y) + a.z b.z: written out in that
// order so that the loops below stay plain arithmetic the compiler vectorises.
inline double dot(const glm::dvec3& a, double x, double y, double z) { return a.x * x + a.y * y + a.z * z; }

}  // namespace

void camera_from_world_lanes(const CameraFrame& frame, const glm::dvec3* points, std::size_t n,
                             const CameraLanes& out) {
    const glm::dvec3 right = frame.right, up = frame.up, forward = frame.forward;
    if (frame.model == CameraModel::opencv) {
        // R p + t (CameraFrame::camera_from_world).
        const glm::dvec3 t = frame.translation;
        for (std::size_t k = 0; k < n; ++k) {
            const double x = points[k].x, y = points[k].y, z = points[k].z;
            out.x[k] = dot(right, x, y, z) + t.x;
            out.y[k] = dot(up, x, y, z) + t.y;
            out.z[k] = dot(forward, x, y, z) + t.z;
        }
        return;
    }
    const glm::dvec3 eye = frame.eye;
    for (std::size_t k = 0; k < n; ++k) {
        const double x = points[k].x - eye.x, y = points[k].y - eye.y, z = points[k].z - eye.z;
        out.x[k] = dot(right, x, y, z);
        out.y[k] = dot(up, x, y, z);
        out.z[k] = dot(forward, x, y, z);
    }
}

void camera_from_world_direction_lanes(const CameraFrame& frame, const glm::vec3* directions, std::size_t n,
                                       const CameraLanes& out) {
    const glm::dvec3 right = frame.right, up = frame.up, forward = frame.forward;
    for (std::size_t k = 0; k < n; ++k) {
        const double x = directions[k].x, y = directions[k].y, z = directions[k].z;
        out.x[k] = dot(right, x, y, z);
        out.y[k] = dot(up, x, y, z);
        out.z[k] = dot(forward, x, y, z);
    }
}

void sample_from_camera_lanes(const CameraFrame& frame, glm::dvec2 offset, std::size_t n, const double* x,
                              const double* y, const double* z, double* column, double* row) {
    if (frame.model == CameraModel::opencv) {
        const OpenCvCamera& k = frame.opencv;
        const double spp = frame.samples_per_pixel;
        for (std::size_t i = 0; i < n; ++i) {
            const double X = x[i], Y = -y[i], Z = z[i];
            column[i] = ((k.fx * X + k.skew * Y) / Z + k.cx + 0.5) * spp - offset.x;
            row[i] = (k.fy * Y / Z + k.cy + 0.5) * spp - offset.y;
        }
        return;
    }
    const double width = frame.sensor_width, height = frame.sensor_height;
    const double columns = frame.columns, rows = frame.rows;
    if (frame.model == CameraModel::look_at) {
        const double focal = frame.focal;
        for (std::size_t i = 0; i < n; ++i) {
            const double px = focal * x[i] / z[i], py = focal * y[i] / z[i];
            column[i] = (px + width / 2.0) / width * columns - offset.x;
            row[i] = (height / 2.0 - py) / height * rows - offset.y;
        }
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        column[i] = (x[i] + width / 2.0) / width * columns - offset.x;
        row[i] = (height / 2.0 - y[i]) / height * rows - offset.y;
    }
}

}  // namespace phongrast::detail
