// render(): the seed's render_object. Computes normals, projects, sorts the
// triangles farthest first by mean camera depth (stable), and fills each with
// the chosen shader, following the scene contract in docs/scene-format.md.
// docs/architecture.md follows a scene through the stages.
#ifndef PHONGRAST_RENDER_HPP
#define PHONGRAST_RENDER_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "phongrast/aov.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/image.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/material.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/progress.hpp"
#include "phongrast/texture.hpp"

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
/// What painter's order spends on samples that a later triangle paints over.
/// Whichever is chosen, the image is the same bit for bit: a sample's colour
/// depends only on the triangle that paints it last. The depth buffer
/// (Visibility::depth_buffer) always shades as it tests: this applies to
/// painter's order only.
enum class Overdraw {
    shade_all,      ///< the classic painter's fill: every triangle shades every sample it covers
    shade_visible,  ///< per band of rows, the triangles in reverse painter's order, each
                    ///< shading only the samples no triangle before it covered: one shading
                    ///< per sample for a test per covered sample
    automatic,      ///< shade_visible where shading costs more than that test (Phong
                    ///< with diffuse or specular light, and every shader on a textured
                    ///< scene: measured in docs/performance.md), shade_all elsewhere
};
enum class Precision { single_float, double_float };
/// Where the samples_per_axis^2 samples of a pixel lie (box-filtered either way).
enum class SamplePattern {
    ordered_grid,  ///< an s x s grid: one render of an image s times larger, then averaged
    rotated_grid,  ///< s^2 samples with s^2 distinct columns and rows (for s = 2 the classic
                   ///< rotated-grid pattern): one render per sample, each with the geometry
                   ///< shifted by minus that sample's offset, then averaged
};
/// Whether back faces of a closed mesh are skipped.
enum class BackFaces {
    draw,              ///< contract: every triangle is painted
    cull_when_hidden,  ///< skip back faces when the mesh is closed and the eye is outside it (detected per render)
};

