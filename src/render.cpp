// The render pipeline: vertex transform -> painter's sort -> triangle setup
// (seed drop or clipping, snapping) -> banded parallel fill and shading.
//
// Every stage is a template over the arithmetic type Real (float or double)
// so the same scene can be rendered in both and compared (RenderOptions::precision).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "aov_pass.hpp"
#include "clipping.hpp"
#include "depth_sort.hpp"
#include "fill_types.hpp"
#include "normals_scratch.hpp"
#include "progress_monitor.hpp"
#include "phongrast/render.hpp"
#include "raster.hpp"
#include "scene_analysis.hpp"
#include "shading.hpp"

namespace phongrast {
namespace detail {
namespace {

/// Distance of the near clip plane in front of the eye, relative to the focal
/// length so that scaling a whole scene (camera included) scales it too. What
/// it removes is visible only within 1e-4 of the sensor's half-size around
/// the image centre.
constexpr double kNearPlaneOverFocal = 1e-4;
/// Projected coordinates up to this size are clipped exactly (differences of
/// two of them stay finite); beyond it only overflow can have produced them.
constexpr double kMaxClippableProjection = 1e306;
constexpr int kBandRows = 16;
constexpr std::size_t kSetupChunk = 4096;
/// Vertices lit by one task (Gouraud with exact light vectors).
constexpr std::size_t kVertexBlock = 1024;
/// How many triangles ahead the setup and the fill ask for the memory they will read.
constexpr std::size_t kPrefetchAhead = 8;

/// Overdraw::shade_visible's scratch for one band of rows, kept between frames.
struct VisibleLayer {
    std::vector<std::uint32_t> owner;  ///< per sample of the band: its last triangle, or kNoOwner
    std::vector<std::uint8_t> shown;   ///< per triangle of the band: owns at least one sample
};

/// A hint to start loading *address into the cache (no effect on results).
inline void prefetch_address(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}
/// Every cache line of *object.
template <typename T>
void prefetch_object(const T* object) {
    const char* bytes = reinterpret_cast<const char*>(object);
    for (std::size_t offset = 0; offset < sizeof(T); offset += 64) prefetch_address(bytes + offset);
    prefetch_address(bytes + sizeof(T) - 1);
}

bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void validate_scene_values(const Scene& scene) {
    const PhongMaterial& m = scene.material;
    if (!finite3(m.ka)) throw std::invalid_argument("material.ka: expected finite numbers");
    if (!finite3(m.kd)) throw std::invalid_argument("material.kd: expected finite numbers");
    if (!finite3(m.ks)) throw std::invalid_argument("material.ks: expected finite numbers");
    if (!(m.n >= 0.0f) || !std::isfinite(m.n)) {
        throw std::invalid_argument("material.n: expected a non-negative finite number");
    }
    if (!finite3(scene.ambient)) throw std::invalid_argument("ambient: expected finite numbers");
    if (!finite3(scene.image.background)) {
        throw std::invalid_argument("image.background: expected finite numbers");
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (!finite3(scene.lights[i].position) || !finite3(scene.lights[i].intensity)) {
            throw std::invalid_argument("lights[" + std::to_string(i) +
                                        "]: expected finite position and intensity");
        }
    }
    validate_mesh(scene.mesh);
}

/// Corners created by clipping, which draw triangles point to: stored in
/// blocks that never move, kept (and reused) from one frame to the next.
template <typename Real>
class ClipVertexStore {
public:
    void clear() { used_ = 0; }
    const Varyings<Real>* push(const Varyings<Real>& corner) {
        const std::size_t block = used_ / kBlockSize;
        if (block == blocks_.size()) blocks_.push_back(std::make_unique<Varyings<Real>[]>(kBlockSize));
        Varyings<Real>* slot = &blocks_[block][used_ % kBlockSize];
        *slot = corner;
        ++used_;
        return slot;
    }

private:
    static constexpr std::size_t kBlockSize = 256;
    std::vector<std::unique_ptr<Varyings<Real>[]>> blocks_;
    std::size_t used_ = 0;
};

struct SetupCounts {
    std::uint64_t degenerate = 0, dropped = 0, clipped = 0, outside = 0, between_samples = 0, drawn = 0, culled = 0;
    std::uint64_t lit_points = 0;  ///< flat triangles or Gouraud corners lit during setup
};

/// Everything a frame works in, kept by a Renderer from one frame to the
/// next: vectors are resized, never shrunk, so a frame no larger than an
/// earlier one allocates nothing.
template <typename Real>
struct FrameBuffers {
    NormalsScratch normals_scratch;
    std::vector<glm::vec3> normals;
    std::vector<double> camera_depth, column, row;
    std::vector<Varyings<Real>> varyings;
    LightRig<Real> rig;
    std::vector<double> mean_depth;
    std::vector<std::uint32_t> order;
    DepthSortScratch sort;
    /// The set-up triangles in painter's order: chunk after chunk, each in order.
    std::vector<std::vector<DrawTriangle<Real>>> chunk_draws;
    std::vector<ClipVertexStore<Real>> chunk_clip_vertices;
    std::vector<SetupCounts> chunk_counts;
    std::vector<std::uint32_t> chunk_band_count, band_start, chunk_band_cursor;
    std::vector<const DrawTriangle<Real>*> binned;
    std::vector<std::uint64_t> shaded, replaced, covered;
    std::vector<Real> depth_buffer;
    // Scratch per fixed piece of work (vertex block, setup chunk, band), not
    // per thread: which worker runs which piece changes from frame to frame,
    // and thread-local scratch would then be allocated whenever a thread
    // first ran a piece.
    std::vector<LightVectorsAt<Real>> vertex_vectors, setup_vectors, band_vectors;
    std::vector<VisibleLayer> band_layers;
};

template <typename Real>
class Pipeline {
public:
    /// sample_offset: where in each pixel, relative to its centre, this render
    /// samples (in pixels); the geometry is shifted by minus it (rotated grid).
    Pipeline(const Scene& scene, const RenderOptions& options, int rows, int columns, FrameBuffers<Real>& buffers,
             ProgressMonitor& progress, glm::dvec2 sample_offset = glm::dvec2(0.0))
        : scene_(scene), options_(options), progress_(progress),
          poll_(progress.enabled() ? std::function<void()>([&progress] { progress.poll(); }) : nullptr),
          frame_(make_camera_frame(scene.camera, rows, columns)),
          near_(scene.camera.focal * kNearPlaneOverFocal), sample_offset_(sample_offset), buffers_(buffers),
          rig_(buffers.rig), camera_depth_(buffers.camera_depth), column_(buffers.column), row_(buffers.row),
          varyings_(buffers.varyings) {}

