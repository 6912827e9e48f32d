// The view of one render pass (internal header): camera frame, size in
// samples, sample offset and near plane, shared by the vertex stage,
// clipping and set-up.
#ifndef PHONGRAST_SRC_VIEW_HPP
#define PHONGRAST_SRC_VIEW_HPP

#include <glm/vec2.hpp>

#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Distance of the near clip plane in front of the eye, relative to the focal
/// length so that scaling a whole scene (camera included) scales it too. What
/// it removes is visible only within 1e-4 of the sensor's half-size around
/// the image centre.
constexpr double kNearPlaneOverFocal = 1e-4;
/// An OpenCV camera's near plane relative to the largest z_c of the scene's
/// vertices (docs/scene-format.md, "Clipping").
constexpr double kNearPlaneOverFarthestVertex = 1e-4;

/// Whether attributes are interpolated perspective-correct (weights over
/// z_c): when the options ask for it and the camera divides by z_c. An
/// orthographic camera's attributes are affine in screen space, so its
/// screen-space weights are already exact.
inline bool perspective_weights(const Scene& scene, const RenderOptions& options) {
    return options.interpolation == Interpolation::perspective_correct &&
           scene.camera.model != CameraModel::orthographic;
}

/// What one render pass sees: the camera frame at the pass's size in samples
/// (frame.rows x frame.columns), where in each pixel the pass samples, and
/// the near plane.
struct View {
    CameraFrame frame;
    /// Offset of this pass's sample from the pixel centre, in pixels: sample
    /// coordinates are pixel coordinates minus it (rotated grid; 0 otherwise).
    glm::dvec2 sample_offset{0.0};
    /// z_c of the near clip plane: a vertex with depth below it is behind.
    /// Look-at: 1e-4 focal. Orthographic: the eye's plane, itself excluded
    /// (the smallest positive double). OpenCV: set by place_near_plane() once
    /// the vertices' depths are known.
    double near_depth = 0.0;

    /// `samples_per_pixel`: rows and columns are the image's times it (an
    /// OpenCV camera's K is in image pixels).
    View(const Camera& camera, int rows, int columns, glm::dvec2 offset, int samples_per_pixel = 1);
    /// Sample coordinates (column, row) of a camera-space point in front of the eye.
    glm::dvec2 sample_from_camera(const glm::dvec3& point_camera) const;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VIEW_HPP
