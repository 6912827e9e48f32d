#include "fill_driver.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "fill_dispatch.hpp"
#include "prefetch.hpp"
#include "populate_pages.hpp"
#include "resize_polling.hpp"
#include "term_counts.hpp"
#include "view.hpp"

namespace phongrast::detail {
namespace {

/// A band can hold hundreds of thousands of draws (a large mesh, or
/// supersampling's tall bands), far more than 20 ms of work: every this many
/// draws the calling thread reports progress (so Ctrl-C in Python is seen)
/// and every thread looks for a cancel, instead of only between bands.
constexpr std::uint32_t kDrawsBetweenPolls = 256;

bool stop_requested(ProgressMonitor& progress) {
    if (!progress.enabled()) return false;
    progress.poll();
    return progress.cancelled();
}

/// Overdraw::automatic picks shade_visible only for per-sample lighting:
/// there shading a sample costs several times claiming it, while Gouraud's
/// or flat's per-sample work (an interpolation, a store) costs about what
/// the claims do (Gouraud visible / all 0.97-1.09 on the 512² meshes;
/// docs/performance.md, "Overdraw and instruction sets").
bool overdraw_shades_visible_only(const Scene& scene, const RenderOptions& options, const EffectSet& effects) {
    switch (options.overdraw) {
        case Overdraw::shade_all: return false;
        case Overdraw::shade_visible: return true;
        case Overdraw::automatic: break;
    }
    // Decided by the scene alone, so the general kernel compares with the specialised ones like for like.
    return scene.shader == Shader::phong && effects.normals;
}

/// How many draws ahead the fill asks for the varyings a draw points to:
/// fewer than kPrefetchAhead, so that the draw itself has mostly arrived.
constexpr std::uint32_t kCornersAhead = 4;

/// A hint to load the three corners' varyings of `draw` (random places in
/// the vertex array, in painter's order: a cache miss each on a large mesh).
template <typename Real>
void prefetch_corners(const FillTriangle<Real>& draw) {
    for (const Varyings<Real>* corner : draw.v) prefetch_object(corner);
}

/// Overdraw::shade_visible for one band: the draws go in reverse painter's
/// order, nearest first, and each claims and shades the samples no draw has
/// claimed yet (FillTarget::owner). The first to claim a sample is the last
/// painter's order draws there, so every sample gets the colour the classic
/// fill leaves there, computed by the same kernel from the same weights, once,
/// and the owner buffer ends naming that draw (read by the extra outputs).
/// One pass: a draw painted over entirely costs its coverage, no shading.
/// (It replaced two passes in painter's order, owners recorded by coverage
/// alone, then the owned samples shaded: 0.83-0.97x the time for Phong,
/// docs/performance.md.) Returns the samples covered.
template <typename Real>
std::uint64_t fill_nearest_first(const FillPlan<Real>& plan, const FillTriangle<Real>* const* draws,
                                 std::uint32_t count, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                                 VisibleLayer& layer, ProgressMonitor& progress) {
    const std::size_t samples = static_cast<std::size_t>(target.row_end - target.row_begin) *
                                static_cast<std::size_t>(target.image.columns);
    assign_populated(layer.owner, samples, kNoOwner);
    target.owner = layer.owner.data();
    for (std::uint32_t done = 0; done < count; ++done) {
        if (done % kDrawsBetweenPolls == 0 && stop_requested(progress)) return target.covered;
        const std::uint32_t i = count - 1 - done;
        if (i >= kPrefetchAhead) prefetch_object(draws[i - kPrefetchAhead]);
        if (plan.reads_corners && i >= kCornersAhead) prefetch_corners(*draws[i - kCornersAhead]);
        target.self = i;
        plan.kernel(*draws[i], target, vectors, plan.constants);
    }
    return target.covered;
}

/// The classic painter's fill of one band: every triangle shades every
/// sample it covers. Returns the samples covered.
template <typename Real>
std::uint64_t fill_every_layer(const FillPlan<Real>& plan, const FillTriangle<Real>* const* draws, std::uint32_t count,
                      FillTarget<Real>& target, LightVectorsAt<Real>& vectors, ProgressMonitor& progress) {
    for (std::uint32_t i = 0; i < count; ++i) {
        if (i % kDrawsBetweenPolls == 0 && stop_requested(progress)) return target.covered;
        if (i + kPrefetchAhead < count) prefetch_object(draws[i + kPrefetchAhead]);
        if (plan.reads_corners && i + kCornersAhead < count) prefetch_corners(*draws[i + kCornersAhead]);
        plan.kernel(*draws[i], target, vectors, plan.constants);
    }
    return target.covered;
}

template <typename Real>
void prepare_memory(const FillPlan<Real>& plan, int bands, std::size_t samples, FillMemory<Real>& memory) {
    assign_populated(memory.depth_buffer, plan.depth_test ? samples : 0, std::numeric_limits<Real>::infinity());
    memory.shaded.assign(bands, 0);
    memory.replaced.assign(bands, 0);
    memory.covered.assign(bands, 0);
    if (memory.band_vectors.size() < static_cast<std::size_t>(bands)) memory.band_vectors.resize(bands);
    if (plan.shade_visible_only && memory.band_layers.size() < static_cast<std::size_t>(bands)) {
        memory.band_layers.resize(bands);
    }
}

}  // namespace

template <typename Real>
FillPlan<Real> plan_fill(const Scene& scene, const RenderOptions& options, const EffectSet& effects,
                         const LightRig<Real>& rig, const KernelTexture* textures,
                         const std::vector<glm::vec3>* vertex_colors) {
    FillPlan<Real> plan;
    plan.constants.textures = textures;
    const std::vector<glm::vec3>& colors = vertex_colors != nullptr ? *vertex_colors : scene.mesh.colors;
    plan.constants.rig = &rig;
    plan.constants.uniform_color = !effects.varying_colors;
    plan.constants.color = colors.empty() ? Vec3<Real>(Real(1)) : Vec3<Real>(colors[0]);
    KernelChoice choice;
    choice.phong = scene.shader == Shader::phong;
    choice.flat = scene.shader == Shader::flat;
    choice.perspective = perspective_weights(scene, options);
    choice.specialized = options.specialize_effects;
    choice.per_sample_vectors = options.light_vectors == LightVectors::shaded_point;
    choice.uniform_color = plan.constants.uniform_color;
    choice.effects = effects;
    choice.textured = textures != nullptr;
    plan.kernel = pick_fill_kernel<Real>(choice);
    plan.tiny_kernel = pick_tiny_fill_kernel<Real>(choice);
    plan.seed_gouraud = scene.shader == Shader::gouraud && options.light_vectors == LightVectors::triangle_centroid;
    plan.effects = effects;
    plan.depth_test = options.visibility == Visibility::depth_buffer;
    plan.shade_visible_only = !plan.depth_test && overdraw_shades_visible_only(scene, options, effects);
    // A texture lookup per sample costs more than claiming the sample too,
    // in every shader (bench_texture_cost: Gouraud and flat interpolate (s, t)
    // and read four texels per sample, most of their per-sample work).
    if (textures != nullptr && options.overdraw == Overdraw::automatic) {
        plan.shade_visible_only = !plan.depth_test;
    }
    // Gouraud is left out: its kernel interpolates three equal corner colours
    // with weights that need not sum to exactly 1, so triangles can differ in
    // the last bit. Phong's unlit kernel and flat write the colour itself.
    const bool one_color = options.specialize_effects && scene.shader != Shader::gouraud && !effects.diffuse &&
                           !effects.specular && !effects.varying_colors;
    plan.order_free = one_color && !plan.depth_test && !plan.shade_visible_only && textures == nullptr;
    // Flat, Gouraud and Phong's unlit kernel go through fill_samples(), the
    // specialised ones only for Phong (the general kernel shades in batches).
    // Flat and Gouraud light per triangle or corner, in set-up or the vertex stage: lit or not, they may walk.
    plan.may_fill_in_mesh_order = !plan.depth_test && !plan.shade_visible_only && textures == nullptr &&
                                  (scene.shader != Shader::phong ||
                                   (!effects.diffuse && !effects.specular && options.specialize_effects));
    plan.reads_corners = textures != nullptr ||
                         (scene.shader == Shader::phong && (effects.normals || effects.varying_colors));
    return plan;
}

namespace {

/// Writes `colour` to `count` pixels four at a time (48 bytes from a local
/// pattern: three 16-byte stores), where std::fill of 12-byte elements stores
/// 8 + 4 bytes per pixel and reloads the colour each time, since the image
/// might alias it: 9% of a 512x512 frame of a small mesh at one thread.
void fill_pixels(glm::vec3* out, std::size_t count, glm::vec3 colour) {
    const glm::vec3 pattern[4] = {colour, colour, colour, colour};
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) std::memcpy(out + i, pattern, sizeof pattern);
    for (; i < count; ++i) out[i] = colour;
}

/// fill_in_mesh_order() with the mesh in two halves: each sample takes the
/// second half's colour where its rank there is higher (all of the second
/// half's triangles come after the first's in mesh order, so an equal key
/// is higher without ties), as one walk of the whole mesh would have written.
template <typename Real>
void merge_later_half(const FillMemory<Real>& memory, bool ties, Image& image) {
    const std::uint64_t* keys = memory.rank_keys.data();
    const std::uint64_t* later_keys = memory.later_rank_keys.data();
    const std::uint32_t* tie = ties ? memory.rank_ties.data() : nullptr;
    const std::uint32_t* later_tie = ties ? memory.later_rank_ties.data() : nullptr;
    const glm::vec3* later = memory.later_half.pixels.data();
    glm::vec3* pixels = image.pixels.data();
    constexpr std::size_t kMergeGrain = std::size_t(1) << 16;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, image.pixels.size(), kMergeGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const std::uint64_t key = later_keys[i];
            const bool later_wins =
                key != 0 && (key > keys[i] || (key == keys[i] && (tie == nullptr || later_tie[i] > tie[i])));
            if (later_wins) pixels[i] = later[i];
        }
    });
}

}  // namespace