    /// Renders into `image` (resized to the frame, its memory reused), and
    /// the extra outputs `aov_planes` asks for into `aovs`.
    void run(RenderStats& stats, Image& image, const AovRequest& aov_planes, AovSamples& aovs) {
        effects_ = find_effects(scene_);
        stats.effects = effects_;
        if (options_.back_faces == BackFaces::cull_when_hidden) {
            hidden_back_faces_ = find_hidden_back_faces(scene_.mesh, scene_.camera.eye);
        }
        transform_vertices();
        if (hidden_back_faces_ != HiddenBackFaces::unknown && front_faces_may_be_cut()) {
            hidden_back_faces_ = HiddenBackFaces::unknown;
        }
        stats.back_faces_culled = hidden_back_faces_ != HiddenBackFaces::unknown;
        build_light_rig();
        choose_kernel();
        if (scene_.shader == Shader::gouraud &&
            options_.light_vectors == LightVectors::shaded_point) {
            light_vertices();
            count_point_evaluations(varyings_.size(), stats);
        }
        painter_order();
        set_up_triangles(stats);
        fill(stats, image, aov_planes.any() ? 0.9 : 1.0);
        if (aov_planes.any()) fill_aovs(aov_planes, aovs);
    }

private:
    // ---- Vertex stage -------------------------------------------------------------
    void transform_vertices() {
        const Mesh& mesh = scene_.mesh;
        const std::size_t count = mesh.positions.size();
        // Ambient-only scenes never look at a normal: do not compute any.
        const bool need_normals = effects_.normals || !options_.specialize_effects || options_.aovs.normal;
        if (need_normals && mesh.normals.empty()) {
            progress_.begin_stage(0.0, 0.05, 1);
            calculate_normals_into(mesh.positions, mesh.triangles, buffers_.normals_scratch, buffers_.normals,
                                   poll_);
        }
        const std::vector<glm::vec3>& normals = mesh.normals.empty() ? buffers_.normals : mesh.normals;

        camera_depth_.resize(count);
        column_.resize(count);
        row_.resize(count);
        varyings_.resize(count);
        progress_.begin_stage(0.05, 0.1, (count + 4095) / 4096);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
                          [&](const tbb::blocked_range<std::size_t>& range) {
            if (progress_.cancelled()) return;
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                const glm::dvec3 camera = frame_.camera_from_world(mesh.positions[i]);
                camera_depth_[i] = camera.z;
                if (camera.z > 0.0) {
                    const ProjectedPoint p = frame_.pixel_from_camera(camera);
                    column_[i] = p.column - sample_offset_.x;
                    row_[i] = p.row - sample_offset_.y;
                } else {
                    column_[i] = row_[i] = std::numeric_limits<double>::quiet_NaN();
                }
                Varyings<Real>& v = varyings_[i];
                v.position = Vec3<Real>(camera);
                v.normal = need_normals ? safe_normalize<Real>(Vec3<Real>(
                                              frame_.camera_from_world_direction(glm::dvec3(normals[i]))))
                                        : Vec3<Real>(Real(0));
                v.color = mesh.colors.empty() ? Vec3<Real>(Real(1)) : Vec3<Real>(mesh.colors[i]);
                v.lit = Vec3<Real>(Real(0));
            }
            progress_.piece_done();
        });
        progress_.throw_if_cancelled();
    }

    // Culling is only invisible when every front face is drawn whole: a front
    // face dropped by the seed's border rule, or cut by the near plane, opens
    // a hole through which painter's order (and the depth buffer) would show
    // the back face behind it. Checked on the vertices, conservatively.
    bool front_faces_may_be_cut() const {
        for (std::size_t i = 0; i < camera_depth_.size(); ++i) {
            if (options_.border == BorderPolicy::drop_triangle ? !vertex_inside_image(static_cast<std::uint32_t>(i))
                                                               : camera_depth_[i] < near_) {
                return true;
            }
        }
        return false;
    }

    void build_light_rig() {
        rig_.lights.clear();
        rig_.active_lights.clear();
        rig_.material = scene_.material;
        rig_.lighting = scene_.lighting;
        // The same product, in the same order, as ambient_term(): ka * Ia, then * c.
        rig_.ambient_factor = Vec3<Real>(scene_.material.ka) * Vec3<Real>(scene_.ambient);
        for (const PointLight& light : scene_.lights) {
            const CameraLight<Real> camera_light{Vec3<Real>(frame_.camera_from_world(light.position)),
                                                 Vec3<Real>(light.intensity)};
            rig_.lights.push_back(camera_light);
            if (light.intensity != glm::vec3(0.0f)) rig_.active_lights.push_back(camera_light);
        }
        point_shader_.rig = &rig_;
        point_shader_.effects = effects_;
        point_shader_.specialized = options_.specialize_effects;
    }

    void choose_kernel() {
        const std::vector<glm::vec3>& colors = scene_.mesh.colors;
        fill_setup_.rig = &rig_;
        fill_setup_.uniform_color = !effects_.varying_colors;
        fill_setup_.color = colors.empty() ? Vec3<Real>(Real(1)) : Vec3<Real>(colors[0]);
        KernelChoice choice;
        choice.phong = scene_.shader == Shader::phong;
        choice.flat = scene_.shader == Shader::flat;
        choice.perspective = options_.interpolation == Interpolation::perspective_correct;
        choice.specialized = options_.specialize_effects;
        choice.per_sample_vectors = options_.light_vectors == LightVectors::shaded_point;
        choice.uniform_color = fill_setup_.uniform_color;
        choice.effects = effects_;
        kernel_ = pick_fill_kernel<Real>(choice);
    }

    // Term counts for `points` lit outside the fill (vertices, corners, flat centroids).
    void count_point_evaluations(std::uint64_t points, RenderStats& stats) const {
        if (options_.specialize_effects) {
            if (effects_.ambient) stats.ambient_evaluations += points;
            if (effects_.diffuse) stats.diffuse_evaluations += points * effects_.active_lights;
            if (effects_.specular) stats.specular_evaluations += points * effects_.active_lights;
        } else {
            if (scene_.lighting.ambient) stats.ambient_evaluations += points;
            if (scene_.lighting.diffuse) stats.diffuse_evaluations += points * scene_.lights.size();
            if (scene_.lighting.specular) stats.specular_evaluations += points * scene_.lights.size();
        }
    }

