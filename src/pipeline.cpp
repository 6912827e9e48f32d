// The pipeline's table of contents: the stages of one render pass, in order.
// Every stage is a template over the arithmetic type Real (float or double)
// so the same scene can be rendered in both and compared (RenderOptions::precision).
#include "pipeline.hpp"

#include "back_faces.hpp"
#include "scene_analysis.hpp"
#include "term_counts.hpp"

namespace phongrast::detail {

template <typename Real>
void render_pass(const Scene& scene, const RenderOptions& options, int rows, int columns, glm::dvec2 sample_offset,
                 FrameMemory<Real>& memory, RenderStats& stats, const PassOutput& out, ProgressMonitor& progress) {
    const View view(scene.camera, rows, columns, sample_offset);
    const EffectSet effects = find_effects(scene);
    stats.effects = effects;

    // Vertex stage.
    const bool need_normals = effects.normals || !options.specialize_effects || out.aov_planes.normal;
    transform_vertices(scene.mesh, view, need_normals, memory.vertex_stage, memory.vertices, progress);
    const HiddenBackFaces cull = back_faces_to_cull(scene, options, view, memory.vertices);
    stats.back_faces_culled = cull != HiddenBackFaces::unknown;
    build_light_rig(scene, view.frame, memory.rig);
    const PointShader<Real> point_shader{&memory.rig, effects, options.specialize_effects};
    const FillPlan<Real> fill_plan = plan_fill(scene, options, effects, memory.rig);
    if (scene.shader == Shader::gouraud && options.light_vectors == LightVectors::shaded_point) {
        light_vertices(point_shader, memory.vertices.varyings, memory.vertex_stage);
        count_term_evaluations(scene, options, effects, memory.vertices.varyings.size(), LitPoints::outside_the_fill,
                               stats);
    }

    // Set-up first, in mesh order; then painter's order of what draws; then bands in that order.
    const SetupInput<Real> setup{scene, options, view, memory.vertices, cull, point_shader, fill_plan.setup};
    set_up_triangles(setup, memory.draws, stats, progress);
    const bool sort = !fill_plan.order_free || out.aov_planes.any();  // depth and id name the last triangle
    // Mesh order hook: a reordered mesh's equal depths are drawn in the caller's triangle order.
    const std::uint32_t* original = out.original_triangle;
    const TieRank tie_rank = original == nullptr ? TieRank() : TieRank([&](const DrawnTriangle& drawn) {
        return original[memory.draws.chunk_draws[drawn.chunk()][drawn.first()].source];
    });
    painter_order(memory.draws.chunk_drawn, memory.draws.chunk_keys, memory.draws.chunks, sort, memory.painter,
                  progress, tie_rank);
    if (sort) stats.triangles_sorted += memory.painter.sorted.size();
    bin_draws(memory.draws, memory.painter, rows, memory.binning, memory.bins);

    progress.begin_stage(0.4, out.aov_planes.any() ? 0.9 : 1.0, static_cast<std::size_t>(memory.bins.bands));
    fill_bins(scene, options, fill_plan, memory.bins, rows, columns, memory.fill, out.image, stats, progress);

    if (out.aov_planes.any()) {
        out.aovs.reset(rows, columns, out.aov_planes);
        const AovPassInput<Real> aov_input{&memory.bins, scene.shader,
                                           options.interpolation == Interpolation::perspective_correct,
                                           fill_plan.depth_test ? memory.fill.depth_buffer.data() : nullptr,
                                           &scene.mesh.triangles, &memory.vertices.varyings, &view.frame,
                                           out.original_triangle};
        run_aov_pass(aov_input, out.aov_planes, out.aovs, progress);
    }
}

template void render_pass<float>(const Scene&, const RenderOptions&, int, int, glm::dvec2, FrameMemory<float>&,
                                 RenderStats&, const PassOutput&, ProgressMonitor&);
template void render_pass<double>(const Scene&, const RenderOptions&, int, int, glm::dvec2, FrameMemory<double>&,
                                  RenderStats&, const PassOutput&, ProgressMonitor&);

}  // namespace phongrast::detail