template <typename Real>
void fill_bins(const Scene& scene, const RenderOptions& options, const FillPlan<Real>& plan, const Bins<Real>& bins,
               int rows, int columns, FillMemory<Real>& memory, Image& image, RenderStats& stats,
               ProgressMonitor& progress) {
    image.rows = rows;
    image.columns = columns;
    // Cleared band by band, in parallel, below: resizing writes only what a larger image adds.
    // A fresh image's whole 2 MiB pages on huge pages (Image is a public type: its vector keeps std::allocator).
    const std::size_t samples = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    const bool mapped = reserve_on_huge_pages(image.pixels, samples);
    resize_polling(image.pixels, samples, progress.poll_function(), !mapped);
    prepare_memory(plan, bins.bands, image.pixels.size(), memory);
    tbb::parallel_for(0, bins.bands, [&](int band) {
        if (progress.cancelled()) return;
        FillTarget<Real> target{image, memory.depth_buffer, band * kBandRows, std::min(rows, (band + 1) * kBandRows),
                                plan.depth_test, 0, 0};
        PendingPhongSamples<Real> pending;
        target.pending = &pending;
        const std::size_t band_start = static_cast<std::size_t>(target.row_begin) * static_cast<std::size_t>(columns);
        const std::size_t band_end = static_cast<std::size_t>(target.row_end) * static_cast<std::size_t>(columns);
        fill_pixels(image.pixels.data() + band_start, band_end - band_start, scene.image.background);
        LightVectorsAt<Real>& vectors = memory.band_vectors[band];
        memory.covered[band] =
            plan.shade_visible_only
                ? fill_nearest_first(plan, bins.band_draws(band), bins.band_size(band), target, vectors,
                                     memory.band_layers[band], progress)
                : fill_every_layer(plan, bins.band_draws(band), bins.band_size(band), target, vectors, progress);
        finish_pending(target);
        memory.shaded[band] = target.samples;
        memory.replaced[band] = target.replaced;
        progress.piece_done();
    });
    progress.throw_if_cancelled();
    std::uint64_t shaded = 0;
    for (int band = 0; band < bins.bands; ++band) {
        stats.samples_covered += memory.covered[band];
        stats.samples_shaded += memory.shaded[band];
        stats.nonfinite_values_replaced += memory.replaced[band];
        shaded += memory.shaded[band];
    }
    if (scene.shader == Shader::phong) {
        count_term_evaluations(scene, options, plan.effects, shaded, LitPoints::phong_samples, stats);
    }
}

