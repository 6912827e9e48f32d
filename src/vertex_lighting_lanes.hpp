// Exact Gouraud's vertices lit in lanes (internal header), compiled once per
// instruction set (lanes_isa.hpp): by lighting_dispatch.cpp for the baseline
// and by lighting_avx2.cpp for AVX2, which lighting_dispatch.cpp picks on CPUs
// that have it (the same operations, no FMA: the same bits, test_kernel_isa).
#ifndef PHONGRAST_SRC_VERTEX_LIGHTING_LANES_HPP
#define PHONGRAST_SRC_VERTEX_LIGHTING_LANES_HPP

#include <algorithm>
#include <cstddef>

#include "lanes_isa.hpp"
#include "shade_lanes.hpp"
#include "vertex_stage.hpp"

namespace phongrast::detail {
inline namespace PHONGRAST_LANES_ISA {

/// Vertices lit together.
constexpr std::size_t kLightingLanes = 64;

/// Specialised lighting of vertices [begin, end), kLightingLanes at a time:
/// the vectors to every active light and to the eye by light_vectors_lanes(),
/// then the vertices are shaded by shade_with_lanes()
/// (one material) or vertex by vertex (materials per vertex): what
/// PointShader computes vertex by vertex, bit for bit. A last, partial group
/// fills its other lanes with copies of its first vertex.
template <typename Real>
void light_vertex_lanes(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                        FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                        LightVectorsAt<Real>& vectors) {
    const std::vector<CameraLight<Real>>& lights = shader.rig->active_lights;
    AxisLanes<Real, kLightingLanes> lanes[kMaxLaneLights + 1];
    AxisLanes<Real, kLightingLanes>& to_eye = lanes[lights.size()];
    ShadeLanesInput<Real, kLightingLanes> in;
    in.to_light = lanes;
    in.to_eye = &to_eye;
    AxisLanes<Real, kLightingLanes> lit;
    vectors.to_light.resize(lights.size());
    for (std::size_t first = begin; first < end; first += kLightingLanes) {
        const std::size_t n = std::min(kLightingLanes, end - first);
        const auto vertex = [&](std::size_t lane) -> Varyings<Real>& { return varyings[first + (lane < n ? lane : 0)]; };
        light_vectors_lanes(
            shader, [&](std::size_t lane) -> const Vec3<Real>& { return vertex(lane).position; }, lanes);
        if (materials.vertex_surfaces == nullptr) {
            for (std::size_t i = 0; i < kLightingLanes; ++i) {
                in.normal.set(i, vertex(i).normal);
                in.color.set(i, vertex(i).color);
            }
            shade_with_lanes(shader, in, lit);
            for (std::size_t i = 0; i < n; ++i) varyings[first + i].lit = lit.get(i);
            continue;
        }
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 0; k < lights.size(); ++k) vectors.to_light[k] = lanes[k].get(i);
            if (shader.effects.specular) vectors.to_eye = to_eye.get(i);
            Varyings<Real>& v = varyings[first + i];
            v.lit = materials.shader_of(shader, first + i).shade_with(vectors, v.normal, v.color);
        }
    }
}

}  // namespace PHONGRAST_LANES_ISA

/// light_vertex_lanes() compiled for the instruction set kernel_isa() names,
/// the fill's (lighting_dispatch.cpp).
template <typename Real>
void light_vertex_lanes_dispatched(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                                   FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                                   LightVectorsAt<Real>& vectors);

#if PHONGRAST_HAVE_AVX2_KERNELS
/// light_vertex_lanes() compiled for AVX2 (lighting_avx2.cpp); call
/// only when kernel_isa() is KernelIsa::avx2.
template <typename Real>
void light_vertex_lanes_avx2(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                             FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                             LightVectorsAt<Real>& vectors);
#endif

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_VERTEX_LIGHTING_LANES_HPP
