// vertex_lighting_lanes.hpp compiled for AVX2: 8 floats or 4 doubles per
// instruction where the baseline has 4 and 2 (lanes_isa.hpp says how the two
// compilations stay apart). Every header the lanes use is included first,
// outside the target region, so their inline functions are the baseline's here
// as everywhere else; only the lanes' own templates are compiled for AVX2.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "shading.hpp"
#include "vertex_stage.hpp"

#define PHONGRAST_LANES_ISA avx2
#pragma GCC push_options
#pragma GCC target("avx2")
#include "vertex_lighting_lanes.hpp"
#pragma GCC pop_options

namespace phongrast::detail {

template <typename Real>
void light_vertex_lanes_avx2(const PointShader<Real>& shader, const VertexMaterials<Real>& materials,
                             FrameVector<Varyings<Real>>& varyings, std::size_t begin, std::size_t end,
                             LightVectorsAt<Real>& vectors) {
    avx2::light_vertex_lanes(shader, materials, varyings, begin, end, vectors);
}

template void light_vertex_lanes_avx2<float>(const PointShader<float>&, const VertexMaterials<float>&,
                                             FrameVector<Varyings<float>>&, std::size_t, std::size_t,
                                             LightVectorsAt<float>&);
template void light_vertex_lanes_avx2<double>(const PointShader<double>&, const VertexMaterials<double>&,
                                              FrameVector<Varyings<double>>&, std::size_t, std::size_t,
                                              LightVectorsAt<double>&);

}  // namespace phongrast::detail
