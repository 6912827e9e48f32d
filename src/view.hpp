// The view of one render pass (internal header): camera frame, size in
// samples, sample offset and near plane, shared by the vertex stage,
// clipping and set-up.
#ifndef PHONGRAST_SRC_VIEW_HPP
#define PHONGRAST_SRC_VIEW_HPP

#include <glm/vec2.hpp>

#include "phongrast/camera.hpp"

namespace phongrast::detail {

/// Distance of the near clip plane in front of the eye, relative to the focal
/// length so that scaling a whole scene (camera included) scales it too. What
/// it removes is visible only within 1e-4 of the sensor's half-size around
/// the image centre.
constexpr double kNearPlaneOverFocal = 1e-4;

/// What one render pass sees: the camera frame at the pass's size in samples
/// (frame.rows x frame.columns), where in each pixel the pass samples, and
/// the near plane.
struct View {
    CameraFrame frame;
    /// Offset of this pass's sample from the pixel centre, in pixels: sample
    /// coordinates are pixel coordinates minus it (rotated grid; 0 otherwise).
    glm::dvec2 sample_offset{0.0};
    double near_depth = 0.0;  ///< z_c of the near clip plane

    View(const Camera& camera, int rows, int columns, glm::dvec2 offset);
    /// Sample coordinates (column, row) of a camera-space point in front of the eye.
    glm::dvec2 sample_from_camera(const glm::dvec3& point_camera) const;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VIEW_HPP