    // Gouraud with exact light vectors: each vertex's colour does not depend on
    // the triangle, so it is lit once and shared.
    void light_vertices() {
        const std::size_t blocks = (varyings_.size() + kVertexBlock - 1) / kVertexBlock;
        if (buffers_.vertex_vectors.size() < blocks) buffers_.vertex_vectors.resize(blocks);
        tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
            LightVectorsAt<Real>& vectors = buffers_.vertex_vectors[block];
            const std::size_t end = std::min(varyings_.size(), (block + 1) * kVertexBlock);
            for (std::size_t i = block * kVertexBlock; i != end; ++i) {
                Varyings<Real>& v = varyings_[i];
                v.lit = point_shader_(vectors, v.position, v.normal, v.color);
            }
        });
    }

    // ---- Painter's order ----------------------------------------------------------
    // Depth is the mean z_c of the three vertices; farthest first; ties keep mesh order.
    void painter_order() {
        const std::vector<Triangle>& triangles = scene_.mesh.triangles;
        std::vector<double>& depth = buffers_.mean_depth;
        depth.resize(triangles.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 16384),
                          [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t t = range.begin(); t != range.end(); ++t) {
                const Triangle& tri = triangles[t];
                depth[t] = (camera_depth_[tri[0]] + camera_depth_[tri[1]] + camera_depth_[tri[2]]) / 3.0;
            }
        });
        progress_.begin_stage(0.1, 0.15, 1);
        farthest_first_order(depth, buffers_.order, buffers_.sort, poll_);
    }

    // ---- Triangle setup -----------------------------------------------------------
    void set_up_triangles(RenderStats& stats) {
        // Fixed-size chunks, concatenated in chunk order: the draw list is the
        // same whatever the number of threads.
        const std::vector<std::uint32_t>& order = buffers_.order;
        const std::size_t chunks = (order.size() + kSetupChunk - 1) / kSetupChunk;
        std::vector<std::vector<DrawTriangle<Real>>>& chunk_draws = buffers_.chunk_draws;
        std::vector<ClipVertexStore<Real>>& chunk_clip_vertices = buffers_.chunk_clip_vertices;
        std::vector<SetupCounts>& chunk_counts = buffers_.chunk_counts;
        if (chunk_draws.size() < chunks) chunk_draws.resize(chunks);
        if (chunk_clip_vertices.size() < chunks) chunk_clip_vertices.resize(chunks);
        if (buffers_.setup_vectors.size() < chunks) buffers_.setup_vectors.resize(chunks);
        chunk_counts.assign(chunks, SetupCounts{});
        progress_.begin_stage(0.15, 0.4, chunks);
        tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
            if (progress_.cancelled()) return;
            const std::size_t begin = chunk * kSetupChunk;
            const std::size_t end = std::min(order.size(), begin + kSetupChunk);
            chunk_draws[chunk].clear();
            chunk_draws[chunk].reserve(end - begin);
            chunk_clip_vertices[chunk].clear();
            for (std::size_t k = begin; k < end; ++k) {
                if (k + kPrefetchAhead < end) prefetch_vertices(scene_.mesh.triangles[order[k + kPrefetchAhead]]);
                set_up_triangle(order[k], chunk_draws[chunk], chunk_clip_vertices[chunk], chunk_counts[chunk],
                                buffers_.setup_vectors[chunk]);
            }
            progress_.piece_done();
        });
        progress_.throw_if_cancelled();
        for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
            stats.triangles_degenerate += chunk_counts[chunk].degenerate;
            stats.triangles_dropped += chunk_counts[chunk].dropped;
            stats.triangles_clipped += chunk_counts[chunk].clipped;
            stats.triangles_outside += chunk_counts[chunk].outside;
            stats.triangles_between_samples += chunk_counts[chunk].between_samples;
            stats.triangles_drawn += chunk_counts[chunk].drawn;
            stats.triangles_culled += chunk_counts[chunk].culled;
            count_point_evaluations(chunk_counts[chunk].lit_points, stats);
        }
        chunks_ = chunks;
    }

    // Painter's order visits the vertices in no particular order: ask for a
    // triangle's vertex data a few triangles before it is set up.
    void prefetch_vertices(const Triangle& tri) const {
        for (std::uint32_t index : tri) {
            prefetch_address(&column_[index]);
            prefetch_address(&row_[index]);
            prefetch_address(&camera_depth_[index]);
            prefetch_object(&varyings_[index]);
        }
    }

    // The seed's rule looks at the unshifted vertex, whatever the sample offset.
    bool vertex_inside_image(std::uint32_t i) const {
        const double column = column_[i] + sample_offset_.x, row = row_[i] + sample_offset_.y;
        return camera_depth_[i] > 0.0 && column >= 0.0 && column <= frame_.columns && row >= 0.0 &&
               row <= frame_.rows;
    }

    void project(ClipVertex<Real>& v) const {
        const ProjectedPoint p = frame_.pixel_from_camera(glm::dvec3(v.varyings.position));
        v.column = p.column - sample_offset_.x;
        v.row = p.row - sample_offset_.y;
    }

    void set_up_triangle(std::uint32_t source, std::vector<DrawTriangle<Real>>& out,
                         ClipVertexStore<Real>& clip_vertices, SetupCounts& counts,
                         LightVectorsAt<Real>& vectors) const {
        const Triangle& tri = scene_.mesh.triangles[source];
        if (hidden_back_faces_ != HiddenBackFaces::unknown && faces_away(tri)) {
            ++counts.culled;
            return;
        }
        const bool inside_image =
            vertex_inside_image(tri[0]) && vertex_inside_image(tri[1]) && vertex_inside_image(tri[2]);
        if (!inside_image && options_.border == BorderPolicy::drop_triangle) {
            ++counts.dropped;
            return;
        }

        const Vec3<Real> centroid =
            (varyings_[tri[0]].position + varyings_[tri[1]].position + varyings_[tri[2]].position) / Real(3);
        if (inside_image && camera_depth_[tri[0]] >= near_ && camera_depth_[tri[1]] >= near_ &&
            camera_depth_[tri[2]] >= near_) {
            set_up_unclipped(source, centroid, out, counts, vectors);
            return;
        }

        ClipPolygon<Real> polygon;
        polygon.count = 3;
        for (int i = 0; i < 3; ++i) {
            ClipVertex<Real>& v = polygon.vertices[i];
            v.varyings = varyings_[tri[i]];
            v.depth = camera_depth_[tri[i]];
            v.column = column_[tri[i]];
            v.row = row_[tri[i]];
        }
        if (scene_.shader == Shader::gouraud) {
            Varyings<Real>* corners[3] = {&polygon.vertices[0].varyings, &polygon.vertices[1].varyings,
                                          &polygon.vertices[2].varyings};
            counts.lit_points += light_corners(corners, centroid, vectors);
        }

        bool clipped = !inside_image;
        if (!clip_to_view(polygon)) {
            ++counts.outside;
            return;
        }

        const std::size_t first_draw = out.size();
        bool any_area = false, any_drawn = false;
        const Varyings<Real>* stored[8] = {};  // the polygon's corners, stored once the first piece is drawn
        for (std::size_t k = 1; k + 1 < polygon.count; ++k) {
            const ClipVertex<Real>* corner[3] = {&polygon.vertices[0], &polygon.vertices[k],
                                                 &polygon.vertices[k + 1]};
            DrawTriangle<Real> draw;
            const SnappedPoint a = snap(corner[0]->column, corner[0]->row);
            const SnappedPoint b = snap(corner[1]->column, corner[1]->row);
            const SnappedPoint c = snap(corner[2]->column, corner[2]->row);
            if (edge_value(a, b, c.x, c.y) != 0) any_area = true;
            if (!setup_coverage(a, b, c, frame_.rows, frame_.columns, draw.coverage)) continue;
            if (!any_drawn) {
                for (std::size_t i = 0; i < polygon.count; ++i) {
                    stored[i] = clip_vertices.push(polygon.vertices[i].varyings);
                }
            }
            std::size_t corner_index[3] = {0, k, k + 1};
            if (draw.coverage.swapped) {
                std::swap(corner[1], corner[2]);
                std::swap(corner_index[1], corner_index[2]);
            }
            for (int i = 0; i < 3; ++i) {
                draw.v[i] = stored[corner_index[i]];
                draw.lit[i] = corner[i]->varyings.lit;
                draw.depth[i] = static_cast<Real>(corner[i]->depth);
            }
            draw.centroid = centroid;
            draw.source = source;
            out.push_back(draw);
            any_drawn = true;
        }
        if (clipped) ++counts.clipped;
        if (any_drawn && scene_.shader == Shader::flat) {
            // Lit only once something is to be drawn: clipped-away and
            // degenerate triangles cost no lighting.
            const Vec3<Real> lit = flat_color(tri, centroid, vectors);
            ++counts.lit_points;
            for (std::size_t d = first_draw; d < out.size(); ++d) {
                for (Vec3<Real>& corner_lit : out[d].lit) corner_lit = lit;
            }
        }
        if (any_drawn) {
            ++counts.drawn;
        } else if (!any_area) {
            ++counts.degenerate;
        } else if (meets_image(polygon)) {
            ++counts.between_samples;
        } else {
            ++counts.outside;  // within the guard band, beyond the image's border
        }
    }

    // The common case, with nothing to clip: no polygon, one draw triangle
    // straight from the vertex arrays.
    void set_up_unclipped(std::uint32_t source, const Vec3<Real>& centroid, std::vector<DrawTriangle<Real>>& out,
                          SetupCounts& counts, LightVectorsAt<Real>& vectors) const {
        const Triangle& tri = scene_.mesh.triangles[source];
        DrawTriangle<Real> draw;
        const SnappedPoint a = snap(column_[tri[0]], row_[tri[0]]);
        const SnappedPoint b = snap(column_[tri[1]], row_[tri[1]]);
        const SnappedPoint c = snap(column_[tri[2]], row_[tri[2]]);
        if (!setup_coverage(a, b, c, frame_.rows, frame_.columns, draw.coverage)) {
            // Its corners are inside the image: a triangle of non-zero area
            // that fails here has no sample centre in its bounding box.
            if (draw.coverage.area2 == 0) {
                ++counts.degenerate;
            } else {
                ++counts.between_samples;
            }
            return;
        }
        std::uint32_t index[3] = {tri[0], tri[1], tri[2]};
        if (draw.coverage.swapped) std::swap(index[1], index[2]);
        for (int i = 0; i < 3; ++i) {
            draw.v[i] = &varyings_[index[i]];
            draw.lit[i] = varyings_[index[i]].lit;
            draw.depth[i] = static_cast<Real>(camera_depth_[index[i]]);
        }
        draw.centroid = centroid;
        draw.source = source;
        if (scene_.shader == Shader::flat) {
            const Vec3<Real> lit = flat_color(tri, centroid, vectors);
            for (Vec3<Real>& corner_lit : draw.lit) corner_lit = lit;
            ++counts.lit_points;
        } else if (scene_.shader == Shader::gouraud) {
            // Lit copies of the corners: light_corners() writes their `lit`, the mesh's vertices stay as they are.
            Varyings<Real> copies[3] = {*draw.v[0], *draw.v[1], *draw.v[2]};
            Varyings<Real>* corners[3] = {&copies[0], &copies[1], &copies[2]};
            counts.lit_points += light_corners(corners, centroid, vectors);
            for (int i = 0; i < 3; ++i) draw.lit[i] = copies[i].lit;
        }
        out.push_back(draw);
        ++counts.drawn;
    }

    // Whether a clipped polygon (convex, in pixel coordinates) overlaps the
    // image rectangle: separating axes are the rectangle's two and the
    // polygon's edges, each with every rectangle corner strictly outside.
    bool meets_image(const ClipPolygon<Real>& polygon) const {
        const double width = frame_.columns, height = frame_.rows;
        double column_min = polygon.vertices[0].column, column_max = column_min;
        double row_min = polygon.vertices[0].row, row_max = row_min;
        double twice_area = 0.0;
        for (std::size_t i = 0; i < polygon.count; ++i) {
            const ClipVertex<Real>& a = polygon.vertices[i];
            const ClipVertex<Real>& b = polygon.vertices[(i + 1) % polygon.count];
            column_min = std::min(column_min, a.column);
            column_max = std::max(column_max, a.column);
            row_min = std::min(row_min, a.row);
            row_max = std::max(row_max, a.row);
            twice_area += a.column * b.row - b.column * a.row;
        }
        if (column_max < 0.0 || column_min > width || row_max < 0.0 || row_min > height) return false;
        const double corners[4][2] = {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
        for (std::size_t i = 0; i < polygon.count; ++i) {
            const ClipVertex<Real>& a = polygon.vertices[i];
            const ClipVertex<Real>& b = polygon.vertices[(i + 1) % polygon.count];
            bool all_outside = true;
            for (const auto& corner : corners) {
                const double side = (b.column - a.column) * (corner[1] - a.row) - (b.row - a.row) * (corner[0] - a.column);
                all_outside = all_outside && (twice_area > 0.0 ? side < 0.0 : side > 0.0);
            }
            if (all_outside) return false;
        }
        return true;
    }

    // A back face: its vertices run clockwise seen from the eye (for an
    // outward-oriented mesh), decided in double in world space.
    bool faces_away(const Triangle& tri) const {
        const glm::dvec3& a = scene_.mesh.positions[tri[0]];
        const glm::dvec3 normal =
            glm::cross(scene_.mesh.positions[tri[1]] - a, scene_.mesh.positions[tri[2]] - a);
        const double facing = glm::dot(normal, scene_.camera.eye - a);
        return hidden_back_faces_ == HiddenBackFaces::outward_oriented ? facing < 0.0 : facing > 0.0;
    }

    // Flat: one colour per triangle, lit at the centroid with the mean vertex
    // normal (renormalised) and the mean vertex colour.
    Vec3<Real> flat_color(const Triangle& tri, const Vec3<Real>& centroid, LightVectorsAt<Real>& vectors) const {
        Vec3<Real> normal(Real(0)), color(Real(0));
        for (std::uint32_t index : tri) {
            normal += varyings_[index].normal;
            color += varyings_[index].color;
        }
        const Vec3<Real> surface = fill_setup_.uniform_color ? fill_setup_.color : color / Real(3);
        return point_shader_(vectors, centroid, safe_normalize<Real>(normal), surface);
    }

    // Gouraud with the seed's centroid vectors: lights the triangle's own
    // corners (before clipping, so clipped corners interpolate lit colours).
    // Returns the points lit.
    std::uint64_t light_corners(Varyings<Real>* const corners[3], const Vec3<Real>& centroid,
                                LightVectorsAt<Real>& vectors) const {
        if (scene_.shader == Shader::gouraud && options_.light_vectors == LightVectors::triangle_centroid) {
            for (int i = 0; i < 3; ++i) {
                Varyings<Real>& v = *corners[i];
                v.lit = point_shader_(vectors, centroid, v.normal, v.color);
            }
            return 3;
        }
        return 0;  // Gouraud with exact vectors: `lit` came from light_vertices(); Phong lights per sample.
    }

    // Near plane, then the guard band. Returns false when nothing is left.
    bool clip_to_view(ClipPolygon<Real>& polygon) const {
        ClipPolygon<Real> scratch;
        bool behind = false;
        for (std::size_t i = 0; i < polygon.count; ++i) behind |= polygon.vertices[i].depth < near_;
        if (behind) {
            clip_against<Real>(
                polygon, scratch, [this](const ClipVertex<Real>& v) { return v.depth - near_; },
                [this](const ClipVertex<Real>& inside, const ClipVertex<Real>& outside, double t) {
                    ClipVertex<Real> v;
                    v.varyings = lerp(inside.varyings, outside.varyings, static_cast<Real>(t));
                    v.depth = inside.depth + (outside.depth - inside.depth) * t;
                    v.varyings.position.z = static_cast<Real>(v.depth);
                    project(v);
                    return v;
                });
            polygon = scratch;
            if (polygon.count < 3) return false;
        }

        // A corner that cannot be represented -- NaN or infinite because a
        // coordinate near the top of the double range (or beyond float's, in a
        // float render) overflowed on the way here -- cannot be clipped
        // meaningfully: the triangle is skipped (counted outside) rather than
        // fed to the fixed-point snapping, where it would overflow.
        for (std::size_t i = 0; i < polygon.count; ++i) {
            const ClipVertex<Real>& v = polygon.vertices[i];
            if (!(std::abs(v.column) <= kMaxClippableProjection && std::abs(v.row) <= kMaxClippableProjection)) {
                return false;
            }
        }

        const double lo = -kGuardBandPixels;
        const double column_hi = frame_.columns + kGuardBandPixels;
        const double row_hi = frame_.rows + kGuardBandPixels;
        bool beyond_guard = false;
        for (std::size_t i = 0; i < polygon.count; ++i) {
            const ClipVertex<Real>& v = polygon.vertices[i];
            beyond_guard |= !(v.column >= lo && v.column <= column_hi && v.row >= lo && v.row <= row_hi);
        }
        if (!beyond_guard) return true;

        const bool perspective = options_.interpolation == Interpolation::perspective_correct;
        const auto make = [perspective](const ClipVertex<Real>& inside, const ClipVertex<Real>& outside,
                                        double t) {
            // t is linear in screen space; for perspective-correct attributes the
            // matching 3D parameter weights each end by 1/z.
            double s = t;
            if (perspective) {
                const double wi = (1.0 - t) / inside.depth, wo = t / outside.depth;
                s = wo / (wi + wo);
            }
            ClipVertex<Real> v;
            v.varyings = lerp(inside.varyings, outside.varyings, static_cast<Real>(s));
            v.depth = inside.depth + (outside.depth - inside.depth) * s;
            v.column = inside.column + (outside.column - inside.column) * t;
            v.row = inside.row + (outside.row - inside.row) * t;
            return v;
        };
        const auto plane = [&](auto distance) {
            clip_against<Real>(polygon, scratch, distance, make);
            polygon = scratch;
            return polygon.count >= 3;
        };
        return plane([lo](const ClipVertex<Real>& v) { return v.column - lo; }) &&
               plane([column_hi](const ClipVertex<Real>& v) { return column_hi - v.column; }) &&
               plane([lo](const ClipVertex<Real>& v) { return v.row - lo; }) &&
               plane([row_hi](const ClipVertex<Real>& v) { return row_hi - v.row; });
    }

    // ---- Fill ---------------------------------------------------------------------
    /// `progress_end`: the fraction of the render done when the fill is.
    void fill(RenderStats& stats, Image& image, double progress_end) {
        image.rows = frame_.rows;
        image.columns = frame_.columns;
        image.pixels.assign(static_cast<std::size_t>(frame_.rows) * static_cast<std::size_t>(frame_.columns),
                            scene_.image.background);
        const bool depth_test = options_.visibility == Visibility::depth_buffer;
        std::vector<Real>& depth_buffer = buffers_.depth_buffer;
        depth_buffer.assign(depth_test ? image.pixels.size() : 0, std::numeric_limits<Real>::infinity());
        const int bands = (frame_.rows + kBandRows - 1) / kBandRows;
        std::vector<std::uint64_t>& shaded = buffers_.shaded;
        std::vector<std::uint64_t>& replaced = buffers_.replaced;
        std::vector<std::uint64_t>& covered = buffers_.covered;
        shaded.assign(bands, 0);
        replaced.assign(bands, 0);
        covered.assign(bands, 0);
        const std::vector<std::vector<DrawTriangle<Real>>>& chunk_draws = buffers_.chunk_draws;

        // Bin the draws by band, keeping painter's order within each band:
        // counted and scattered in parallel over the setup chunks (which are
        // in painter's order), each chunk writing its own slice of every band.
        const std::size_t chunks = chunks_;
        std::vector<std::uint32_t>& chunk_band_count = buffers_.chunk_band_count;
        chunk_band_count.assign(chunks * static_cast<std::size_t>(bands), 0);
        const auto for_each_band = [](const DrawTriangle<Real>& draw, auto&& visit) {
            for (int band = draw.coverage.row_min / kBandRows; band <= draw.coverage.row_max / kBandRows; ++band) {
                visit(static_cast<std::size_t>(band));
            }
        };
        tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
            std::uint32_t* count = &chunk_band_count[chunk * static_cast<std::size_t>(bands)];
            for (const DrawTriangle<Real>& draw : chunk_draws[chunk]) {
                for_each_band(draw, [&](std::size_t band) { ++count[band]; });
            }
        });
        // Band-major offsets: band b's slice starts at band_start[b]; within it, chunk after chunk.
        std::vector<std::uint32_t>& band_start = buffers_.band_start;
        std::vector<std::uint32_t>& chunk_band_cursor = buffers_.chunk_band_cursor;
        band_start.assign(static_cast<std::size_t>(bands) + 1, 0);
        chunk_band_cursor.resize(chunk_band_count.size());
        {
            std::uint32_t total = 0;
            for (int band = 0; band < bands; ++band) {
                band_start[band] = total;
                for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
                    const std::size_t slot = chunk * static_cast<std::size_t>(bands) + static_cast<std::size_t>(band);
                    chunk_band_cursor[slot] = total;
                    total += chunk_band_count[slot];
                }
            }
            band_start[bands] = total;
        }
        std::vector<const DrawTriangle<Real>*>& binned = buffers_.binned;
        binned.resize(band_start[bands]);
        tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
            std::uint32_t* cursor = &chunk_band_cursor[chunk * static_cast<std::size_t>(bands)];
            for (const DrawTriangle<Real>& draw : chunk_draws[chunk]) {
                for_each_band(draw, [&](std::size_t band) { binned[cursor[band]++] = &draw; });
            }
        });

        const bool shade_visible = !depth_test && overdraw_shades_visible_only();
        if (buffers_.band_vectors.size() < static_cast<std::size_t>(bands)) buffers_.band_vectors.resize(bands);
        if (shade_visible && buffers_.band_layers.size() < static_cast<std::size_t>(bands)) {
            buffers_.band_layers.resize(bands);
        }
        progress_.begin_stage(0.4, progress_end, static_cast<std::size_t>(bands));
        tbb::parallel_for(0, bands, [&](int band) {
            if (progress_.cancelled()) return;
            FillTarget<Real> target{image, depth_buffer, band * kBandRows,
                                    std::min(frame_.rows, (band + 1) * kBandRows), depth_test, 0, 0};
            const DrawTriangle<Real>* const* draws = binned.data() + band_start[band];
            const std::uint32_t count = band_start[band + 1] - band_start[band];
            LightVectorsAt<Real>& vectors = buffers_.band_vectors[band];
            if (shade_visible) {
                fill_visible_layer(draws, count, target, vectors, buffers_.band_layers[band], covered[band]);
            } else {
                for (std::uint32_t i = 0; i < count; ++i) {
                    if (i + kPrefetchAhead < count) prefetch_object(draws[i + kPrefetchAhead]);
                    kernel_(*draws[i], target, vectors, fill_setup_);
                }
                covered[band] = target.covered;
            }
            shaded[band] = target.samples;
            replaced[band] = target.replaced;
            progress_.piece_done();
        });
        progress_.throw_if_cancelled();
        for (int band = 0; band < bands; ++band) {
            stats.samples_covered += covered[band];
            stats.samples_shaded += shaded[band];
            stats.nonfinite_values_replaced += replaced[band];
        }
        count_sample_evaluations(stats.samples_shaded, stats);
    }

    /// The extra outputs, from the bins the fill just used.
    void fill_aovs(const AovRequest& planes, AovSamples& out) const {
        out.reset(frame_.rows, frame_.columns, planes);
        AovPassInput<Real> input;
        input.binned = buffers_.binned.data();
        input.band_start = buffers_.band_start.data();
        input.bands = (frame_.rows + kBandRows - 1) / kBandRows;
        input.band_rows = kBandRows;
        input.shader = scene_.shader;
        input.perspective = options_.interpolation == Interpolation::perspective_correct;
        input.depth_buffer = options_.visibility == Visibility::depth_buffer ? buffers_.depth_buffer.data() : nullptr;
        input.triangles = &scene_.mesh.triangles;
        input.vertices = &varyings_;
        input.frame = &frame_;
        run_aov_pass(input, planes, out, progress_);
    }

    /// Overdraw::automatic picks shade_visible only for per-sample lighting:
    /// there shading a sample costs several times the second coverage pass,
    /// while Gouraud's or flat's per-sample work (an interpolation, a store)
    /// costs about what the pass does (docs/performance.md, "Overdraw").
    bool overdraw_shades_visible_only() const {
        switch (options_.overdraw) {
            case Overdraw::shade_all: return false;
            case Overdraw::shade_visible: return true;
            case Overdraw::automatic: break;
        }
        // Decided by the scene alone, so the general kernel compares with the specialised ones like for like.
        return scene_.shader == Shader::phong && effects_.normals;
    }

    /// Overdraw::shade_visible for one band: pass one records which of the
    /// band's triangles paints each sample last (painter's order: the last
    /// one to cover it); pass two shades, in the same order, only the
    /// triangles that own a sample, and of each only the samples it owns.
    /// Every sample gets the colour the classic fill leaves there, computed
    /// by the same kernel from the same weights, once.
    void fill_visible_layer(const DrawTriangle<Real>* const* draws, std::uint32_t count, FillTarget<Real>& target,
                            LightVectorsAt<Real>& vectors, VisibleLayer& layer, std::uint64_t& covered) const {
        const std::size_t samples = static_cast<std::size_t>(target.row_end - target.row_begin) *
                                    static_cast<std::size_t>(frame_.columns);
        layer.owner.assign(samples, kNoOwner);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (i + kPrefetchAhead < count) prefetch_object(draws[i + kPrefetchAhead]);
            covered += record_owner(*draws[i], target, i, layer.owner.data());
        }
        layer.shown.assign(count, 0);
        for (const std::uint32_t owner : layer.owner) {
            if (owner != kNoOwner) layer.shown[owner] = 1;
        }
        target.owner = layer.owner.data();
        for (std::uint32_t i = 0; i < count; ++i) {
            if (!layer.shown[i]) continue;  // entirely painted over: no shading at all
            target.self = i;
            kernel_(*draws[i], target, vectors, fill_setup_);
        }
    }

    // Per-sample term counts follow from the kernel chosen: it evaluates exactly these.
    void count_sample_evaluations(std::uint64_t samples, RenderStats& stats) const {
        if (scene_.shader != Shader::phong) return;
        if (options_.specialize_effects) {
            if (effects_.ambient) stats.ambient_evaluations += samples;
            if (effects_.diffuse) stats.diffuse_evaluations += samples * effects_.active_lights;
            if (effects_.specular) stats.specular_evaluations += samples * effects_.active_lights;
            if (effects_.normals) stats.normal_interpolations += samples;
        } else {
            if (scene_.lighting.ambient) stats.ambient_evaluations += samples;
            if (scene_.lighting.diffuse) stats.diffuse_evaluations += samples * scene_.lights.size();
            if (scene_.lighting.specular) stats.specular_evaluations += samples * scene_.lights.size();
            stats.normal_interpolations += samples;
        }
    }

    const Scene& scene_;
    RenderOptions options_;
    ProgressMonitor& progress_;
    /// progress_.poll(), for the serial and block loops outside this class (empty without a callback).
    std::function<void()> poll_;
    CameraFrame frame_;
    double near_;
    glm::dvec2 sample_offset_;
    EffectSet effects_;
    HiddenBackFaces hidden_back_faces_ = HiddenBackFaces::unknown;
    FrameBuffers<Real>& buffers_;
    LightRig<Real>& rig_;
    PointShader<Real> point_shader_;
    FillSetup<Real> fill_setup_;
    FillKernel<Real> kernel_ = nullptr;
    std::vector<double>& camera_depth_;
    std::vector<double>& column_;
    std::vector<double>& row_;
    std::vector<Varyings<Real>>& varyings_;
    std::size_t chunks_ = 0;  ///< setup chunks of this frame (buffers_.chunk_draws may hold more)
};

