// render(): the seed's render_object. Computes normals, projects, sorts the
// triangles farthest first by mean camera depth (stable), and fills each with
// the chosen shader, following ../shared/scene-format.md.
#ifndef PHONGRAST_RENDER_HPP
#define PHONGRAST_RENDER_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "phongrast/camera.hpp"
#include "phongrast/image.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast {

enum class Shader {
    flat,     ///< one colour per triangle: lighting at the centroid with the mean vertex normal and colour
    gouraud,  ///< lighting at the three vertices, colours interpolated
    phong,    ///< normals and colours interpolated, normal renormalised, lighting per pixel
};
/// "flat", "gouraud" or "phong"; throws std::invalid_argument listing them otherwise.
Shader parse_shader(std::string_view text);
const char* to_string(Shader shader);

/// Where L (to each light) and V (to the eye) are computed.
enum class LightVectors {
    triangle_centroid,  ///< seed: once per triangle at its centroid, held constant over it
    shaded_point,       ///< exact: at each vertex (Gouraud) or each pixel (Phong)
};
/// How vertex attributes (colour, normal, lit colour, position) vary across a triangle.
enum class Interpolation {
    screen_affine,        ///< seed: linear in screen space
    perspective_correct,  ///< exact: linear in the triangle's 3D plane
};
/// What happens to a triangle with a vertex outside the image or behind the eye.
enum class BorderPolicy {
    drop_triangle,  ///< seed: not drawn at all
    clip,           ///< exact: clipped to the image and to a plane just in front of the eye
};
/// How overlapping triangles are resolved.
enum class Visibility {
    painter,       ///< contract: farthest mean depth first, later triangles overwrite
    depth_buffer,  ///< per-sample nearest depth wins (not part of the contract; for comparison)
};
enum class Precision { single_float, double_float };

struct RenderOptions {
    LightVectors light_vectors = LightVectors::shaded_point;
    Interpolation interpolation = Interpolation::perspective_correct;
    BorderPolicy border = BorderPolicy::clip;
    Visibility visibility = Visibility::painter;
    Precision precision = Precision::single_float;
    /// Samples per pixel = samples_per_axis^2 on an ordered grid, box-filtered. 1 = centre only.
    int samples_per_axis = 1;
    /// Worker threads; 0 uses every core. The image does not depend on it.
    int threads = 0;

    /// Exactly the contract's three seed simplifications, nothing else.
    static RenderOptions seed();
    /// The contract's rendering without those simplifications.
    static RenderOptions exact();
};

struct ImageSpec {
    int rows = 512;     ///< M
    int columns = 512;  ///< N
    glm::vec3 background{1.0f};
};

/// Everything a scene file describes, with the mesh loaded.
struct Scene {
    Mesh mesh;
    Camera camera;
    ImageSpec image;
    PhongMaterial material;
    glm::vec3 ambient{0.2f};  ///< Ia
    std::vector<PointLight> lights;
    Shader shader = Shader::phong;
    Lighting lighting = Lighting::full();
};

struct RenderStats {
    std::uint64_t triangles_in = 0;
    std::uint64_t triangles_degenerate = 0;  ///< zero projected area after snapping: cover nothing
    std::uint64_t triangles_dropped = 0;     ///< seed border rule: a vertex outside the image or behind the eye
    std::uint64_t triangles_clipped = 0;     ///< crossed the image border or the near plane and were clipped
    std::uint64_t triangles_outside = 0;     ///< entirely outside the view: nothing to draw
    std::uint64_t triangles_drawn = 0;       ///< reached the fill (possibly as several clipped pieces)
    std::uint64_t samples_shaded = 0;        ///< samples written (a sample is a pixel when samples_per_axis = 1)
    std::uint64_t nonfinite_values_replaced = 0;  ///< should stay 0: a last guard, counted so tests see it
    double seconds = 0.0;                    ///< wall time of the whole render
};

struct RenderResult {
    Image image;
    RenderStats stats;
};

/// Renders a scene. Throws std::invalid_argument for an invalid camera, image
/// size or mesh (the message names the field).
RenderResult render(const Scene& scene, const RenderOptions& options = RenderOptions::exact());

/// The seed's call with plain arrays: positions (x, y, z), per-vertex colours
/// (r, g, b; may be empty for white) and faces (0-based index triples).
Image render_object(const std::vector<glm::dvec3>& positions,
                    const std::vector<glm::vec3>& colors,
                    const std::vector<Triangle>& faces, const Camera& camera,
                    const ImageSpec& image, const PhongMaterial& material,
                    const glm::vec3& ambient, const std::vector<PointLight>& lights,
                    Shader shader, Lighting lighting,
                    const RenderOptions& options = RenderOptions::exact());

}  // namespace phongrast

#endif  // PHONGRAST_RENDER_HPP
