// The vertex stage (internal header): every vertex transformed to camera
// space and projected to sample coordinates, the lights moved to camera
// space, and, for Gouraud with exact light vectors, every vertex lit.
#ifndef PHONGRAST_SRC_VERTEX_STAGE_HPP
#define PHONGRAST_SRC_VERTEX_STAGE_HPP

#include <cstdint>
#include <vector>

#include "huge_page_pool.hpp"
#include "normals.hpp"
#include "phongrast/render.hpp"
#include "progress_monitor.hpp"
#include "shading.hpp"
#include "varyings.hpp"
#include "view.hpp"

namespace phongrast::detail {

struct KernelTexture;  // fill_types.hpp

/// Where a vertex lands: what set-up, clipping and painter's order read of
/// it, side by side, so that a triangle whose vertices lie far apart in the
/// arrays costs one cache line per vertex, not three.
struct ScreenVertex {
    double column, row;  ///< sample coordinates; NaN for a vertex not in front of the eye
    double depth;        ///< z_c (camera space), > 0 in front of the eye
};

/// The vertex stage's output, indexed like Mesh::positions.
template <typename Real>
struct TransformedVertices {
    FrameVector<ScreenVertex> screen;
    FrameVector<Varyings<Real>> varyings; ///< camera-space position and normal, colour, lit colour

    /// The seed's border rule: in front of the eye and inside the image, judged
    /// at the unshifted vertex whatever the sample offset.
    bool inside_image(std::uint32_t vertex, const View& view) const {
        const ScreenVertex& s = screen[vertex];
        const double c = s.column + view.sample_offset.x, r = s.row + view.sample_offset.y;
        return s.depth > 0.0 && c >= 0.0 && c <= view.frame.columns && r >= 0.0 && r <= view.frame.rows;
    }
};

/// The vertex stage's scratch, kept from frame to frame.
template <typename Real>
struct VertexStageMemory {
    NormalsScratch normals_scratch;
    /// Calculated from the mesh's positions and triangles alone, when it has
    /// no normals or some zero ones (kept for the next frame while
    /// normals_source matches).
    std::vector<glm::vec3> normals;
    ComputedNormalsSource normals_source;  ///< the mesh `normals` were calculated from, while valid
    /// The mesh's own normals with the zero ones taken from `normals`.
    std::vector<glm::vec3> filled_normals;
    /// Times `normals` were calculated (tests: once while the mesh is unchanged).
    std::size_t normals_calculated = 0;
    std::vector<LightVectorsAt<Real>> block_vectors;  ///< one per block of vertices lit
};

/// Where the vertex stage reads each vertex's position, colour and normal
/// when not in the rendered mesh: a reordered copy (mesh_order.hpp) that
/// holds only triangles leaves them in the caller's mesh, and rendered
/// vertex i is the caller's vertex source[i]. Gathered here, once per frame,
/// instead of into a copy that would hold them twice.
struct CallerVertices {
    const Mesh* mesh = nullptr;             ///< null: the rendered mesh's own arrays
    const std::uint32_t* source = nullptr;  ///< per rendered vertex, the caller's
    /// The rendered mesh's normals are final, zero ones too: mesh_order.cpp
    /// computed every normal the caller's mesh would (a zero one is zero in
    /// any order of triangles), so none is computed again here.
    bool normals_final = false;
};

/// Transforms and projects every vertex; computes normals when the mesh has
/// none or some zero ones and `need_normals` (an ambient-only scene never
/// looks at one), or reuses the previous frame's. With `caller.mesh` set,
/// reads the caller's arrays instead (which then have normals to use as they
/// are, or `need_normals` is false: mesh_order.cpp sees to it).
/// Reports progress, and stops early when the render is cancelled. Each
/// vertex's `lit` is zero; or with `unlit_shader` (one that
/// lights_ambient_only()) its shade_unlit() colour, computed here while the
/// colour is at hand instead of in a pass of light_vertices() over every
/// vertex; or with `lit_shader` (exact Gouraud, one material) what
/// light_vertices() computes, each block of vertices lit right after its
/// transform, while its varyings are still in cache. At most one of the two.
template <typename Real>
void transform_vertices(const Mesh& mesh, const CallerVertices& caller, const View& view, bool need_normals,
                        VertexStageMemory<Real>& memory, TransformedVertices<Real>& out, ProgressMonitor& progress,
                        const PointShader<Real>* unlit_shader = nullptr, const PointShader<Real>* lit_shader = nullptr);

/// An OpenCV camera's near plane: 1e-4 x the largest z_c of the vertices
/// (`screen`, from transform_vertices()); other cameras' is set by View.
void place_near_plane(View& view, const FrameVector<ScreenVertex>& screen);

/// The lights in camera space, those with zero intensity left out of the active ones.
template <typename Real>
void build_light_rig(const Scene& scene, const CameraFrame& frame, LightRig<Real>& rig);

/// The same with the material `material` instead of the scene's (one rig per material).
template <typename Real>
void build_light_rig(const Scene& scene, const PhongMaterial& material, const CameraFrame& frame,
                     LightRig<Real>& rig);

/// Which shader lights each vertex: in a scene of several materials, its
/// material's (assembly splits vertices so that each has one); else the one shader.
template <typename Real>
struct VertexMaterials {
    const std::uint32_t* vertex_surfaces = nullptr;     ///< per vertex; null: one material
    const PointShader<Real>* surface_shaders = nullptr; ///< per material

    const PointShader<Real>& shader_of(const PointShader<Real>& shader, std::size_t vertex) const {
        return vertex_surfaces != nullptr ? surface_shaders[vertex_surfaces[vertex]] : shader;
    }
};

/// Whether `shader` lights every vertex with its ambient term alone (a
/// specialised shader with neither diffuse nor specular, one material):
/// transform_vertices() then lights them (its `unlit_shader`), not light_vertices().
template <typename Real>
bool lights_ambient_only(const PointShader<Real>& shader, const VertexMaterials<Real>& materials) {
    return !shader.reads_position_and_normal() && materials.vertex_surfaces == nullptr;
}

/// Gouraud with exact light vectors: each vertex's colour does not depend on
/// the triangle, so it is lit once, into Varyings::lit, and shared. (A shader
/// that lights_ambient_only() is left to transform_vertices(); here it would
/// take the general loop, a call per vertex.)
template <typename Real>
void light_vertices(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                    FrameVector<Varyings<Real>>& varyings, VertexStageMemory<Real>& memory);

/// Textured Gouraud's parts (contract "Texture maps"): per material, whether
/// its faces draw a texture, and the shaders of the colour-carrying part A
/// (ks = 0) and of the specular part S (ka = kd = 0).
template <typename Real>
struct ShadingParts {
    const KernelTexture* textures = nullptr;  ///< per material; no texels: drawn untextured
    const PointShader<Real>* colour_part_shaders = nullptr;
    const PointShader<Real>* specular_part_shaders = nullptr;
};

/// light_vertices() for a textured Gouraud scene with exact vectors: a vertex
/// of a textured material gets A into `colour_parts` and S into its `color`
/// (the surface colour is read by nothing after lighting); any other vertex
/// its whole lit colour into `colour_parts`. `lit` keeps (s, t). A separate
/// array, so that untextured renders carry nothing more per vertex.
template <typename Real>
void light_vertices_in_parts(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                             const ShadingParts<Real>& parts, FrameVector<Varyings<Real>>& varyings,
                             std::vector<Vec3<Real>>& colour_parts, VertexStageMemory<Real>& memory);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VERTEX_STAGE_HPP
