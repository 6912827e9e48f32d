// Every check of a scene and of the render options, in one place (internal
// header). Each failure throws std::invalid_argument naming the field and
// what was expected; nothing past validation meets a non-finite input.
#ifndef PHONGRAST_SRC_VALIDATION_HPP
#define PHONGRAST_SRC_VALIDATION_HPP

#include <functional>

#include <glm/vec3.hpp>

#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// The largest magnitude a lit colour channel may reach: the selected terms of
/// the lighting formula, with every dot product at its largest (1), must stay
/// within it for every vertex colour (white without colours), or the scene is
/// refused. It is far beyond any radiance a scene means, and far enough below
/// float's largest value (3.4e38) that interpolation between corners and the
/// sum of up to 256 supersamples stay finite: past float's range a pixel
/// would be infinite, or NaN where two such terms of opposite sign meet.
inline constexpr double kMaxLitValue = 1e30;

/// The scene's values (material, ambient, background, lights, camera, mesh;
/// lit values within kMaxLitValue) and the options (samples per axis, threads,
/// image size in samples).
void validate_render_request(const Scene& scene, const RenderOptions& options);

/// phongrast::validate_mesh, with each vertex colour's channels also at most
/// `colour_limit` in magnitude; `lit_value` says, for the message, how far
/// the offending colour could be lit.
void validate_mesh(const Mesh& mesh, const glm::dvec3& colour_limit,
                   const std::function<double(const glm::vec3&)>& lit_value);

/// The camera's own fields: finite eye, lookat and up; positive finite focal
/// length and sensor. (make_camera_frame() adds the checks that need the
/// basis: lookat != eye, up not parallel to the view.)
void validate_camera(const Camera& camera);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VALIDATION_HPP
