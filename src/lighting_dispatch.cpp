// Picks the instruction set of the lighting lanes (lanes_isa.hpp): the fill's
// (kernel_isa(), fill_dispatch.hpp), so that one choice, or one override in the
// tests and benchmarks, covers the fill and the lighting alike. The baseline
// copies are compiled here.
#include "fill_dispatch.hpp"
#include "seed_corner_lanes.hpp"
#include "vertex_lighting_lanes.hpp"

namespace phongrast::detail {

template <typename Real>
void light_vertex_lanes_dispatched(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                                   FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                                   LightVectorsAt<Real>& vectors) {
#if PHONGRAST_HAVE_AVX2_KERNELS
    if (kernel_isa() == KernelIsa::avx2) return light_vertex_lanes_avx2(shader, materials, varyings, begin, end, vectors);
#endif
    light_vertex_lanes(shader, materials, varyings, begin, end, vectors);
}

template <typename Real>
void light_seed_corners_dispatched(const PointShader<Real>& shader, const PendingSeedTriangle<Real>* pending,
                                   std::size_t count, Vec3<Real>* const* lit) {
#if PHONGRAST_HAVE_AVX2_KERNELS
    if (kernel_isa() == KernelIsa::avx2) return light_seed_corners_avx2(shader, pending, count, lit);
#endif
    light_seed_corners(shader, pending, count, lit);
}

#define PHONGRAST_INSTANTIATE_LIGHTING_DISPATCH(Real)                                                            \
    template void light_vertex_lanes_dispatched<Real>(const PointShader<Real>&, const VertexMaterials<Real>&,      \
                                                      FrameVector<Varyings<Real>>&, std::size_t, std::size_t,      \
                                                      LightVectorsAt<Real>&);                                      \
    template void light_seed_corners_dispatched<Real>(const PointShader<Real>&, const PendingSeedTriangle<Real>*, \
                                                      std::size_t, Vec3<Real>* const*);
PHONGRAST_INSTANTIATE_LIGHTING_DISPATCH(float)
PHONGRAST_INSTANTIATE_LIGHTING_DISPATCH(double)
#undef PHONGRAST_INSTANTIATE_LIGHTING_DISPATCH

}  // namespace phongrast::detail
