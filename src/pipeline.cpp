// The pipeline's table of contents: the stages of one render pass, in order.
// Every stage is a template over the arithmetic type Real (float or double)
// so the same scene can be rendered in both and compared (RenderOptions::precision).
#include "pipeline.hpp"

#include "back_faces.hpp"
#include "effects.hpp"
#include "stage_times.hpp"
#include "term_counts.hpp"
#include "view.hpp"

namespace phongrast::detail {

namespace {

/// A scene of several materials: a rig and a shader per material, all with
/// the scene's effect set (the union over its materials).
template <typename Real>
void build_surface_shaders(const Scene& scene, const AssembledScene& assembled, const View& view,
                           const PointShader<Real>& point_shader, FrameMemory<Real>& memory) {
    const std::size_t count = assembled.surfaces.size();
    memory.surface_rigs.resize(count);
    memory.surface_shaders.resize(count);
    for (std::size_t s = 0; s < count; ++s) {
        build_light_rig(scene, assembled.surfaces[s].material, view.frame, memory.surface_rigs[s]);
        memory.surface_shaders[s] = point_shader;
        memory.surface_shaders[s].rig = &memory.surface_rigs[s];
    }
}

/// A textured scene: each material's texture as the kernels read it, and
/// (s, t) of each vertex in its `lit` (Phong reads no lit colour), from
/// where clipping and the fill interpolate it like every attribute.
/// `footprint_scale`: one sample's footprint in steps of the pass's sample
/// grid (trilinear; see KernelTexture).
template <typename Real>
void prepare_textures(const AssembledScene& assembled, const RenderOptions& options, bool perspective,
                      double footprint_scale, FrameMemory<Real>& memory) {
    memory.surface_textures.assign(assembled.surfaces.size(), KernelTexture{});
    for (std::size_t s = 0; s < assembled.surfaces.size(); ++s) {
        const std::optional<TextureMap>& map = assembled.surfaces[s].texture;
        if (!map || !map->image) continue;
        KernelTexture& texture = memory.surface_textures[s];
        texture.texels = map->image->texels.data();
        texture.rows = map->image->rows;
        texture.columns = map->image->columns;
        texture.wrap_s = map->wrap_s;
        texture.wrap_t = map->wrap_t;
        texture.filter = options.texture_filter;
        if (options.texture_filter == TextureFilter::trilinear) {
            // Built on the first frame that asks, then kept with the image (shared by every user).
            const std::vector<MipLevel>& levels = map->image->mip_levels();
            texture.mip_levels = levels.data();
            texture.mip_level_count = static_cast<int>(levels.size());
            texture.perspective = perspective;
            texture.footprint_scale = footprint_scale;
        }
    }
}

/// (s, t) of each vertex into its `lit`, which Phong and flat do not otherwise
/// read and textured Gouraud leaves to (s, t) (its A and S live elsewhere).
template <typename Real>
void put_texcoords_in_lit(const AssembledScene& assembled, FrameMemory<Real>& memory) {
    FrameVector<Varyings<Real>>& varyings = memory.vertices.varyings;
    for (std::size_t i = 0; i < varyings.size(); ++i) {
        varyings[i].lit = Vec3<Real>(Real(assembled.texcoords[i].x), Real(assembled.texcoords[i].y), Real(0));
    }
}

/// Flat and Gouraud on textured faces light A and S apart (contract "Texture maps"):
/// each material's rig without its specular coefficient, and with only it.
template <typename Real>
void build_part_shaders(const Scene& scene, const AssembledScene& assembled, const View& view,
                        const PointShader<Real>& point_shader, FrameMemory<Real>& memory) {
    const std::size_t count = assembled.surfaces.size();
    memory.colour_part_rigs.resize(count);
    memory.specular_part_rigs.resize(count);
    memory.colour_part_shaders.resize(count);
    memory.specular_part_shaders.resize(count);
    for (std::size_t s = 0; s < count; ++s) {
        PhongMaterial colour_part = assembled.surfaces[s].material, specular_part = colour_part;
        colour_part.ks = glm::vec3(0.0f);
        specular_part.ka = specular_part.kd = glm::vec3(0.0f);
        build_light_rig(scene, colour_part, view.frame, memory.colour_part_rigs[s]);
        build_light_rig(scene, specular_part, view.frame, memory.specular_part_rigs[s]);
        memory.colour_part_shaders[s] = point_shader;
        memory.colour_part_shaders[s].rig = &memory.colour_part_rigs[s];
        memory.specular_part_shaders[s] = point_shader;
        memory.specular_part_shaders[s].rig = &memory.specular_part_rigs[s];
    }
}

}  // namespace

template <typename Real>
void render_pass(const Scene& scene, const AssembledScene* assembled, const RenderOptions& options, int rows,
                 int columns, glm::dvec2 sample_offset, FrameMemory<Real>& memory, RenderStats& stats,
                 const PassOutput& out, ProgressMonitor& progress) {
    // Passes are the image's size or a whole multiple of it (supersampling).
    View view(scene.camera, rows, columns, sample_offset, std::max(1, rows / scene.image.rows));
    // The vertices' colours: the mesh's, or the caller's when the copy holds only triangles.
    const std::vector<glm::vec3>& colors =
        out.caller_vertices.mesh != nullptr ? out.caller_vertices.mesh->colors : scene.mesh.colors;
    const EffectSet effects = find_effects(scene, colors);
    stats.effects = effects;
    StageClock clock;

    build_light_rig(scene, view.frame, memory.rig);
    const PointShader<Real> point_shader{&memory.rig, effects, options.specialize_effects};
    // Several materials: each triangle and vertex names its own (assembly).
    const bool several = assembled != nullptr && !assembled->single_surface();
    const bool textured = assembled != nullptr && assembled->textured();
    // Flat and Gouraud on textured faces light A and S apart.
    const bool in_parts = textured && scene.shader != Shader::phong;
    const bool exact_gouraud = scene.shader == Shader::gouraud && options.light_vectors == LightVectors::shaded_point;
    // Exact Gouraud that lights each vertex with its ambient term alone: the
    // transform computes it as it writes the vertex's colour (light_vertices()
    // would read every vertex again for it: 3-4 ms of the 1.3M sphere's frame).
    const bool lit_in_transform = exact_gouraud && !in_parts && !several &&
                                  lights_ambient_only(point_shader, VertexMaterials<Real>{});
    // Any other exact Gouraud of one material: each block of vertices lit right
    // after its transform, while in cache, not in a pass that reads them all
    // again (1.3M sphere, 1 thread, in-process A/B: fastest frames 0.98-0.99).
    const bool lit_after_transform = exact_gouraud && !in_parts && !several && !lit_in_transform;

    // Vertex stage.
    const bool need_normals = effects.normals || !options.specialize_effects || out.aov_planes.normal;
    transform_vertices(scene.mesh, out.caller_vertices, view, need_normals, memory.vertex_stage, memory.vertices,
                       progress, lit_in_transform ? &point_shader : nullptr,
                       lit_after_transform ? &point_shader : nullptr);
    clock.lap(Stage::vertices);
    place_near_plane(view, memory.vertices.screen);
    const HiddenBackFaces cull = back_faces_to_cull(scene, options, view, memory.vertices);
    stats.back_faces_culled = cull != HiddenBackFaces::unknown;
    if (several) build_surface_shaders(scene, *assembled, view, point_shader, memory);
    if (textured) {
        // The pass has `density` samples per pixel along each axis (the
        // ordered grid's s, or 1 for each rotated-grid pass); a sample's
        // footprint is 1 / samples_per_axis of a pixel either way.
        const int density = std::max(1, rows / scene.image.rows);
        prepare_textures(*assembled, options, perspective_weights(scene, options),
                         static_cast<double>(density) / static_cast<double>(std::max(1, options.samples_per_axis)),
                         memory);
    }
    // Untextured Gouraud's `lit` is its lit colour; textured Gouraud keeps
    // that (A) apart, in the draws, and (s, t) in `lit` too.
    const bool texcoords_in_lit = assembled != nullptr && !assembled->texcoords.empty() &&
                                  (scene.shader != Shader::gouraud || textured);
    if (texcoords_in_lit) put_texcoords_in_lit(*assembled, memory);
    if (in_parts) build_part_shaders(scene, *assembled, view, point_shader, memory);
    FillPlan<Real> fill_plan = plan_fill(scene, options, effects, several ? memory.surface_rigs[0] : memory.rig,
                                         textured ? memory.surface_textures.data() : nullptr, &colors);
    if (several) fill_plan.order_free = false;  // one colour per material, not one for all
    const VertexMaterials<Real> vertex_materials{several ? assembled->vertex_surfaces.data() : nullptr,
                                                 several ? memory.surface_shaders.data() : nullptr};
    const ShadingParts<Real> parts{in_parts ? memory.surface_textures.data() : nullptr,
                                   in_parts ? memory.colour_part_shaders.data() : nullptr,
                                   in_parts ? memory.specular_part_shaders.data() : nullptr};
    clock.lap(Stage::faces);
    if (exact_gouraud && in_parts) {
        light_vertices_in_parts(point_shader, vertex_materials, parts, memory.vertices.varyings,
                                memory.vertex_colour_parts, memory.vertex_stage);
        count_term_evaluations(scene, options, effects, memory.vertices.varyings.size(), LitPoints::outside_the_fill,
                               stats);
    } else if (exact_gouraud) {
        if (!lit_in_transform && !lit_after_transform) {
            light_vertices(point_shader, vertex_materials, memory.vertices.varyings, memory.vertex_stage);
        }
        count_term_evaluations(scene, options, effects, memory.vertices.varyings.size(), LitPoints::outside_the_fill,
                               stats);
    }

    clock.lap(Stage::vertex_lights);

    // Set-up first, in mesh order; then painter's order of what draws; then bands in that order.
    const SetupInput<Real> setup{scene,
                                 options,
                                 view,
                                 memory.vertices,
                                 cull,
                                 point_shader,
                                 fill_plan.constants,
                                 several ? assembled->triangle_surfaces.data() : nullptr,
                                 several ? memory.surface_shaders.data() : nullptr,
                                 parts.textures,
                                 parts.colour_part_shaders,
                                 parts.specular_part_shaders,
                                 exact_gouraud && in_parts ? memory.vertex_colour_parts.data() : nullptr};
    const double samples_per_triangle =
        fill_plan.may_fill_in_mesh_order
            ? sampled_samples_per_triangle(scene.mesh.triangles, memory.vertices.screen, rows, columns)
            : 0.0;
    clock.lap(Stage::faces);  // the triangles' sizes, sampled to choose the walk
    if (fills_in_mesh_order(fill_plan, out.aov_planes.any(), samples_per_triangle)) {
        // Small triangles, nothing lit per sample: no record, sort or bins; a walk of the mesh per
        // thread (fill_driver.hpp).
        fill_in_mesh_order(scene, options, fill_plan, setup, out.original_triangle, rows, columns, memory.draws,
                           memory.fill, out.image, stats, progress);
        clock.lap(Stage::walk);
        return;
    }
    set_up_triangles(setup, memory.draws, stats, progress);
    clock.lap(Stage::setup);
    const bool sort = !fill_plan.order_free || out.aov_planes.any();  // depth and id name the last triangle
    // Mesh order hook: a reordered mesh's equal depths are drawn in the caller's triangle order.
    const std::uint32_t* original = out.original_triangle;
    const TieRank tie_rank = original == nullptr ? TieRank() : TieRank([&](const DrawSpan& drawn) {
        return original[memory.draws.chunk_draws[drawn.chunk()][drawn.first()].source];
    });
    painter_order(memory.draws.chunk_drawn, memory.draws.chunk_keys, memory.draws.chunks, sort, memory.painter,
                  progress, tie_rank);
    if (sort) stats.triangles_sorted += memory.painter.sorted.size();
    clock.lap(Stage::painter_order);
    bin_draws(memory.draws, memory.painter, rows, memory.binning, memory.bins, progress.poll_function());
    clock.lap(Stage::binning);

    progress.begin_stage(0.4, out.aov_planes.any() ? 0.9 : 1.0, static_cast<std::size_t>(memory.bins.bands));
    fill_bins(scene, options, fill_plan, memory.bins, rows, columns, memory.fill, out.image, stats, progress);
    clock.lap(Stage::fill);

    if (out.aov_planes.any()) {
        out.aovs.reset(rows, columns, out.aov_planes);
        const AovPassInput<Real> aov_input{&memory.bins, scene.shader,
                                           perspective_weights(scene, options),
                                           fill_plan.depth_test ? memory.fill.depth_buffer.data() : nullptr,
                                           &scene.mesh.triangles, &memory.vertices.varyings, &view.frame,
                                           view.sample_offset, texcoords_in_lit, out.original_triangle,
                                           fill_plan.shade_visible_only ? memory.fill.band_layers.data() : nullptr};
        run_aov_pass(aov_input, out.aov_planes, out.aovs, progress);
        clock.lap(Stage::extra_outputs);
    }
}

template void render_pass<float>(const Scene&, const AssembledScene*, const RenderOptions&, int, int, glm::dvec2,
                                 FrameMemory<float>&, RenderStats&, const PassOutput&, ProgressMonitor&);
template void render_pass<double>(const Scene&, const AssembledScene*, const RenderOptions&, int, int, glm::dvec2,
                                  FrameMemory<double>&, RenderStats&, const PassOutput&, ProgressMonitor&);

}  // namespace phongrast::detail