// Rotated grid: sample k = i * s + j of an s x s set sits at
//   column offset (i s + j + 1/2) / s^2 - 1/2,  row offset (j s + (s - 1 - i) + 1/2) / s^2 - 1/2,
// a lattice whose s^2 samples all have distinct columns and distinct rows
// (for s = 2: (+-1/8, +-3/8) and (+-3/8, -+1/8), the classic rotated grid).
// The offsets are multiples of 1/(2 s^2) pixel, exact after 1/256 snapping for s <= 8.
glm::dvec2 rotated_grid_offset(int i, int j, int s) {
    const double cells = double(s) * double(s);
    return {(double(i * s + j) + 0.5) / cells - 0.5, (double(j * s + (s - 1 - i)) + 0.5) / cells - 0.5};
}

// Adds one pass's sample work to the total; triangle counts come from the first pass.
void add_pass_stats(const RenderStats& pass, RenderStats& total) {
    total.samples_covered += pass.samples_covered;
    total.samples_shaded += pass.samples_shaded;
    total.nonfinite_values_replaced += pass.nonfinite_values_replaced;
    total.ambient_evaluations += pass.ambient_evaluations;
    total.diffuse_evaluations += pass.diffuse_evaluations;
    total.specular_evaluations += pass.specular_evaluations;
    total.normal_interpolations += pass.normal_interpolations;
}

