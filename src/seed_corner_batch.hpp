// Seed Gouraud's corners lit several triangles at a time (internal header).
//
// With the seed's light vectors (LightVectors::triangle_centroid) Gouraud
// lights each drawn triangle's three corners from vectors taken at its
// centroid: nine points of three lights per triangle, which one at a time,
// in scalar glm arithmetic, were a quarter of such a frame on a mesh of small
// triangles. Set-up instead leaves a whole triangle's `lit` for later and
// notes it here; light() then lights the corners of up to kSeedBatch
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

    /// Notes that draw `draw` of `out` (a whole triangle, centroid in camera
    /// space) needs its corners lit; true when the batch is full and must be lit.
    bool add(std::size_t draw, const Vec3<Real>& centroid) {
        pending_[count_] = {draw, centroid};
        return ++count_ == kSeedBatch;
    }

    /// Lights the noted draws' corners into their `lit`, and forgets them.
    void light(const PointShader<Real>& shader, ChunkVector<FillTriangle<Real>>& out) {
        if (count_ == 0) return;
        light_seed_corners_dispatched(shader, pending_, count_, out);
        count_ = 0;
    }

private:
    PendingSeedTriangle<Real> pending_[kSeedBatch];
    std::size_t count_ = 0;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SEED_CORNER_BATCH_HPP
