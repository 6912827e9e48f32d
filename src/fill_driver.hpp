// The fill driver (internal header): picks the fill kernel for the scene and
// runs it over the bins, one band of rows per task, with painter's order's
// overdraw strategy (shade every layer, or only the visible one).
#ifndef PHONGRAST_SRC_FILL_DRIVER_HPP
#define PHONGRAST_SRC_FILL_DRIVER_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "binning.hpp"
#include "fill_types.hpp"
#include "triangle_setup.hpp"
#include "huge_page_pool.hpp"
#include "phongrast/image.hpp"
#include "phongrast/render.hpp"
#include "progress_monitor.hpp"

namespace phongrast::detail {

/// Overdraw::shade_visible's scratch for one band of rows.
struct VisibleLayer {
    /// Per sample of the band: the draw that claimed it (the last painter's
    /// order draws there), or kNoOwner (FillTarget::owner; huge pages).
    FrameVector<std::uint32_t> owner;
};

/// The fill's scratch, kept from frame to frame; per band, not per thread
/// (see light_vertices()).
template <typename Real>
struct FillMemory {
    std::vector<Real> depth_buffer;  ///< Visibility::depth_buffer only: z_c per sample
    std::vector<std::uint64_t> shaded, replaced, covered;  ///< per band
    std::vector<LightVectorsAt<Real>> band_vectors;
    std::vector<VisibleLayer> band_layers;
    /// fill_in_mesh_order(): per sample, the painter's rank of its colour (FillTarget::rank_keys).
    FrameVector<std::uint64_t> rank_keys;
    FrameVector<std::uint32_t> rank_ties;
    /// The same for the walks of the mesh's second half, and the colours they
    /// wrote, merged into the image after the walks (fill_in_mesh_order()).
    FrameVector<std::uint64_t> later_rank_keys;
    FrameVector<std::uint32_t> later_rank_ties;
    Image later_half;
};

/// How this render fills: the kernel, its constants and the strategy.
template <typename Real>
struct FillPlan {
    FillKernel<Real> kernel = nullptr;
    /// The kernel's TinyDraw twin (pick_tiny_fill_kernel()), for the fill in mesh order; may be null.
    TinyFillKernel<Real> tiny_kernel = nullptr;
    /// Gouraud with the seed's light vectors (corners lit per triangle, in
    /// batches): walks at one thread only (fills_in_mesh_order()).
    bool seed_gouraud = false;
    FillConstants<Real> constants;
    bool depth_test = false;         ///< Visibility::depth_buffer
    bool shade_visible_only = false; ///< Overdraw::shade_visible in effect
    /// Every covered sample gets one and the same colour (a uniform colour,
    /// no diffuse or specular term, a kernel that writes it as it is), and
    /// nothing but the image depends on which triangle wrote it last: the
    /// order of the triangles cannot change the picture, so it is not sorted.
    bool order_free = false;
    /// The kernel reads the corners' varyings through FillTriangle::v (Phong's
    /// colours or normals, textures' (s, t)): the fill prefetches them.
    bool reads_corners = false;
    EffectSet effects;               ///< what the kernel evaluates (for the term counts)
    /// The kernel goes through fill_samples() (FillTarget::rank_keys), every
    /// layer shaded, no depth buffer, no texture, and nothing lit per sample
    /// (flat and Gouraud, whose light is per triangle or corner; Phong
    /// ambient only): fill_in_mesh_order() may paint this picture, when
    /// nothing else asks for painter's order.
    bool may_fill_in_mesh_order = false;
};

/// Chooses the kernel and strategy for the scene, its effects and the options.
/// `textures`: per material, for a scene with texture maps (the textured
/// kernels; the order of triangles always matters then); null otherwise.
/// `colors`: the vertices' colours when not the scene mesh's (CallerVertices).
template <typename Real>
FillPlan<Real> plan_fill(const Scene& scene, const RenderOptions& options, const EffectSet& effects,
                         const LightRig<Real>& rig, const KernelTexture* textures = nullptr,
                         const std::vector<glm::vec3>* colors = nullptr);

/// Fills `image` (resized to rows x columns samples and cleared to the
/// background) from the bins; adds the samples covered and shaded, the
/// values replaced and, for Phong, the lighting done to `stats`. One band is
/// one piece of `progress`'s current stage; a cancelled render stops early.
template <typename Real>
void fill_bins(const Scene& scene, const RenderOptions& options, const FillPlan<Real>& plan, const Bins<Real>& bins,
               int rows, int columns, FillMemory<Real>& memory, Image& image, RenderStats& stats,
               ProgressMonitor& progress);

/// The walk's extra cost is per sample (a rank read and compared for each
/// sample shaded), its saving per triangle (no record, sort or bins): it
/// pays on meshes of small triangles only. `bench_speed_once
/// --walk-against-sorted` (docs/performance.md, "The fill in mesh order"):
/// walk / sorted at one thread 0.82-0.99 (seed Gouraud 0.92-1.08) at
/// 1.3-3.9 samples per drawn triangle, 0.99-1.40 at 20-226.
constexpr double kWalkMaxSamplesPerTriangle = 8.0;

/// Lit seed Gouraud, which fills tiny triangles too but lights their corners
/// in batches, walks at two threads or more only on triangles this small:
/// walks over the mesh's halves / sorted at 2 threads (`--walk-against-sorted
/// --walk always`, b9c4968): 1.3M [1.3 samples per drawn triangle] 0.76, 8M
/// 0.78, armadillo 0.98, bunny [3.9] 0.96, 125k [3.2] 1.02-1.09.
constexpr double kSeedWalkMaxSamplesPerTriangle = 2.0;

/// sampled_samples_per_triangle() reads every size()/kTrianglesSampledForSize-th
/// triangle: 1,024 to 2,047 of them, or all of a smaller mesh. It runs on one
/// thread before anything else can start, so the sample is kept small: 4,096
/// cost spot and the teapot (5.8k and 6.3k triangles, all of them read)
/// 0.03-0.05 ms of their 1.6-2.3 ms 512² frames; 1,024 cost 0.01 (in-process
/// A/B, Gouraud: frames 0.98-0.99 at 1 and 2 threads; the same choice of walk
/// in 96 cases: 8 speed scenes x 3 shaders x ambient or full x exact or seed).
constexpr std::size_t kTrianglesSampledForSize = 1024;

/// The mean area in samples of the sampled triangles (above) that lie at
/// least partly on the image, each counted at most as the image's area; 0
/// when none does.
double sampled_samples_per_triangle(const std::vector<Triangle>& triangles, const FrameVector<ScreenVertex>& screen,
                                    int rows, int columns);

/// Whether this pass fills in mesh order: the plan allows it, no extra
/// output names the last triangle, its triangles are small (mean area
/// `samples_per_triangle`, at most kWalkMaxSamplesPerTriangle), and it is
/// ambient only, fills tiny triangles from the coverage screen (flat, exact
/// Gouraud: FillPlan::tiny_kernel; the seed's Gouraud only on triangles of
/// at most kSeedWalkMaxSamplesPerTriangle) or fills in one walk (one thread).
template <typename Real>
bool fills_in_mesh_order(const FillPlan<Real>& plan, bool extra_outputs, double samples_per_triangle);

/// For tests and benchmarks: when fills_in_mesh_order() says yes.
enum class WalkChoice {
    by_triangle_size,  ///< the default: the plan allows it and the triangles are small
    always,            ///< whenever the plan allows it, whatever the triangles' size
    never,             ///< never: every pass is set up, sorted and binned
};
/// Sets the choice; returns the previous one.
WalkChoice set_mesh_order_walk_choice(WalkChoice choice);
/// For tests: the passes filled in mesh order since the process started.
std::uint64_t passes_filled_in_mesh_order();
/// For tests: the triangles those passes filled from the coverage screen's
/// TinyDraw, with no set-up (DirectFill::tiny_kernel), since the process started.
std::uint64_t tiny_draws_filled();
/// For tests: the walks fill_in_mesh_order() splits the rows into (at most:
/// each keeps a row), whatever the threads; 0 (the default) means one per
/// thread. Returns the previous setting.
int set_mesh_order_walks(int walks);

/// When fills_in_mesh_order() says so: set-up and fill in walks of the
/// mesh, one per thread, each over its own rows of the image
/// (set_up_and_fill(), RowSplit), painter's order kept by a rank test per
/// sample instead of a sort, into `image` resized and cleared as fill_bins()
/// does; adds what set-up and fill_bins() add to `stats`, the same counts.
/// The image is the one painter's fill paints, bit for bit.
template <typename Real>
void fill_in_mesh_order(const Scene& scene, const RenderOptions& options, const FillPlan<Real>& plan,
                        const SetupInput<Real>& setup, const std::uint32_t* original_triangle, int rows, int columns,
                        DrawList<Real>& draws, FillMemory<Real>& memory, Image& image, RenderStats& stats,
                        ProgressMonitor& progress);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_DRIVER_HPP
