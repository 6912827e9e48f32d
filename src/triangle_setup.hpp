// Triangle set-up (internal header): each triangle, in mesh order,
// culled, dropped (seed border rule) or clipped, snapped to fixed point and
// turned into the FillTriangles the fill reads, with flat and seed-Gouraud
// lighting done here once per triangle.
#ifndef PHONGRAST_SRC_TRIANGLE_SETUP_HPP
#define PHONGRAST_SRC_TRIANGLE_SETUP_HPP

#include <cstdint>
#include <memory>
#include <vector>

#include "chunk_arena.hpp"
#include "closed_mesh.hpp"
#include "draw_span.hpp"
#include "fill_types.hpp"
#include "record_pages.hpp"
#include "vertex_stage.hpp"

namespace phongrast::detail {

/// Corners created by clipping, which fill triangles point to: stored in
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

/// What set-up did with the triangles of one chunk: each triangle lands in
/// exactly one of culled, dropped, outside, out_of_range, between_samples,
/// degenerate and drawn; clipped counts those of them that were clipped.
struct SetupCounts {
    std::uint64_t culled = 0, dropped = 0, clipped = 0, outside = 0, out_of_range = 0, between_samples = 0,
                  degenerate = 0, drawn = 0;
    std::uint64_t lit_points = 0;  ///< flat triangles or Gouraud corners lit during set-up
};

/// The image's rows split among several walks of the mesh, one per thread:
/// part p fills rows [starts[p], starts[p + 1]) (split_rows_by_triangles()). Each walk sets up only the
/// triangles that may reach its rows, and each triangle is counted by
/// exactly one walk, its owner's (the part of its first corner's row), so the
/// counts are those of one walk over the whole image.
struct RowSplit {
    std::vector<int> starts{0, 0};  ///< parts() + 1 ascending rows: 0 first, the image's rows last

