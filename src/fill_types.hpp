// What the fill kernels and the pipeline share (internal header): the set-up
// triangle, the rows a task fills, the per-render constants and the kernel
// signature. What chooses a kernel is in fill_dispatch.hpp.
//
// Kept apart from fill_kernels.hpp, which is compiled once per instruction
// set (see fill_kernels_avx2.hpp): every kernel, whatever its instruction
// set, takes these types.
#ifndef PHONGRAST_SRC_FILL_TYPES_HPP
#define PHONGRAST_SRC_FILL_TYPES_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "phongrast/image.hpp"
#include "phongrast/texture.hpp"
#include "raster.hpp"
#include "shading.hpp"
#include "varyings.hpp"

namespace phongrast::detail {

/// Rows of samples per band: the unit of work of the fill (binning.hpp).
constexpr int kBandRows = 16;

/// One triangle ready to fill. The varyings are not copied: they stay in the
/// mesh's vertex array (or, for the corners clipping creates, in the draw
/// list's own storage), and the triangle points to them.
///
/// The renderer keeps one per drawn piece of every triangle until the frame
/// is filled, so on a large mesh its size is most of the memory per triangle:
/// 120 bytes in float on 64-bit targets (fields ordered so that no byte is
/// padding: the material index took the last 4). To keep it there, the coverage stores no area (the fill
/// recomputes it exactly) and Phong's centroid shares the lit colours' place.
template <typename Real>
struct FillTriangle {
    SnappedTriangle coverage;
    Real depth[3];                ///< z_c of the corners
    std::uint32_t source;         ///< index of the mesh triangle it comes from (the id output)
    /// Its material: an index into FillConstants::rig (0 in a scene of one
    /// material). It fills what was padding: the size does not change.
    std::uint32_t surface;
    /// Gouraud: the lit corner colours; flat: the triangle's colour, thrice;
    /// Phong, which reads no lit colour: centroid() in lit[0].
    Vec3<Real> lit[3];
    const Varyings<Real>* v[3];  ///< in coverage order

    /// Phong only: the source triangle's centroid in camera space, where the
    /// seed's light vectors are computed (zero when they are not used).
    const Vec3<Real>& centroid() const { return lit[0]; }
    void set_centroid(const Vec3<Real>& centroid) { lit[0] = centroid; }
};
static_assert(sizeof(void*) != 8 || sizeof(FillTriangle<float>) <= 120,
              "FillTriangle is most of the memory per triangle on large meshes: keep it at 120 bytes");

template <typename Real>
struct PendingPhongSamples;

/// The rows of the image (in samples) one task fills, and what it counts.
template <typename Real>
struct FillTarget {
    Image& image;
    std::vector<Real>& depth_buffer;
    int row_begin, row_end;
    bool depth_test;
    std::uint64_t samples;   ///< samples shaded and written
    std::uint64_t replaced;  ///< non-finite channels replaced by 0
    std::uint64_t covered = 0;  ///< samples inside the triangles filled, shaded or not
    /// Overdraw::shade_visible: the draws come nearest first (painter's order
    /// reversed), and for each sample of rows [row_begin, row_end) (row-major,
    /// image.columns wide) this holds the number of the draw that claimed it,
    /// or kNoOwner where none has yet. A kernel claims such a sample (writes
    /// `self` there) and shades it, and skips the others: a draw painter's
    /// order paints later has them. Null: shade every covered sample.
    std::uint32_t* owner = nullptr;
    std::uint32_t self = 0;
    /// Painter's order by a test per sample instead of a sort (the fill in
    /// mesh order, set_up_and_fill()): per sample of the image, the painter's
    /// rank of the triangle whose colour it holds, `rank_keys` its key
    /// (0: none yet, no triangle's key is 0) and `rank_ties` its tie-break;
    /// the draw being filled writes a sample only when its own rank (`key`,
    /// then `tie`) is higher, i.e. when painter's order draws it later.
    /// `rank_ties` null: the draws come in the order of their ties (the
    /// mesh's), so an equal key wins. `rank_keys` null: the draws come in
    /// painter's order, each writes every sample it shades.
    std::uint64_t* rank_keys = nullptr;
    std::uint32_t* rank_ties = nullptr;
    std::uint64_t key = 0;
    std::uint32_t tie = 0;
    /// Where Phong's kernels with per-sample light vectors gather the samples
    /// of several triangles for one batch of shading (PendingPhongSamples);
    /// the driver that sets it calls finish_pending() after the band's last
    /// triangle. Null: each triangle's samples are shaded and written by its
    /// own kernel call.
    PendingPhongSamples<Real>* pending = nullptr;
};

/// No triangle covers the sample (Overdraw::shade_visible's owner buffer).
constexpr std::uint32_t kNoOwner = 0xffffffffu;

/// The owner row of `row` when the target shades only the samples it claims, else null.
template <typename Real>
std::uint32_t* owner_row(const FillTarget<Real>& target, int row) {
    if (target.owner == nullptr) return nullptr;
    return target.owner + static_cast<std::size_t>(row - target.row_begin) * static_cast<std::size_t>(target.image.columns);
}

/// Whether draw `self` shades sample k of an owner row (owner_row(), not
/// null): when no nearer draw has claimed it, in which case it claims it.
inline bool claims_sample(std::uint32_t* owners, int k, std::uint32_t self) {
    if (owners[k] != kNoOwner) return false;
    owners[k] = self;
    return true;
}

/// Claims the span's `count` samples no draw has claimed yet for `self`
/// (owners starts at the span's first sample) and returns how many it
/// claimed. One pass without branches, so that it vectorises.
inline int claim_span(std::uint32_t* owners, int count, std::uint32_t self) {
    int claimed = 0;
    for (int k = 0; k < count; ++k) {
        const bool free = owners[k] == kNoOwner;
        owners[k] = free ? self : owners[k];
        claimed += int(free);
    }
    return claimed;
}

/// A material's texture as the kernels read it (a view of its TextureImage).
struct KernelTexture {
    const glm::vec3* texels = nullptr;  ///< rows * columns, row 0 the top row; null: T = 1
    int rows = 0, columns = 0;
    TextureWrap wrap_s = TextureWrap::repeat, wrap_t = TextureWrap::repeat;
    TextureFilter filter = TextureFilter::bilinear;
    /// Trilinear only: levels 1, 2, ... of the image's pyramid (TextureImage::mip_levels()).
    const MipLevel* mip_levels = nullptr;
    int mip_level_count = 0;
    /// Trilinear only: whether the fill's weights are perspective-correct,
    /// which decides how (s, t)'s derivatives follow from them.
    bool perspective = true;
    /// Trilinear only: one sample's footprint in steps of this pass's sample
    /// grid (1 for one sample per pixel and the ordered grid; 1 / s for each
    /// of the rotated grid's passes at pixel spacing).
    double footprint_scale = 1.0;
};

/// Per-render constants the kernels read.
template <typename Real>
struct FillConstants {
    /// One rig per material of the scene (one for a version-1 scene), indexed by FillTriangle::surface.
    const LightRig<Real>* rig = nullptr;
    bool uniform_color = true;
    Vec3<Real> color{Real(1)};  ///< the colour of every vertex when uniform_color
    /// Textured scenes only (the textured kernels): per material, indexed by
    /// FillTriangle::surface; (s, t) are in each vertex's `lit`.
    const KernelTexture* textures = nullptr;

