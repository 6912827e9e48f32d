#include "vertex_stage.hpp"

#include "camera_lanes.hpp"
#include "fill_types.hpp"
#include "normalize_lanes.hpp"
#include "prefetch.hpp"
#include "resize_polling.hpp"
#include "shade_lanes.hpp"
#include "task_sizes.hpp"
#include "vertex_lighting_lanes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace phongrast::detail {
namespace {

/// Vertices transformed by one task, and the fewest a task takes when a
/// small mesh's blocks are made smaller so that every thread gets several
/// (items_per_task(); powers of two, so whole batches of kGatherLanes and
/// kTransformLanes).
constexpr std::size_t kTransformBlock = 4096;
constexpr std::size_t kSmallestTransformBlock = 512;
/// Vertices lit by one task (Gouraud with exact light vectors).
constexpr std::size_t kLightingBlock = 1024;

/// Vertices whose arrays a gathering task copies from the caller's before
/// transforming them: a tight loop of independent loads keeps many cache
/// misses in flight, where loads inside the transform's long loop body wait
/// one by one (reading the caller's arrays there made a shuffled mesh's frame
/// 1.7-1.8x its spatial order's, against 1.0-1.2x from a copy; gathered
/// here, 1.1-1.2x: docs/performance.md, "Mesh order"). 48 bytes each on the stack.
constexpr std::size_t kGatherLanes = 256;

/// Vertices transformed together (CameraLanes: 40 bytes each on the stack).
constexpr std::size_t kTransformLanes = 128;

/// The unit camera-space normals of vertices first .. first + n - 1, whose
/// world normals are normals[0 .. n-1], into their varyings.
template <typename Real>
void camera_normals(const CameraFrame& frame, const glm::vec3* normals, std::size_t first, std::size_t n,
                    FrameVector<Varyings<Real>>& varyings) {
    double camera_x[kTransformLanes], camera_y[kTransformLanes], camera_z[kTransformLanes];
    Real x[kTransformLanes], y[kTransformLanes], z[kTransformLanes];
    for (std::size_t done = 0; done < n; done += kTransformLanes) {
        const std::size_t lanes = std::min(kTransformLanes, n - done);
        camera_from_world_direction_lanes(frame, normals + done, lanes, {camera_x, camera_y, camera_z});
        for (std::size_t k = 0; k < lanes; ++k) {
            x[k] = static_cast<Real>(camera_x[k]);
            y[k] = static_cast<Real>(camera_y[k]);
            z[k] = static_cast<Real>(camera_z[k]);
        }
        safe_normalize_lanes(lanes, x, y, z);
        for (std::size_t k = 0; k < lanes; ++k) varyings[first + done + k].normal = Vec3<Real>(x[k], y[k], z[k]);
    }
}

/// Transforms vertices first .. first + n - 1, whose arrays are positions[0 .. n-1]
/// and likewise `colors` (null: white) and `normals` (null: none needed, zero);
/// `lit` as transform_vertices() says.
template <typename Real>
void transform_span(const glm::dvec3* positions, const glm::vec3* colors, const glm::vec3* normals,
                    std::size_t first, std::size_t n, const View& view, const PointShader<Real>* unlit_shader,
                    TransformedVertices<Real>& out) {
    const CameraFrame& frame = view.frame;
    const LightVectorsAt<Real> unread_vectors;  // shade_unlit() reads none
    double x[kTransformLanes], y[kTransformLanes], z[kTransformLanes], column[kTransformLanes], row[kTransformLanes];
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t done = 0; done < n; done += kTransformLanes) {
        const std::size_t lanes = std::min(kTransformLanes, n - done);
        camera_from_world_lanes(frame, positions + done, lanes, {x, y, z});
        sample_from_camera_lanes(frame, view.sample_offset, lanes, x, y, z, column, row);
        for (std::size_t k = 0; k < lanes; ++k) {
            ScreenVertex& screen = out.screen[first + done + k];
            screen.depth = z[k];
            // Behind the eye (or at it) a vertex has no sample position.
            const bool in_front = z[k] > 0.0;
            screen.column = in_front ? column[k] : kNaN;
            screen.row = in_front ? row[k] : kNaN;
            Varyings<Real>& v = out.varyings[first + done + k];
            v.position = Vec3<Real>(static_cast<Real>(x[k]), static_cast<Real>(y[k]), static_cast<Real>(z[k]));
            v.color = colors == nullptr ? Vec3<Real>(Real(1)) : Vec3<Real>(colors[done + k]);
            v.lit = unlit_shader != nullptr ? unlit_shader->shade_unlit(unread_vectors, v.color)
                                            : Vec3<Real>(Real(0));
        }
    }
    if (normals != nullptr) {
        camera_normals(frame, normals, first, n, out.varyings);
    } else {
        for (std::size_t k = 0; k < n; ++k) out.varyings[first + k].normal = Vec3<Real>(Real(0));
    }
}