struct RenderOptions {
    LightVectors light_vectors = LightVectors::shaded_point;
    Interpolation interpolation = Interpolation::perspective_correct;
    BorderPolicy border = BorderPolicy::clip;
    Visibility visibility = Visibility::painter;
    /// Not a simplification (the image does not change): the same in both presets.
    Overdraw overdraw = Overdraw::automatic;
    Precision precision = Precision::single_float;
    /// Samples per pixel = samples_per_axis^2, box-filtered. 1 = centre only.
    int samples_per_axis = 1;
    /// Placement of those samples; ignored when samples_per_axis is 1.
    SamplePattern sample_pattern = SamplePattern::ordered_grid;
    /// Worker threads; 0 uses every core, more than the machine has are
    /// clamped to that (quietly). The image does not depend on it.
    int threads = 0;
    /// Off by default in both presets: the contract paints every triangle, and culling
    /// changes the pixels where painter's order shows a back face over a front face.
    BackFaces back_faces = BackFaces::draw;
    /// true: fill with a kernel compiled for exactly the effects the scene needs
    /// (see EffectSet). false: the general kernel, which asks per sample which
    /// terms are on. Both give the same image bit for bit; false exists to prove
    /// that and to measure what specialisation saves.
    bool specialize_effects = true;
    /// Extra planes to fill next to the colour (RenderResult::aovs); none by default.
    AovRequest aovs;
    /// Progress reports, and cancellation by returning false (progress.hpp). Empty: none.
    ProgressCallback progress;
    /// How textured faces sample their texture; the contract's picture is bilinear.
    TextureFilter texture_filter = TextureFilter::bilinear;

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

/// Where vertex normals come from (contract "Lighting").
enum class NormalSource {
    computed,  ///< area-weighted from the positions (calculate_normals), per object in world space
    file,      ///< each corner's normal from the mesh file (Mesh::file_normals), else the computed one
};
/// "computed" or "file"; throws std::invalid_argument otherwise.
NormalSource parse_normal_source(std::string_view text);
const char* to_string(NormalSource source);

/// One placed mesh of a scene of several objects (contract "Objects").
struct SceneObject {
    /// Shared, so that a mesh placed many times is held once.
    std::shared_ptr<const Mesh> mesh;
    /// Model matrix (column vectors: p_world = transform * [p, 1]); last row
    /// 0 0 0 1, finite, not singular. A negative determinant (a mirror)
    /// reverses each triangle's corners so computed normals stay outward.
    glm::dmat4 transform{1.0};
    /// Overrides the scene's material fields (and so each face's own), field by field.
    MaterialFields material;
    /// Overrides Scene::normals for this object when set.
    std::optional<NormalSource> normals;
    std::string name;  ///< for messages ("objects[2]" when empty)
};

/// Everything a scene file describes, with the meshes loaded.
///
/// Either one mesh (`mesh`, object 0 with the identity transform: the
/// version-1 scene, rendered exactly as before) or several `objects`, whose
/// triangles form one list in the order given for painter's order and the
/// id output. Not both: a scene with objects must leave `mesh` empty.
struct Scene {
    Mesh mesh;
    std::vector<SceneObject> objects;
    Camera camera;
    ImageSpec image;
    /// The base material: what every face has when nothing else gives a field
    /// (for scene files: the scene's fields, else the contract's defaults).
    PhongMaterial material;
    /// The scene's own material fields, which win over each face's material
    /// from its mesh file (contract precedence: object, scene, face, base).
    /// Empty for version-1 scenes built in memory: `material` is then all.
    MaterialFields material_fields;
    NormalSource normals = NormalSource::computed;
    glm::vec3 ambient{0.2f};  ///< Ia
    std::vector<PointLight> lights;
    Shader shader = Shader::phong;
    Lighting lighting = Lighting::full();
};

/// The effects a render really simulates: the lighting selection intersected
/// with what the scene makes non-zero.
struct EffectSet {
    bool ambient = false;            ///< selected, and ka * Ia is non-zero
    bool diffuse = false;            ///< selected, kd non-zero, and some light has non-zero intensity
    bool specular = false;           ///< selected, ks non-zero, and some light has non-zero intensity
    bool varying_colors = false;     ///< vertex colours are not all equal
    bool normals = false;            ///< diffuse or specular: normals are needed at all
    std::uint32_t active_lights = 0; ///< lights with non-zero intensity (the others cost nothing)
};
std::string to_string(const EffectSet& effects);

struct RenderStats {
    std::uint64_t triangles_in = 0;
    std::uint64_t triangles_culled = 0;      ///< back faces skipped (BackFaces::cull_when_hidden, closed mesh, eye outside)
    std::uint64_t triangles_degenerate = 0;  ///< zero projected area after snapping: cover nothing
    std::uint64_t triangles_dropped = 0;     ///< seed border rule: a vertex outside the image or behind the eye
    std::uint64_t triangles_clipped = 0;     ///< crossed the image border or the near plane and were clipped
    std::uint64_t triangles_outside = 0;     ///< entirely outside the view: nothing to draw
    /// A corner beyond what the render's precision can draw, skipped whole: in
    /// front of the eye farther than 1e30 (single precision; 1e300 in double),
    /// or, clipped at the near plane, projected beyond 1e306 sample widths.
    std::uint64_t triangles_out_of_range = 0;
    std::uint64_t triangles_between_samples = 0;  ///< in the view, but no sample centre inside (smaller than the sample spacing)
    std::uint64_t triangles_drawn = 0;       ///< reached the fill (possibly as several clipped pieces)
    std::uint64_t triangles_sorted = 0;      ///< drawn triangles put into painter's order: 0 when every covered
                                             ///< sample gets one colour and no extra output names a triangle
    std::uint64_t samples_covered = 0;       ///< samples inside drawn triangles, overdraw included (a sample is a pixel when samples_per_axis = 1)
    std::uint64_t samples_shaded = 0;        ///< samples shaded and written: samples_covered with Overdraw::shade_all
                                             ///< (depth buffer: those passing the test); the visible ones with shade_visible
    std::uint64_t nonfinite_values_replaced = 0;  ///< should stay 0: a last guard, counted so tests see it
    /// Evaluations of each lighting term: one per light per shaded point
    /// (vertex for Gouraud, sample for Phong, triangle for flat); ambient one per point.
    std::uint64_t ambient_evaluations = 0;
    std::uint64_t diffuse_evaluations = 0;
    std::uint64_t specular_evaluations = 0;
    std::uint64_t normal_interpolations = 0;  ///< samples where a normal was interpolated and renormalised
    EffectSet effects;                        ///< what was simulated
    bool back_faces_culled = false;           ///< the mesh was found closed with the eye outside, and culled
    /// The scene has no triangles at all (no vertices, or vertices without
    /// triangles): the image is the background alone. Not an error; the
    /// phongrast command warns.
    bool empty_scene = false;
    double seconds = 0.0;                    ///< wall time of the whole render