namespace {
std::atomic<WalkChoice> walk_choice{WalkChoice::by_triangle_size};
std::atomic<std::uint64_t> mesh_order_fill_passes{0};
std::atomic<std::uint64_t> tiny_draws{0};
std::atomic<int> mesh_order_fill_walks{0};
}  // namespace

WalkChoice set_mesh_order_walk_choice(WalkChoice choice) { return walk_choice.exchange(choice); }

std::uint64_t passes_filled_in_mesh_order() { return mesh_order_fill_passes.load(std::memory_order_relaxed); }

std::uint64_t tiny_draws_filled() { return tiny_draws.load(std::memory_order_relaxed); }

int set_mesh_order_walks(int walks) { return mesh_order_fill_walks.exchange(walks); }

double sampled_samples_per_triangle(const std::vector<Triangle>& triangles, const FrameVector<ScreenVertex>& screen,
                                    int rows, int columns) {
    const std::size_t step = std::max<std::size_t>(1, triangles.size() / kTrianglesSampledForSize);
    const double image_area = double(rows) * double(columns);
    double area_sum = 0.0;
    std::size_t counted = 0;
    for (std::size_t t = 0; t < triangles.size(); t += step) {
        const ScreenVertex& a = screen[triangles[t][0]];
        const ScreenVertex& b = screen[triangles[t][1]];
        const ScreenVertex& c = screen[triangles[t][2]];
        // A corner not in front of the eye has NaN rows: left out, as a triangle off the image.
        if (!(std::isfinite(a.row) && std::isfinite(b.row) && std::isfinite(c.row) && std::isfinite(a.column) &&
              std::isfinite(b.column) && std::isfinite(c.column))) {
            continue;
        }
        const double top = std::min({a.row, b.row, c.row}), bottom = std::max({a.row, b.row, c.row});
        const double left = std::min({a.column, b.column, c.column}), right = std::max({a.column, b.column, c.column});
        if (!(bottom >= 0.0 && top <= rows && right >= 0.0 && left <= columns)) continue;
        const double area = 0.5 * std::abs((b.column - a.column) * (c.row - a.row) -
                                           (c.column - a.column) * (b.row - a.row));
        area_sum += std::isfinite(area) ? std::min(area, image_area) : image_area;
        ++counted;
    }
    return counted == 0 ? 0.0 : area_sum / double(counted);
}