    int parts() const { return static_cast<int>(starts.size()) - 1; }
    /// The part that counts a triangle whose first corner lies at `row`: the
    /// part holding the row, the nearest one outside the image, the first for NaN.
    int owner(double row) const {
        int part = 0;
        while (part + 1 < parts() && row >= starts[static_cast<std::size_t>(part) + 1]) ++part;
        return part;
    }
};

/// set_up_and_fill()'s scratch for one walk of the mesh, written for every
/// triangle (the draws' end, the clipped corners' count, the counts): aligned
/// to a cache line so that two walks on two threads never write one line.
template <typename Real>
struct alignas(64) DirectScratch {
    ChunkVector<FillTriangle<Real>> draws;  ///< the draws of the one triangle being filled
    ClipVertexStore<Real> clip_vertices;   ///< its clipped corners
    LightVectorsAt<Real> vectors;          ///< set-up's light vectors (flat, seed Gouraud)
    LightVectorsAt<Real> fill_vectors;     ///< the fill kernel's
    SetupCounts counts;                    ///< the triangles this walk owns (RowSplit::owner)
    std::uint64_t samples_covered = 0, samples_shaded = 0, values_replaced = 0;  ///< its FillTarget's counts
    std::uint64_t tiny_draws = 0;  ///< triangles filled from the coverage screen's TinyDraw (no set-up)
};

/// Set-up's output, in mesh order: chunk after chunk of kSetupChunk mesh
/// triangles (fewer for a small mesh on several threads: set_up_triangles()),
/// each chunk's draws in mesh order, and for each triangle that draws
/// something its painter's-order key and where its draws are. Where the
/// chunks start changes no draw, key or count, nor their order.
/// Kept from frame to frame. A small frame's chunk vectors live in `arena`
/// (chunk_arena.hpp: huge pages), a large frame's on the heap.
template <typename Real>
struct DrawList {
    std::size_t chunks = 0;  ///< chunks of this frame (the vectors may hold more from earlier frames)
    ChunkArena arena;        ///< before the vectors: they give their slots back before it goes
    std::vector<ChunkVector<FillTriangle<Real>>> chunk_draws;
    std::vector<ChunkVector<DrawSpan>> chunk_drawn;
    std::vector<ChunkVector<std::uint64_t>> chunk_keys;  ///< farthest_first_key() of each drawn triangle's mean z_c
    std::vector<ClipVertexStore<Real>> chunk_clip_vertices;
    std::vector<SetupCounts> chunk_counts;
    std::vector<LightVectorsAt<Real>> chunk_vectors;  ///< per chunk, not per thread (see light_vertices())
    std::vector<MappedRecords> chunk_mapped;  ///< chunk_draws' pages mapped so far (record_pages.hpp)
    /// set_up_and_fill(): per walk (RowSplit part), the draws of the one
    /// triangle being filled (at most 6 pieces), its clipped corners and light vectors.
    std::vector<DirectScratch<Real>> direct_parts;
    RowSplit direct_split;                    ///< the walks' rows
    std::vector<double> direct_split_work;  ///< split_rows_by_triangles()'s scratch
};

/// Everything set-up reads.
template <typename Real>
struct SetupInput {
    const Scene& scene;
    const RenderOptions& options;
    const View& view;
    const TransformedVertices<Real>& vertices;
    HiddenBackFaces cull;             ///< back_faces_to_cull()
    const PointShader<Real>& shader;  ///< lights flat centroids and seed-Gouraud corners
    const FillConstants<Real>& fill_constants;  ///< the uniform surface colour, when there is one
    /// A scene of several materials: each triangle's material, and one shader
    /// per material (same effects, its own rig). Null: `shader` for every triangle.
    const std::uint32_t* triangle_surfaces = nullptr;
    const PointShader<Real>* surface_shaders = nullptr;
    /// A textured scene drawn flat or Gouraud: per material, its texture (null
    /// otherwise), and the shaders of the colour-carrying part A (ks = 0) and
    /// of the specular part S (ka = kd = 0). A textured face's flat draw
    /// carries A in lit[0] and S in lit[1]; its Gouraud draw carries A at each
    /// corner in lit[i] and S in its corners' `color` ((s, t) in their `lit`).
    const KernelTexture* textures = nullptr;
    const PointShader<Real>* colour_part_shaders = nullptr;
    const PointShader<Real>* specular_part_shaders = nullptr;
    /// Textured Gouraud with exact vectors: per vertex, A (or the whole lit
    /// colour on a face without texture) from light_vertices_in_parts().
    const Vec3<Real>* vertex_colour_parts = nullptr;
};

/// Sets up every triangle of the mesh, in mesh order, into `draws` and adds
/// the triangle counts and the lighting done to `stats`. Set-up does not
/// depend on the order of triangles, so it walks the vertex arrays in the
/// order the mesh lists them (far fewer cache misses than painter's order)
/// and leaves the ordering to painter_order(), which then sorts only the
/// triangles that draw something. Reports progress, and stops early when
/// the render is cancelled.
template <typename Real>
void set_up_triangles(const SetupInput<Real>& input, DrawList<Real>& draws, RenderStats& stats,
                      ProgressMonitor& progress);

/// What set_up_and_fill() does with each triangle's draws: fills them into
/// `target` (the rows of its part of the image) with `kernel`. `ranked`: the
/// picture depends on painter's order, so each draw carries its triangle's
/// rank (its painter's key, then its index in the caller's mesh:
/// `original_triangle`, or the index itself when null) and the target keeps,
/// per sample, the rank of the colour written there (FillTarget::rank_keys);
/// else (FillPlan::order_free) every draw writes what it covers.
template <typename Real>
struct DirectFill {
    FillKernel<Real> kernel = nullptr;
    /// Fills the triangles the coverage screen found tiny and covering
    /// (TinyDraw) without setting them up; null: they are set up as any.
    TinyFillKernel<Real> tiny_kernel = nullptr;
    const FillConstants<Real>* constants = nullptr;
    FillTarget<Real>* target = nullptr;
    LightVectorsAt<Real>* vectors = nullptr;
    const std::uint32_t* original_triangle = nullptr;
    bool ranked = true;
    bool reads_varyings = true;  ///< set-up or the kernel reads the corners' varyings (colours vary)
    /// The walk's share of the mesh: its chunks [first_chunk, end_chunk) of
    /// kSetupChunk triangles (clamped to the mesh's).
    std::size_t first_chunk = 0, end_chunk = SIZE_MAX;
};

/// Splits `rows` rows into at most `parts` parts of about equal work, so
/// that the walks end together: the work of a sample of up to 4,096
/// triangles, each a set-up at its first corner's row and its area over the
/// rows it spans. Every part has at least one row. `work` is scratch: with
/// `split`, kept from frame to frame (no allocation per frame).
void split_rows_by_triangles(const std::vector<Triangle>& triangles, const FrameVector<ScreenVertex>& screen,
                             int rows, int parts, std::vector<double>& work, RowSplit& split);

/// Set-up and fill in one walk of the mesh (of fill's chunks of it), on the
/// calling thread, for the rows of part `part` of `split` (fill.target's rows): each triangle that
/// may reach them set up as set_up_triangles() sets it up, its draws filled
/// at once and forgotten, so no draw record reaches memory and nothing is
/// sorted or binned (painter's order is the rank test of `fill`). Sets
/// scratch.counts to the triangles this part owns (RowSplit::owner; the
/// fill's counts are in `fill`'s target). Reports progress in pieces of
/// kSetupChunk triangles, and stops early when the render is cancelled.
template <typename Real>
void set_up_and_fill(const SetupInput<Real>& input, const DirectFill<Real>& fill, const RowSplit& split, int part,
                     DirectScratch<Real>& scratch, ProgressMonitor& progress);

/// Adds what set-up counted (a chunk's, or a walk's scratch.counts) to `stats`: the
/// triangles and the lighting done.
template <typename Real>
void add_setup_counts(const SetupInput<Real>& input, const SetupCounts& counts, RenderStats& stats);

/// Sets up mesh triangle `source`: appends its fill triangles (none, one, or
/// one per piece of its clipped polygon) to `out` and counts it in `counts`.
template <typename Real>
void set_up_triangle(const SetupInput<Real>& input, std::uint32_t source, ChunkVector<FillTriangle<Real>>& out,
                     ClipVertexStore<Real>& clip_vertices, SetupCounts& counts, LightVectorsAt<Real>& vectors);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_TRIANGLE_SETUP_HPP
