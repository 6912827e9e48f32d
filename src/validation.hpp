// Every check of a scene and of the render options, in one place (internal
// header). Each failure throws std::invalid_argument naming the field and
// what was expected; nothing past validation meets a non-finite input.
#ifndef PHONGRAST_SRC_VALIDATION_HPP
#define PHONGRAST_SRC_VALIDATION_HPP

#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// The scene's values (material, ambient, background, lights, camera, mesh)
/// and the options (samples per axis, threads, image size in samples).
void validate_render_request(const Scene& scene, const RenderOptions& options);

/// The camera's own fields: finite eye, lookat and up; positive finite focal
/// length and sensor. (make_camera_frame() adds the checks that need the
/// basis: lookat != eye, up not parallel to the view.)
void validate_camera(const Camera& camera);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VALIDATION_HPP
