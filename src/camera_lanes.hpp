#ifndef PHONGRAST_SRC_CAMERA_LANES_HPP
#define PHONGRAST_SRC_CAMERA_LANES_HPP

// CameraFrame's transforms of many points at once, for the vertex stage.
// Each lane computes exactly what the one-point member function computes,
// operation for operation in the same order (same bits: test_camera_lanes),
// but the camera's model is chosen once per call and the lanes are
// independent, so the compiler vectorises them and the divisions of
// different points overlap. One point per call waited on its divisions
// (docs/performance.md, "Vertices, lighting and normals per frame").

#include <phongrast/camera.hpp>

#include <glm/vec2.hpp>

#include <cstddef>

namespace phongrast::detail {

/// Camera-space points (struct of arrays).
struct CameraLanes {
    double* x;
    double* y;
    double* z;
};

/// CameraFrame::camera_from_world() of points[0 .. n-1].
void camera_from_world_lanes(const CameraFrame& frame, const glm::dvec3* points, std::size_t n,
                             const CameraLanes& out);

/// CameraFrame::camera_from_world_direction() of directions[0 .. n-1] (float,
/// converted to double first, as a caller of the member function would).
void camera_from_world_direction_lanes(const CameraFrame& frame, const glm::vec3* directions, std::size_t n,
                                       const CameraLanes& out);

/// CameraFrame::pixel_from_camera()'s column and row of points 0 .. n-1
/// minus `offset` (View::sample_from_camera()). A lane whose z is not
/// positive gets meaningless values (the member function's inputs must have z != 0).
void sample_from_camera_lanes(const CameraFrame& frame, glm::dvec2 offset, std::size_t n, const double* x,
                              const double* y, const double* z, double* column, double* row);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_CAMERA_LANES_HPP