/// transform_span() of vertices [begin, end) whose arrays are the caller's
/// at source[i] (CallerVertices), gathered kGatherLanes at a time.
template <typename Real>
void transform_gathered(const Mesh& caller, const std::uint32_t* source, const std::vector<glm::vec3>* normals,
                        std::size_t begin, std::size_t end, const View& view, const PointShader<Real>* unlit_shader,
                        TransformedVertices<Real>& out) {
    glm::dvec3 positions[kGatherLanes];
    glm::vec3 colors[kGatherLanes], gathered_normals[kGatherLanes];
    const bool coloured = !caller.colors.empty();
    for (std::size_t first = begin; first < end; first += kGatherLanes) {
        const std::size_t n = std::min(kGatherLanes, end - first);
        for (std::size_t k = 0; k < n; ++k) positions[k] = caller.positions[source[first + k]];
        if (coloured) {
            for (std::size_t k = 0; k < n; ++k) colors[k] = caller.colors[source[first + k]];
        }
        if (normals != nullptr) {
            for (std::size_t k = 0; k < n; ++k) gathered_normals[k] = (*normals)[source[first + k]];
        }
        // The next block's caller vertices, asked for now so that their cache
        // misses overlap this block's transform instead of the next gather.
        const std::size_t next_end = std::min(end, first + n + kGatherLanes);
        for (std::size_t i = first + n; i < next_end; ++i) {
            prefetch_object(&caller.positions[source[i]]);
            if (coloured) prefetch_object(&caller.colors[source[i]]);
            if (normals != nullptr) prefetch_object(&(*normals)[source[i]]);
        }
        transform_span(positions, coloured ? colors : nullptr, normals != nullptr ? gathered_normals : nullptr,
                       first, n, view, unlit_shader, out);
    }
}

/// light_vertices() of vertices [begin, end), with `vectors` as scratch.
template <typename Real>
void light_vertex_range(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                        FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                        LightVectorsAt<Real>& vectors) {
    if (shader.specialized && shader.effects.normals && shader.rig->active_lights.size() <= kMaxLaneLights) {
        light_vertex_lanes_dispatched(shader, materials, varyings, begin, end, vectors);
        return;
    }
    for (std::size_t i = begin; i != end; ++i) {
        Varyings<Real>& v = varyings[i];
        v.lit = materials.shader_of(shader, i)(vectors, v.position, v.normal, v.color);
    }
}

}  // namespace

View::View(const Camera& camera, int rows, int columns, glm::dvec2 offset, int samples_per_pixel)
    : frame(make_camera_frame(camera, rows, columns, samples_per_pixel)), sample_offset(offset),
      near_depth(camera.model == CameraModel::orthographic ? std::numeric_limits<double>::denorm_min()
                                                             : camera.focal * kNearPlaneOverFocal) {}

void place_near_plane(View& view, const FrameVector<ScreenVertex>& screen) {
    if (view.frame.model != CameraModel::opencv) return;
    double farthest = -std::numeric_limits<double>::infinity();
    for (const ScreenVertex& s : screen) farthest = std::max(farthest, s.depth);
    // Nothing in front of the eye (or no vertex): every vertex is behind the
    // smallest positive plane, so nothing is drawn, as it should be.
    view.near_depth = farthest > 0.0 ? std::max(farthest * kNearPlaneOverFarthestVertex,
                                                std::numeric_limits<double>::denorm_min())
                                     : std::numeric_limits<double>::denorm_min();
}

