// Extra outputs of a render next to the colour image ("arbitrary output
// variables"): camera depth, distance from the eye, shading normal, triangle
// id, coverage and texture coordinates, each computed only when asked for.
#ifndef PHONGRAST_AOV_HPP
#define PHONGRAST_AOV_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phongrast {

/// Which extra planes a render fills (RenderOptions::aovs). None by default:
/// a render that asks for none does no work for them.
struct AovRequest {
    bool depth = false;   ///< camera depth z_c of the surface that paints the sample
    bool normal = false;  ///< unit world-space shading normal there
    bool id = false;      ///< index of the mesh triangle that paints the sample
    bool alpha = false;   ///< covered fraction of the pixel's samples
    bool uv = false;      ///< texture coordinates (s, t) of the surface that paints the sample
    bool distance = false;  ///< distance from the eye to the surface that paints the sample

    bool any() const { return depth || normal || id || alpha || uv || distance; }
    static AovRequest all() { return {true, true, true, true, true, true}; }
};

/// "depth,normal,id,alpha,uv,distance" (any subset, comma-separated, or "all"); throws
/// std::invalid_argument naming an unknown entry and listing the valid ones.
AovRequest parse_aovs(std::string_view text);
std::string to_string(const AovRequest& request);

/// The requested planes, row-major like Image::pixels (row 0 at the top);
/// a plane that was not requested is empty.
///
/// Which sample a pixel reports: without supersampling, its centre. With
/// samples_per_axis > 1, depth, distance, normal, id and uv come from the pixel's nearest
/// covered sample (smallest depth; the first in sample order on a tie), so
/// they always describe one real surface point, and alpha counts all samples.
struct AovPlanes {
    int rows = 0;
    int columns = 0;
    /// Camera depth z_c in world units, perspective-correct in every mode
    /// (it is the surface's depth, not an interpolated attribute). In
    /// painter's order the surface is the last one painted there; with the
    /// depth buffer, the nearest. +infinity on the background.
    std::vector<float> depth;
    /// Unit world-space normal used for shading: interpolated with the
    /// shading's weights and renormalised (Gouraud and Phong), or the
    /// triangle's one normal for flat shading (its mean vertex normal,
    /// normalised: what flat shading lights with). Zero on the background,
    /// and where a surface has no normal (see calculate_normals).
    std::vector<glm::vec3> normal;
    /// Index into Mesh::triangles; -1 on the background.
    std::vector<std::int32_t> id;
    /// Covered fraction of the pixel's samples, from 0 to 1 (exact multiples of 1 / samples).
    std::vector<float> alpha;
    /// Texture coordinates (s, t) (t = 0 at a texture's bottom row) of the
    /// surface the depth and id come from, interpolated as the shading
    /// interpolates them (perspective-correct in exact mode). Zero on the
    /// background, on faces without texture coordinates, and with the Gouraud
    /// shader in a scene that draws no texture (its vertices carry no (s, t) then).
    std::vector<glm::vec2> uv;
    /// Euclidean distance in world units from the eye to the surface point
    /// the depth comes from (the same sample): z_c times the length of the
    /// camera-space ray (x_c / z_c, y_c / z_c, 1) through the sample
    /// (CameraFrame::camera_ray), so distance / depth depends on the sample's
    /// position alone. For the orthographic camera, whose eye is at infinity,
    /// it is the distance from the image plane through Camera::eye, which is
    /// z_c (the ray is (0, 0, 1)). +infinity on the background, as depth.
    std::vector<float> distance;
};

}  // namespace phongrast

#endif  // PHONGRAST_AOV_HPP
