// The fill kernels of fill_kernels.hpp compiled a second time, for AVX2 (8
// floats or 4 doubles per instruction instead of SSE2's 4 and 2), chosen at
// run time by fill_dispatch.cpp on CPUs that have it. Included only by
// fill_kernels_avx2_float.cpp and fill_kernels_avx2_double.cpp, which
// instantiate one precision each (see fill_kernels_float.cpp for why).
//
// Only the kernels are compiled for AVX2: every header they use is included
// first, outside the target region, so the inline functions and templates of
// those headers (the standard library, GLM, the rasterizer) are compiled for
// the baseline here as everywhere else, and the linker can never pick an AVX2
// copy of them for code that runs on any x86-64. The kernels themselves live
// in namespace phongrast::detail::avx2. AVX2 without FMA, and the same
// operations in the same order: the images are the baseline kernels' bit for
// bit (tests/test_kernel_isa.cpp).
#ifndef PHONGRAST_SRC_FILL_KERNELS_AVX2_HPP
#define PHONGRAST_SRC_FILL_KERNELS_AVX2_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <immintrin.h>

#include "fill_dispatch.hpp"

#define PHONGRAST_FILL_ISA avx2
#define PHONGRAST_FILL_VECTOR_BYTES 32

#pragma GCC push_options
#pragma GCC target("avx2")
#include "fill_kernels.hpp"
#pragma GCC pop_options

namespace phongrast::detail {

template <typename Real>
FillKernel<Real> pick_kernel_avx2(const KernelChoice& choice) {
    return avx2::pick_kernel<Real>(choice);
}

template <typename Real>
TinyFillKernel<Real> pick_tiny_kernel_avx2(const KernelChoice& choice) {
    return avx2::pick_tiny_kernel<Real>(choice);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNELS_AVX2_HPP