template <typename Real>
bool fills_in_mesh_order(const FillPlan<Real>& plan, bool extra_outputs, double samples_per_triangle) {
    if (!plan.may_fill_in_mesh_order || extra_outputs) return false;
    switch (walk_choice.load(std::memory_order_relaxed)) {
    case WalkChoice::always: return true;
    case WalkChoice::never: return false;
    case WalkChoice::by_triangle_size: break;
    }
    if (samples_per_triangle > kWalkMaxSamplesPerTriangle) return false;
    // Lit walks gain at two only where the walk fills tiny triangles with no
    // set-up (TinyDraw: flat, exact Gouraud), ambient ones at two as well. The
    // seed's Gouraud, which fills them too but lights their corners in
    // batches, gains only where they are tinier still (kSeedWalkMaxSamplesPerTriangle).
    const int forced_walks = mesh_order_fill_walks.load(std::memory_order_relaxed);
    const int walks = forced_walks > 0 ? forced_walks : tbb::this_task_arena::max_concurrency();
    return walks == 1 || !(plan.effects.diffuse || plan.effects.specular) ||
           (plan.tiny_kernel != nullptr &&
            (!plan.seed_gouraud || samples_per_triangle <= kSeedWalkMaxSamplesPerTriangle));
}

template <typename Real>
void fill_in_mesh_order(const Scene& scene, const RenderOptions& options, const FillPlan<Real>& plan,
                        const SetupInput<Real>& setup, const std::uint32_t* original_triangle, int rows, int columns,
                        DrawList<Real>& draws, FillMemory<Real>& memory, Image& image, RenderStats& stats,
                        ProgressMonitor& progress) {
    mesh_order_fill_passes.fetch_add(1, std::memory_order_relaxed);
    image.rows = rows;
    image.columns = columns;
    const std::size_t samples = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    const bool mapped = reserve_on_huge_pages(image.pixels, samples);
    resize_polling(image.pixels, samples, progress.poll_function(), !mapped);
    const bool ranked = !plan.order_free;
    const std::size_t chunks = (scene.mesh.triangles.size() + kSetupChunk - 1) / kSetupChunk;
    // One walk per thread. Ranked, an even number of walks take the mesh in
    // two halves, each walk over its half's triangles that reach its rows
    // (rows in parts as the walks pair up), the second half's ranks and
    // colours apart, merged into the image after (merge_later_half()): each
    // walk screens and reads only its own triangles, where walks over rows
    // alone each screen all of them. (An odd number keeps rows alone, every
    // thread busy: measured only at two.)
    const int forced_walks = mesh_order_fill_walks.load(std::memory_order_relaxed);
    const int threads = forced_walks > 0 ? forced_walks : tbb::this_task_arena::max_concurrency();
    const std::size_t halves = ranked && threads % 2 == 0 && chunks >= 2 ? 2 : 1;
    const std::size_t first_half_chunks = (chunks + 1) / 2;
    RowSplit& split = draws.direct_split;
    split_rows_by_triangles(scene.mesh.triangles, setup.vertices.screen, rows,
                            std::max(1, threads / static_cast<int>(halves)), draws.direct_split_work, split);
    const std::size_t row_parts = static_cast<std::size_t>(split.parts());
    const std::size_t walks = row_parts * halves;
    if (ranked) {
        // Key 0 is no triangle's (farthest_first_key() gives it to a NaN
        // only): "no colour yet", so the ties need no clearing. Each walk
        // clears its rows' keys; the buffers are only mapped here.
        reserve_populated(memory.rank_keys, samples);
        memory.rank_keys.resize(samples);
        // The walk takes the triangles in mesh order, i.e. in the order of
        // their ties, unless the mesh is a reordered copy (mesh_order.hpp).
        if (original_triangle != nullptr && memory.rank_ties.size() < samples) memory.rank_ties.resize(samples);
        if (halves == 2) {
            reserve_populated(memory.later_rank_keys, samples);
            memory.later_rank_keys.resize(samples);
            if (original_triangle != nullptr && memory.later_rank_ties.size() < samples) {
                memory.later_rank_ties.resize(samples);
            }
            memory.later_half.rows = rows;
            memory.later_half.columns = columns;
            reserve_populated(memory.later_half.pixels, samples);
            memory.later_half.pixels.resize(samples);  // read only where a later key is set
        }
    }
    if (draws.direct_parts.size() < walks) draws.direct_parts.resize(walks);
    progress.begin_stage(0.1, 1.0, chunks * row_parts);
    tbb::parallel_for(std::size_t(0), walks, [&](std::size_t walk) {
        if (progress.cancelled()) return;
        const std::size_t part = walk % row_parts, half = walk / row_parts;
        const int row_begin = split.starts[part], row_end = split.starts[part + 1];
        const std::size_t first = static_cast<std::size_t>(row_begin) * static_cast<std::size_t>(columns);
        const std::size_t end = static_cast<std::size_t>(row_end) * static_cast<std::size_t>(columns);
        Image& written = half == 0 ? image : memory.later_half;
        if (half == 0) fill_pixels(image.pixels.data() + first, end - first, scene.image.background);
        FillTarget<Real> target{written, memory.depth_buffer, row_begin, row_end, false, 0, 0};
        if (ranked) {
            FrameVector<std::uint64_t>& keys = half == 0 ? memory.rank_keys : memory.later_rank_keys;
            std::fill(keys.begin() + static_cast<std::ptrdiff_t>(first), keys.begin() + static_cast<std::ptrdiff_t>(end),
                      std::uint64_t(0));
            target.rank_keys = keys.data();
            if (original_triangle != nullptr) {
                target.rank_ties = half == 0 ? memory.rank_ties.data() : memory.later_rank_ties.data();
            }
        }
        DirectFill<Real> fill;
        fill.kernel = plan.kernel;
        fill.tiny_kernel = plan.tiny_kernel;
        fill.constants = &plan.constants;
        fill.target = &target;
        DirectScratch<Real>& scratch = draws.direct_parts[walk];
        fill.vectors = &scratch.fill_vectors;
        fill.original_triangle = original_triangle;
        fill.ranked = ranked;
        fill.reads_varyings = !plan.constants.uniform_color;
        if (halves == 2) {
            fill.first_chunk = half == 0 ? 0 : first_half_chunks;
            fill.end_chunk = half == 0 ? first_half_chunks : chunks;
        }
        set_up_and_fill(setup, fill, split, static_cast<int>(part), scratch, progress);
        scratch.samples_covered = target.covered;
        scratch.samples_shaded = target.samples;
        scratch.values_replaced = target.replaced;
    });
    if (halves == 2 && !progress.cancelled()) {
        merge_later_half(memory, original_triangle != nullptr, image);
    }
    progress.throw_if_cancelled();
    std::uint64_t shaded = 0;
    for (std::size_t walk = 0; walk < walks; ++walk) {
        const DirectScratch<Real>& scratch = draws.direct_parts[walk];
        add_setup_counts(setup, scratch.counts, stats);
        // The rank test puts every drawn triangle in painter's order, as the sort would have.
        if (ranked) stats.triangles_sorted += scratch.counts.drawn;
        stats.samples_covered += scratch.samples_covered;
        stats.samples_shaded += scratch.samples_shaded;
        stats.nonfinite_values_replaced += scratch.values_replaced;
        shaded += scratch.samples_shaded;
        tiny_draws.fetch_add(scratch.tiny_draws, std::memory_order_relaxed);
    }
    if (scene.shader == Shader::phong) {
        count_term_evaluations(scene, options, plan.effects, shaded, LitPoints::phong_samples, stats);
    }
}

#define PHONGRAST_INSTANTIATE_FILL_DRIVER(Real)                                                              \
    template FillPlan<Real> plan_fill<Real>(const Scene&, const RenderOptions&, const EffectSet&,                \
                                            const LightRig<Real>&, const KernelTexture*,                     \
                                            const std::vector<glm::vec3>*);                                  \
    template void fill_bins<Real>(const Scene&, const RenderOptions&, const FillPlan<Real>&, const Bins<Real>&,  \
                                  int, int, FillMemory<Real>&, Image&, RenderStats&, ProgressMonitor&);    \
    template bool fills_in_mesh_order<Real>(const FillPlan<Real>&, bool, double);                                     \
    template void fill_in_mesh_order<Real>(const Scene&, const RenderOptions&, const FillPlan<Real>&,        \
                                           const SetupInput<Real>&, const std::uint32_t*, int, int,           \
                                           DrawList<Real>&, FillMemory<Real>&, Image&, RenderStats&,          \
                                           ProgressMonitor&);
PHONGRAST_INSTANTIATE_FILL_DRIVER(float)
PHONGRAST_INSTANTIATE_FILL_DRIVER(double)
#undef PHONGRAST_INSTANTIATE_FILL_DRIVER

}  // namespace phongrast::detail