    /// Adds every counter and the seconds of `other` (a sum over several
    /// renders); effects, back_faces_culled and empty_scene stay this one's.
    RenderStats& operator+=(const RenderStats& other);
};

/// One counter of RenderStats: its name (the field's, as the phongrast
/// command's --stats JSON writes it) and the field.
struct RenderCounter {
    const char* name;
    std::uint64_t RenderStats::*field;
    /// A count of triangles, the same for every sample position of a render
    /// (false: a count of work, which each rotated-grid pass adds to).
    bool counts_triangles;
};
/// Every counter of RenderStats, in the order the struct declares them.
const std::vector<RenderCounter>& render_counters();

struct RenderResult {
    Image image;
    RenderStats stats;
    AovPlanes aovs;  ///< the planes RenderOptions::aovs asked for, at the image's size
};

/// Renders a scene. Throws std::invalid_argument for an invalid camera, mesh,
/// option or enum value, a negative coefficient or intensity, a non-finite
/// value, or lit values that could pass 1e30; std::length_error for an image
/// (or its samples) past the size limit (image.hpp); each message names the
/// C++ member (docs/robustness.md lists every case). RenderCancelled when the
/// progress callback asks to stop.
///
/// Each thread keeps the working memory of its last render() call for its
/// next one when the frame is small (at most 262,144 triangles and
/// 2048 x 2048 samples), so a series of one-off calls does not fault in
/// fresh memory every time. What stays never changes the picture, which is
/// the one a fresh call draws: the memory, and normals computed for a mesh
/// without any, reused only while its positions and triangles are the same
/// bytes. Larger frames release their memory as they return (a Renderer
/// keeps any size). The image returned is a copy of the kept one.
RenderResult render(const Scene& scene, const RenderOptions& options = RenderOptions::exact());

/// render() into `out`, the image without a copy: the frame is drawn in
/// out.image's memory when it can hold the frame's pixels (else in the
/// thread's kept image, which then trades places with out.image), so a loop
/// that passes the same RenderResult call after call draws in one buffer,
/// with no copy of its image and no fresh pages (what out.image held before
/// does not matter: its size and contents are overwritten). The picture,
/// statistics and extra outputs are render()'s.
void render(const Scene& scene, const RenderOptions& options, RenderResult& out);

/// Frees the memory render() keeps for the calling thread (it is freed
/// anyway when the thread ends).
void release_render_memory();

/// The checks render() makes before drawing, alone: throws what render()
/// would throw for `scene` and `options`, so that a caller can name the file
/// the bad value came from before any work.
void validate_render(const Scene& scene, const RenderOptions& options = RenderOptions::exact());

namespace detail {
struct RendererState;
}

/// Renders frame after frame (an animation, a benchmark, an interactive
/// view) and keeps its working memory and worker threads from one frame to
/// the next: once it has rendered a frame, a frame with no more vertices,
/// triangles, pixels and lights than any before allocates no memory
/// (tests/test_renderer.cpp counts). Pictures and statistics are render()'s.
/// One frame at a time: a Renderer is not to be used by two threads at once.
class Renderer {
public:
    explicit Renderer(const RenderOptions& options = RenderOptions::exact());
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const RenderOptions& options() const;
    void set_options(const RenderOptions& options);

    /// Renders `scene`. The result stays valid until the next call; copy it to keep it.
    /// Throws like render(). A moved-from Renderer works again like a new
    /// Renderer() (exact options).
    const RenderResult& render(const Scene& scene);

private:
    detail::RendererState& state();
    std::unique_ptr<detail::RendererState> state_;
};

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