    const LightRig<Real>& rig_of(const FillTriangle<Real>& draw) const { return rig[draw.surface]; }
};

/// Samples of consecutive triangles of one band, waiting to be shaded
/// together: a 12k-triangle mesh at 256x256 has two or three visible samples
/// per triangle, and a batch per triangle would shade a whole vector of
/// lanes for them (most lanes wasted, and the batch's set-up paid per
/// triangle). Each sample's interpolated attributes are computed from its
/// own triangle's corners when it joins; the lighting of the batch, lane by
/// lane the same operations as a batch of one triangle's, runs when it is
/// full, when the next triangle has another material, or when the band ends.
/// Writes keep the order of the samples' triangles, so a later triangle's
/// sample still lands after an earlier one's.
inline constexpr int kPendingSamples = 32;
template <typename Real>
struct PendingPhongSamples {
    alignas(64) Real color[3][kPendingSamples];  ///< unused with one colour (FillConstants::uniform_color)
    alignas(64) Real normal[3][kPendingSamples];
    alignas(64) Real point[3][kPendingSamples];  ///< camera space
    alignas(64) Real depth[kPendingSamples];
    std::size_t index[kPendingSamples];  ///< into the image
    int count = 0;
    std::uint32_t surface = 0;  ///< the material of every sample waiting
    const FillConstants<Real>* constants = nullptr;
    const LightVectorsAt<Real>* vectors = nullptr;  ///< the band's (read only with per-triangle vectors)
    /// Shades the samples waiting and writes them (compiled with the kernel that gathered them).
    void (*shade_and_write)(PendingPhongSamples&, FillTarget<Real>&) = nullptr;
};

/// Shades and writes whatever samples wait in `target`'s PendingPhongSamples.
template <typename Real>
void finish_pending(FillTarget<Real>& target) {
    PendingPhongSamples<Real>* pending = target.pending;
    if (pending != nullptr && pending->count > 0) pending->shade_and_write(*pending, target);
}

template <typename Real>
using FillKernel = void (*)(const FillTriangle<Real>&, FillTarget<Real>&, LightVectorsAt<Real>&,
                            const FillConstants<Real>&);

/// What the coverage screen (coverage_screen.hpp) found of a whole triangle
/// whose bounding box holds at most 2 x 2 sample centres, some of them
/// covered: all the fill needs of its coverage, so the walk fills it with no
/// set-up of its own (TinyFillKernel). The corners are in coverage order
/// (SnappedTriangle: 0, then 1 and 2 exchanged when `swapped`), and every
/// value is an integer below 2^53, so the doubles hold the fill's int64 values exactly.
struct TinyCoverage {
    double e[3];            ///< edge values opposite each corner at the box's first centre, unbiased (CoveredSpan::e)
    double column_step[3];  ///< their change per column (CoveredRows::step())
    double row_step[3];     ///< and per row
    double area2;           ///< SnappedTriangle::area2(), > 0
    int column_min, row_min;  ///< the box's first centre (clamped to the image)
    unsigned covered;       ///< bit 2 r + c set where centre (row_min + r, column_min + c) is covered
    bool swapped;           ///< corners 1 and 2 were exchanged
};

/// A tiny triangle to fill: its coverage and, in coverage order, what the
/// kernel interpolates at its corners (Gouraud: the lit colours; Phong
/// ambient only: the vertex colours; flat: the triangle's colour, at corner 0)
/// and their depths z_c.
template <typename Real>
struct TinyDraw {
    TinyCoverage coverage;
    const Vec3<Real>* corner[3];
    Real depth[3];
    std::uint32_t surface;  ///< FillTriangle::surface
};

/// Fills a TinyDraw as the render's FillKernel fills the FillTriangle set-up
/// would make of the same triangle: the same samples, bits and counts.
template <typename Real>
using TinyFillKernel = void (*)(const TinyDraw<Real>&, FillTarget<Real>&, const FillConstants<Real>&);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_TYPES_HPP