/// Averages each factor x factor block of `fine` into `coarse` (resized, memory reused).
void box_downsample(const Image& fine, int factor, int rows, int columns, Image& coarse) {
    coarse.rows = rows;
    coarse.columns = columns;
    coarse.pixels.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    const float weight = 1.0f / static_cast<float>(factor * factor);
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            glm::vec3 sum(0.0f);
            for (int dy = 0; dy < factor; ++dy) {
                for (int dx = 0; dx < factor; ++dx) sum += fine.at(row * factor + dy, column * factor + dx);
            }
            coarse.at(row, column) = sum * weight;
        }
    }
}

void validate_render_request(const Scene& scene, const RenderOptions& options) {
    validate_scene_values(scene);
    if (options.samples_per_axis < 1 || options.samples_per_axis > 16) {
        throw std::invalid_argument("samples_per_axis: expected 1 to 16, got " +
                                    std::to_string(options.samples_per_axis));
    }
    if (options.threads < 0) throw std::invalid_argument("threads: expected 0 (all cores) or more");
    const int factor = options.samples_per_axis;
    const long long fine_rows = static_cast<long long>(scene.image.rows) * factor;
    const long long fine_columns = static_cast<long long>(scene.image.columns) * factor;
    if (scene.image.rows < 1 || fine_rows > kMaxImageSide) {
        throw std::invalid_argument("image.height: expected 1 to " + std::to_string(kMaxImageSide / factor) +
                                    " rows, got " + std::to_string(scene.image.rows));
    }
    if (scene.image.columns < 1 || fine_columns > kMaxImageSide) {
        throw std::invalid_argument("image.width: expected 1 to " + std::to_string(kMaxImageSide / factor) +
                                    " columns, got " + std::to_string(scene.image.columns));
    }
}

}  // namespace

