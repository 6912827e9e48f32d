// Seed Gouraud's corners lit several triangles at a time (internal header).
//
// With the seed's light vectors (LightVectors::triangle_centroid) Gouraud
// lights each drawn triangle's three corners from vectors taken at its
// centroid: nine points of three lights per triangle, which one at a time,
// in scalar glm arithmetic, were a quarter of such a frame on a mesh of small
// triangles. Set-up instead leaves a whole triangle's `lit` for later and
// notes it here; light() then lights the corners of up to kSeedBatch
// triangles in vector loops (light_vectors_lanes(), shade_with_lanes()):
// the same operations in the same order as PointShader's, so the same bits.
#ifndef PHONGRAST_SRC_SEED_CORNER_BATCH_HPP
#define PHONGRAST_SRC_SEED_CORNER_BATCH_HPP

#include <cstddef>
#include <cstring>

#include "chunk_arena.hpp"
#include "fill_types.hpp"
#include "shade_lanes.hpp"

namespace phongrast::detail {

/// Triangles whose corners are lit together.
constexpr std::size_t kSeedBatch = 16;

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
        // Lane i * kSeedBatch + p: corner i of pending triangle p (blocks of
        // corners: a triangle's vectors are copied to its corners a block at a time).
        constexpr std::size_t N = 3 * kSeedBatch;
        // Lanes past the noted triangles repeat the first one's corners (lit, not written).
        const auto triangle = [&](std::size_t lane) -> const Pending& {
            const std::size_t p = lane % kSeedBatch;
            return pending_[p < count_ ? p : 0];
        };
        const std::vector<CameraLight<Real>>& lights = shader.rig->active_lights;
        AxisLanes<Real, N> vectors[kMaxLaneLights + 1];  // the lights, then the eye
        AxisLanes<Real, N>& to_eye = vectors[lights.size()];
        if (shader.effects.normals) {  // else no vector is read (PointShader::compute_vectors())
            // Normalised once per triangle, then given to its three corners' lanes.
            AxisLanes<Real, kSeedBatch> per_triangle[kMaxLaneLights + 1];
            light_vectors_lanes(
                shader, [&](std::size_t p) -> const Vec3<Real>& { return triangle(p).centroid; }, per_triangle);
            for (std::size_t k = 0; k < lights.size() + (shader.effects.specular ? 1 : 0); ++k) {
                for (int c = 0; c < 3; ++c) {
                    for (std::size_t corner = 0; corner < 3; ++corner) {
                        std::memcpy(&vectors[k].axis[c][corner * kSeedBatch], per_triangle[k].axis[c],
                                    sizeof per_triangle[k].axis[c]);
                    }
                }
            }
        }
        ShadeLanesInput<Real, N> in;
        in.to_light = vectors;
        in.to_eye = &to_eye;
        for (std::size_t l = 0; l < N; ++l) {
            const Varyings<Real>& corner = *out[triangle(l).draw].v[l / kSeedBatch];
            in.normal.set(l, corner.normal);
            in.color.set(l, corner.color);
        }
        AxisLanes<Real, N> lit;
        shade_with_lanes(shader, in, lit);
        for (std::size_t p = 0; p < count_; ++p) {
            for (std::size_t corner = 0; corner < 3; ++corner) {
                out[pending_[p].draw].lit[corner] = lit.get(corner * kSeedBatch + p);
            }
        }
        count_ = 0;
    }

private:
    struct Pending {
        std::size_t draw;
        Vec3<Real> centroid;
    };
    Pending pending_[kSeedBatch];
    std::size_t count_ = 0;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SEED_CORNER_BATCH_HPP