glm::dvec2 View::sample_from_camera(const glm::dvec3& point_camera) const {
    const ProjectedPoint p = frame.pixel_from_camera(point_camera);
    return {p.column - sample_offset.x, p.row - sample_offset.y};
}

template <typename Real>
void transform_vertices(const Mesh& mesh, const CallerVertices& caller, const View& view, bool need_normals,
                        VertexStageMemory<Real>& memory, TransformedVertices<Real>& out, ProgressMonitor& progress,
                        const PointShader<Real>* unlit_shader, const PointShader<Real>* lit_shader) {
    assert(unlit_shader == nullptr || lit_shader == nullptr);
    const bool gathered = caller.mesh != nullptr;
    const Mesh& arrays = gathered ? *caller.mesh : mesh;
    const std::size_t count = arrays.positions.size();
    // A zero user normal means "compute this one" (docs/robustness.md); a
    // gathered mesh's normals, and a copy's made by mesh_order.cpp, are used
    // as they are (it computed the zero ones).
    const bool computes = !gathered && !caller.normals_final && need_normals;
    const bool fill_in = computes && !mesh.normals.empty() && has_zero_normal(mesh.normals);
    if (computes && (mesh.normals.empty() || fill_in)) {
        progress.begin_stage(0.0, 0.05, 1);
        // The previous frame's normals when computed from the same positions
        // and triangles (ComputedNormalsSource): the given normals play no
        // part in them, so a mesh with zero normals reuses them too.
        if (!memory.normals_source.matches(mesh)) {
            memory.normals_source.valid = false;  // until computed whole (a cancel stops it halfway)
            calculate_normals_into(mesh.positions, mesh.triangles, memory.normals_scratch, memory.normals,
                                   progress.poll_function());
            ++memory.normals_calculated;
            memory.normals_source.remember(mesh);
        }
        if (fill_in) {
            memory.filled_normals.assign(memory.normals.begin(), memory.normals.end());
            keep_given_normals(mesh.normals, memory.filled_normals);
        }
    }
    assert(!gathered || !need_normals || arrays.normals.size() == count);
    assert(!caller.normals_final || !need_normals || mesh.normals.size() == count);
    const std::vector<glm::vec3>* normals = !need_normals        ? nullptr
                                            : fill_in            ? &memory.filled_normals
                                            : computes && mesh.normals.empty() ? &memory.normals
                                                                 : &arrays.normals;
    resize_polling(out.screen, count, progress.poll_function());
    resize_polling(out.varyings, count, progress.poll_function());
    const std::size_t block_size =
        items_per_task(count, tbb::this_task_arena::max_concurrency(), kTransformBlock, kSmallestTransformBlock);
    const std::size_t blocks = (count + block_size - 1) / block_size;
    progress.begin_stage(0.05, 0.1, blocks);
    // The lighting's scratch per block, not per thread (see light_vertices()).
    if (lit_shader != nullptr && memory.block_vectors.size() < blocks) memory.block_vectors.resize(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        if (progress.cancelled()) return;
        const std::size_t first = block * block_size, end = std::min(count, first + block_size);
        if (gathered) {
            transform_gathered(arrays, caller.source, normals, first, end, view, unlit_shader, out);
        } else {
            transform_span(arrays.positions.data() + first, arrays.colors.empty() ? nullptr : arrays.colors.data() + first,
                           normals != nullptr ? normals->data() + first : nullptr, first, end - first, view,
                           unlit_shader, out);
        }
        if (lit_shader != nullptr) {
            // While the block's varyings are still in cache (a pass of its own read them all again).
            light_vertex_range(*lit_shader, VertexMaterials<Real>{}, out.varyings, first, end,
                               memory.block_vectors[block]);
        }
        progress.piece_done();
    });
    progress.throw_if_cancelled();
}

template <typename Real>
void build_light_rig(const Scene& scene, const CameraFrame& frame, LightRig<Real>& rig) {
    build_light_rig(scene, scene.material, frame, rig);
}

