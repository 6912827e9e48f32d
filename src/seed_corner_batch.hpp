// Seed Gouraud's corners lit several triangles at a time (internal header).
//
// With the seed's light vectors (LightVectors::triangle_centroid) Gouraud
// lights each drawn triangle's three corners from vectors taken at its
// centroid: nine points of three lights per triangle, which one at a time,
// in scalar glm arithmetic, were a quarter of such a frame on a mesh of small
// triangles. Set-up instead leaves a whole triangle's `lit` for later and
// notes it here (the mesh-order walk notes tiny triangles it fills without
// set-up too: TinyDraw); light() then lights the corners of up to kSeedBatch
// triangles in vector loops (seed_corner_lanes.hpp, AVX2 where the CPU has it):
// the same operations in the same order as PointShader's, so the same bits.
#ifndef PHONGRAST_SRC_SEED_CORNER_BATCH_HPP
#define PHONGRAST_SRC_SEED_CORNER_BATCH_HPP

#include <cstddef>

#include "chunk_arena.hpp"
#include "fill_types.hpp"
#include "seed_corner_lanes.hpp"
#include "shade_lanes.hpp"

namespace phongrast::detail {

template <typename Real>
class SeedCornerBatch {
public:
    /// Whether `shader` can light batches: specialised, and few enough lights
    /// for the lanes' vectors on the stack. (One shader for every triangle:
    /// the caller does not batch meshes of several materials.)
    static bool can_light(const PointShader<Real>& shader) {
        return shader.specialized && shader.rig->active_lights.size() <= kMaxLaneLights;
    }

    /// Notes a whole triangle whose corners (in its draw's order) are to be
    /// lit with the vectors at `centroid` (camera space): draw `draw` of the
    /// `out` given to light(), or kNoDraw for the caller's own use of lit().
    /// Returns its slot; the batch is full() after kSeedBatch of them.
    std::size_t add(const Varyings<Real>* const (&corners)[3], const Vec3<Real>& centroid, std::size_t draw) {
        PendingSeedTriangle<Real>& pending = pending_[count_];
        for (int i = 0; i < 3; ++i) pending.corner[i] = corners[i];
        pending.centroid = centroid;
        draws_[count_] = draw;
        return count_++;
    }
    bool full() const { return count_ == kSeedBatch; }

    /// Lights the noted triangles' corners into their draws' `lit` (or
    /// lit()), and forgets them.
    void light(const PointShader<Real>& shader, ChunkVector<FillTriangle<Real>>& out) {
        if (count_ == 0) return;
        Vec3<Real>* into[kSeedBatch];
        for (std::size_t p = 0; p < count_; ++p) into[p] = draws_[p] == kNoDraw ? lit_[p] : out[draws_[p]].lit;
        light_seed_corners_dispatched(shader, pending_, count_, into);
        count_ = 0;
    }

    /// The lit corners of slot `slot` (add() with kNoDraw), from light() until the next add().
    const Vec3<Real>* lit(std::size_t slot) const { return lit_[slot]; }

    static constexpr std::size_t kNoDraw = ~std::size_t(0);

private:
    PendingSeedTriangle<Real> pending_[kSeedBatch];
    std::size_t draws_[kSeedBatch];
    Vec3<Real> lit_[kSeedBatch][3];
    std::size_t count_ = 0;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SEED_CORNER_BATCH_HPP
