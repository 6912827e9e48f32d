// Seed Gouraud's batched corner lighting (seed_corner_batch.hpp) in lanes
// (internal header), compiled once per instruction set (lanes_isa.hpp): for
// the baseline by lighting_dispatch.cpp, for AVX2 by lighting_avx2.cpp.
#ifndef PHONGRAST_SRC_SEED_CORNER_LANES_HPP
#define PHONGRAST_SRC_SEED_CORNER_LANES_HPP

#include <cstddef>
#include <cstring>
#include <vector>

#include "lanes_isa.hpp"
#include "shade_lanes.hpp"
#include "varyings.hpp"

namespace phongrast::detail {

/// Triangles whose corners are lit together.
constexpr std::size_t kSeedBatch = 16;

/// A whole triangle waiting for its corners' colours.
template <typename Real>
struct PendingSeedTriangle {
    const Varyings<Real>* corner[3];  ///< in its draw's (coverage) order
    Vec3<Real> centroid;              ///< camera space: where the seed takes its light vectors
};

/// light_seed_corners() compiled for the instruction set kernel_isa() names,
/// the fill's (lighting_dispatch.cpp).
template <typename Real>
void light_seed_corners_dispatched(const PointShader<Real>& shader, const PendingSeedTriangle<Real>* pending,
                                   std::size_t count, Vec3<Real>* const* lit);

#if PHONGRAST_HAVE_AVX2_KERNELS
/// light_seed_corners() compiled for AVX2 (lighting_avx2.cpp); call only
/// when kernel_isa() is KernelIsa::avx2.
template <typename Real>
void light_seed_corners_avx2(const PointShader<Real>& shader, const PendingSeedTriangle<Real>* pending,
                             std::size_t count, Vec3<Real>* const* lit);
#endif

inline namespace PHONGRAST_LANES_ISA {

/// Lights the corners of pending[0 .. count-1] (count from 1 to kSeedBatch)
/// into lit[0 .. count-1] (three corners each, in their order): the vectors
/// at each centroid by light_vectors_lanes(), then every corner by shade_with_lanes().
template <typename Real>
void light_seed_corners(const PointShader<Real>& shader, const PendingSeedTriangle<Real>* pending,
                        std::size_t count, Vec3<Real>* const* lit) {
    // Lane i * kSeedBatch + p: corner i of pending triangle p (blocks of
    // corners: a triangle's vectors are copied to its corners a block at a time).
    constexpr std::size_t N = 3 * kSeedBatch;
    // Lanes past the noted triangles repeat the first one's corners (lit, not written).
    const auto triangle = [&](std::size_t lane) -> const PendingSeedTriangle<Real>& {
        const std::size_t p = lane % kSeedBatch;
        return pending[p < count ? p : 0];
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
        const Varyings<Real>& corner = *triangle(l).corner[l / kSeedBatch];
        in.normal.set(l, corner.normal);
        in.color.set(l, corner.color);
    }
    AxisLanes<Real, N> lit_lanes;
    shade_with_lanes(shader, in, lit_lanes);
    for (std::size_t p = 0; p < count; ++p) {
        for (std::size_t corner = 0; corner < 3; ++corner) lit[p][corner] = lit_lanes.get(corner * kSeedBatch + p);
    }
}

}  // namespace PHONGRAST_LANES_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SEED_CORNER_LANES_HPP