template <typename Real>
void build_light_rig(const Scene& scene, const PhongMaterial& material, const CameraFrame& frame,
                     LightRig<Real>& rig) {
    rig.lights.clear();
    rig.active_lights.clear();
    rig.material = material;
    rig.lighting = scene.lighting;
    rig.eye_at_infinity = !frame.perspective();
    // The same product, in the same order, as ambient_term(): ka * Ia, then * c.
    rig.ambient_factor = Vec3<Real>(material.ka) * Vec3<Real>(scene.ambient);
    for (const PointLight& light : scene.lights) {
        const CameraLight<Real> camera_light{Vec3<Real>(frame.camera_from_world(light.position)),
                                             Vec3<Real>(light.intensity)};
        rig.lights.push_back(camera_light);
        if (light.intensity != glm::vec3(0.0f)) rig.active_lights.push_back(camera_light);
    }
}

template <typename Real>
void light_vertices(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                    FrameVector<Varyings<Real>>& varyings, VertexStageMemory<Real>& memory) {
    const std::size_t blocks = (varyings.size() + kLightingBlock - 1) / kLightingBlock;
    if (memory.block_vectors.size() < blocks) memory.block_vectors.resize(blocks);
    // Scratch per block, not per thread: which worker runs which block changes
    // from frame to frame, and per-thread scratch would then allocate.
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        const std::size_t begin = block * kLightingBlock;
        const std::size_t end = std::min(varyings.size(), (block + 1) * kLightingBlock);
        light_vertex_range(shader, materials, varyings, begin, end, memory.block_vectors[block]);
    });
}

template <typename Real>
void light_vertices_in_parts(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                             const ShadingParts<Real>& parts, FrameVector<Varyings<Real>>& varyings,
                             std::vector<Vec3<Real>>& colour_parts, VertexStageMemory<Real>& memory) {
    colour_parts.resize(varyings.size());
    const std::size_t blocks = (varyings.size() + kLightingBlock - 1) / kLightingBlock;
    if (memory.block_vectors.size() < blocks) memory.block_vectors.resize(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
        LightVectorsAt<Real>& vectors = memory.block_vectors[block];
        const std::size_t end = std::min(varyings.size(), (block + 1) * kLightingBlock);
        for (std::size_t i = block * kLightingBlock; i != end; ++i) {
            Varyings<Real>& v = varyings[i];
            const std::uint32_t surface = materials.vertex_surfaces != nullptr ? materials.vertex_surfaces[i] : 0;
            if (parts.textures[surface].texels == nullptr) {
                colour_parts[i] = materials.shader_of(shader, i)(vectors, v.position, v.normal, v.color);
                continue;
            }
            // Both parts from the same vectors (the part rigs have the material's lights).
            const PointShader<Real>& colour_part = parts.colour_part_shaders[surface];
            colour_part.compute_vectors(vectors, v.position);
            colour_parts[i] = colour_part.shade_prepared(vectors, v.normal, v.color);
            v.color = parts.specular_part_shaders[surface].shade_prepared(vectors, v.normal, v.color);
        }
    });
}

#define PHONGRAST_INSTANTIATE_VERTEX_STAGE(Real)                                                               \
    template void transform_vertices<Real>(const Mesh&, const CallerVertices&, const View&, bool,               \
                                           VertexStageMemory<Real>&, TransformedVertices<Real>&, ProgressMonitor&,  \
                                           const PointShader<Real>*, const PointShader<Real>*);                  \
    template void build_light_rig<Real>(const Scene&, const CameraFrame&, LightRig<Real>&);                     \
    template void build_light_rig<Real>(const Scene&, const PhongMaterial&, const CameraFrame&, LightRig<Real>&); \
    template void light_vertices<Real>(const PointShader<Real>&, const VertexMaterials<Real>&,                  \
                                       FrameVector<Varyings<Real>>&, VertexStageMemory<Real>&);              \
    template void light_vertices_in_parts<Real>(const PointShader<Real>&, const VertexMaterials<Real>&,         \
                                                const ShadingParts<Real>&, FrameVector<Varyings<Real>>&,        \
                                                std::vector<Vec3<Real>>&, VertexStageMemory<Real>&);
PHONGRAST_INSTANTIATE_VERTEX_STAGE(float)
PHONGRAST_INSTANTIATE_VERTEX_STAGE(double)
#undef PHONGRAST_INSTANTIATE_VERTEX_STAGE

}  // namespace phongrast::detail