/// A Renderer's state: its options, its thread arena and every buffer a frame works in.
struct RendererState {
    RenderOptions options;
    std::vector<std::pair<int, std::unique_ptr<tbb::task_arena>>> arenas;
    RenderResult result;
    Image fine, pass, sum;  ///< supersampling: the large image, or one rotated-grid pass and the running sum
    AovSamples aov_samples;  ///< one pass's extra outputs per sample, before the resolve into result.aovs
    FrameBuffers<float> single;
    FrameBuffers<double> twice;

    template <typename Real>
    FrameBuffers<Real>& buffers() {
        if constexpr (std::is_same_v<Real, float>) {
            return single;
        } else {
            return twice;
        }
    }

    /// One arena per thread count asked for, kept: switching thread counts between frames allocates nothing either.
    tbb::task_arena& arena_for(int threads) {
        for (auto& [count, arena] : arenas) {
            if (count == threads) return *arena;
        }
        constexpr int kAllCores = tbb::task_arena::automatic;  // a copy: no reference to TBB's static member
        arenas.emplace_back(threads, std::make_unique<tbb::task_arena>(threads > 0 ? threads : kAllCores));
        return *arenas.back().second;
    }

    void render(const Scene& scene) {
        const auto start = std::chrono::steady_clock::now();
        validate_render_request(scene, options);
        ProgressMonitor progress(options.progress);
        const int factor = options.samples_per_axis;
        const int fine_rows = scene.image.rows * factor, fine_columns = scene.image.columns * factor;
        // The planes each pass fills per sample (none unless asked: the frame is then the colour fill alone).
        const AovRequest aov_planes =
            options.aovs.any() ? sample_planes_for(options.aovs, factor) : AovRequest{};
        reset_aov_planes(scene.image.rows, scene.image.columns, aov_planes, result.aovs);
        result.stats = RenderStats{};
        result.stats.triangles_in = scene.mesh.triangles.size();
        arena_for(options.threads).execute([&] {
            // One pipeline run; `aov_factor` is its samples per pixel axis for the extra outputs' resolve.
            const auto run = [&](auto real_tag, int rows, int columns, glm::dvec2 offset, RenderStats& stats,
                                 Image& image, int aov_factor) {
                using Real = decltype(real_tag);
                Pipeline<Real> pipeline(scene, options, rows, columns, buffers<Real>(), progress, offset);
                pipeline.run(stats, image, aov_planes, aov_samples);
                if (aov_planes.any()) resolve_aovs(aov_samples, aov_factor, aov_planes, result.aovs);
            };
            const auto run_in_precision = [&](int rows, int columns, glm::dvec2 offset, RenderStats& stats,
                                              Image& image, int aov_factor) {
                if (options.precision == Precision::double_float) {
                    run(double{}, rows, columns, offset, stats, image, aov_factor);
                } else {
                    run(float{}, rows, columns, offset, stats, image, aov_factor);
                }
            };
            if (factor > 1 && options.sample_pattern == SamplePattern::rotated_grid) {
                // One render per sample at the final size, averaged like box_downsample does.
                sum.rows = scene.image.rows;
                sum.columns = scene.image.columns;
                sum.pixels.assign(static_cast<std::size_t>(sum.rows) * static_cast<std::size_t>(sum.columns),
                                  glm::vec3(0.0f));
                for (int i = 0; i < factor; ++i) {
                    for (int j = 0; j < factor; ++j) {
                        RenderStats pass_stats;
                        pass_stats.triangles_in = result.stats.triangles_in;
                        progress.set_pass(i * factor + j, factor * factor);
                        run_in_precision(scene.image.rows, scene.image.columns, rotated_grid_offset(i, j, factor),
                                         pass_stats, pass, 1);
                        for (std::size_t p = 0; p < sum.pixels.size(); ++p) sum.pixels[p] += pass.pixels[p];
                        if (i == 0 && j == 0) {
                            result.stats = pass_stats;
                        } else {
                            add_pass_stats(pass_stats, result.stats);
                        }
                    }
                }
                const float weight = 1.0f / static_cast<float>(factor * factor);
                result.image.rows = sum.rows;
                result.image.columns = sum.columns;
                result.image.pixels.resize(sum.pixels.size());
                for (std::size_t p = 0; p < sum.pixels.size(); ++p) result.image.pixels[p] = sum.pixels[p] * weight;
                return;
            }
            if (factor == 1) {
                run_in_precision(fine_rows, fine_columns, glm::dvec2(0.0), result.stats, result.image, 1);
                return;
            }
            run_in_precision(fine_rows, fine_columns, glm::dvec2(0.0), result.stats, fine, factor);
            box_downsample(fine, factor, scene.image.rows, scene.image.columns, result.image);
        });
        if (aov_planes.any()) finish_aovs(options.aovs, factor * factor, result.aovs);
        progress.finish();
        result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

}  // namespace detail

Renderer::Renderer(const RenderOptions& options) : state_(std::make_unique<detail::RendererState>()) {
    state_->options = options;
}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

const RenderOptions& Renderer::options() const { return state_->options; }
void Renderer::set_options(const RenderOptions& options) { state_->options = options; }

const RenderResult& Renderer::render(const Scene& scene) {
    state_->render(scene);
    return state_->result;
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    detail::RendererState state;
    state.options = options;
    state.render(scene);
    return std::move(state.result);
}

Image render_object(const std::vector<glm::dvec3>& positions, const std::vector<glm::vec3>& colors,
                    const std::vector<Triangle>& faces, const Camera& camera, const ImageSpec& image,
                    const PhongMaterial& material, const glm::vec3& ambient,
                    const std::vector<PointLight>& lights, Shader shader, Lighting lighting,
                    const RenderOptions& options) {
    Scene scene;
    scene.mesh.positions = positions;
    scene.mesh.colors = colors;
    scene.mesh.triangles = faces;
    scene.camera = camera;
    scene.image = image;
    scene.material = material;
    scene.ambient = ambient;
    scene.lights = lights;
    scene.shader = shader;
    scene.lighting = lighting;
    return render(scene, options).image;
}

}  // namespace phongrast
