// One render pass through the stages (internal header), and the memory a
// Renderer keeps for it from frame to frame.
#ifndef PHONGRAST_SRC_PIPELINE_HPP
#define PHONGRAST_SRC_PIPELINE_HPP

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "aov_pass.hpp"
#include "binning.hpp"
#include "fill_driver.hpp"
#include "painter_order.hpp"
#include "progress_monitor.hpp"
#include "phongrast/render.hpp"
#include "scene_assembly.hpp"
#include "shading.hpp"
#include "triangle_setup.hpp"
#include "vertex_stage.hpp"

namespace phongrast::detail {

/// Everything a render pass works in, kept by a Renderer from one frame to
/// the next: vectors are resized, never shrunk, so a frame no larger than an
/// earlier one allocates nothing.
template <typename Real>
struct FrameMemory {
    VertexStageMemory<Real> vertex_stage;
    TransformedVertices<Real> vertices;
    LightRig<Real> rig;
    DrawList<Real> draws;
    PainterOrderMemory painter;
    BinningMemory binning;
    Bins<Real> bins;
    FillMemory<Real> fill;
    /// A scene of several materials: one rig and one shader per material.
    std::vector<LightRig<Real>> surface_rigs;
    std::vector<PointShader<Real>> surface_shaders;
    std::vector<KernelTexture> surface_textures;  ///< a textured scene: per material
    /// A textured scene drawn flat or Gouraud: per material, rigs and shaders of A (ks = 0) and S (ka = kd = 0).
    std::vector<LightRig<Real>> colour_part_rigs, specular_part_rigs;
    std::vector<PointShader<Real>> colour_part_shaders, specular_part_shaders;
    /// Textured Gouraud with exact vectors: A (or the whole lit colour) per vertex.
    std::vector<Vec3<Real>> vertex_colour_parts;
};

/// What one render pass writes: the image, and the extra outputs `aov_planes`
/// asks for (none: the pass does no work for them).
struct PassOutput {
    Image& image;
    const AovRequest& aov_planes;
    AovSamples& aovs;
    /// Mesh order hook: the caller's index of each triangle when the scene's mesh is a reordered copy
    /// (mesh_order.hpp), for painter's ties and the id output; null: the mesh is the caller's.
    const std::uint32_t* original_triangle = nullptr;
    /// Mesh order hook: where the vertex arrays are when the reordered copy holds only triangles.
    CallerVertices caller_vertices;
};

/// Renders `scene` at rows x columns samples, each sample `sample_offset`
/// pixels from its pixel's centre, into `out` (its memory reused); adds
/// this pass's counts to `stats`. Reports progress; throws RenderCancelled
/// when the callback asks to stop. `assembled`: what assembly made of a
/// version-2 scene (`scene` is then assembled->scene), or null.
template <typename Real>
void render_pass(const Scene& scene, const AssembledScene* assembled, const RenderOptions& options, int rows,
                 int columns, glm::dvec2 sample_offset, FrameMemory<Real>& memory, RenderStats& stats,
                 const PassOutput& out, ProgressMonitor& progress);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PIPELINE_HPP
