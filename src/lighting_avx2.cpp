// The lighting lanes (vertex_lighting_lanes.hpp, seed_corner_lanes.hpp)
// compiled for AVX2: 8 floats or 4 doubles per instruction where the baseline
// has 4 and 2 (lanes_isa.hpp says how the two compilations stay apart;
// lighting_dispatch.cpp picks one). Every header the lanes use is included
// first, outside the target region, so their inline functions are the
// baseline's here as everywhere else; only the lanes' own templates are
// compiled for AVX2.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "fill_types.hpp"
#include "shading.hpp"
#include "vertex_stage.hpp"

#define PHONGRAST_LANES_ISA avx2
#pragma GCC push_options
#pragma GCC target("avx2")
#include "seed_corner_lanes.hpp"
#include "vertex_lighting_lanes.hpp"
#pragma GCC pop_options

namespace phongrast::detail {

template <typename Real>
void light_vertex_lanes_avx2(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                             FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                             LightVectorsAt<Real>& vectors) {
    avx2::light_vertex_lanes(shader, materials, varyings, begin, end, vectors);
}

template <typename Real>
void light_seed_corners_avx2(const PointShader<Real>& shader, const PendingSeedTriangle<Real>* pending,
                             std::size_t count, Vec3<Real>* const* lit) {
    avx2::light_seed_corners(shader, pending, count, lit);
}

#define PHONGRAST_INSTANTIATE_LIGHTING_AVX2(Real)                                                           \
    template void light_vertex_lanes_avx2<Real>(const PointShader<Real>&, const VertexMaterials<Real>&,      \
                                                FrameVector<Varyings<Real>>&, std::size_t, std::size_t,      \
                                                LightVectorsAt<Real>&);                                      \
    template void light_seed_corners_avx2<Real>(const PointShader<Real>&, const PendingSeedTriangle<Real>*, \
                                                std::size_t, Vec3<Real>* const*);
PHONGRAST_INSTANTIATE_LIGHTING_AVX2(float)
PHONGRAST_INSTANTIATE_LIGHTING_AVX2(double)
#undef PHONGRAST_INSTANTIATE_LIGHTING_AVX2

}  // namespace phongrast::detail
