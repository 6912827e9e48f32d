// The fill kernels of fill_kernels.hpp for the build's target instruction
// set (x86-64: SSE2). Included only by fill_kernels_baseline_float.cpp and
// fill_kernels_baseline_double.cpp, which instantiate one precision each
// (fill_kernel_sets.hpp says why).
#ifndef PHONGRAST_SRC_FILL_KERNELS_BASELINE_HPP
#define PHONGRAST_SRC_FILL_KERNELS_BASELINE_HPP

#include "fill_kernels.hpp"
#include "fill_dispatch.hpp"

namespace phongrast::detail {

template <typename Real>
FillKernel<Real> pick_kernel_baseline(const KernelChoice& choice) {
    return baseline::pick_kernel<Real>(choice);
}

template <typename Real>
TinyFillKernel<Real> pick_tiny_kernel_baseline(const KernelChoice& choice) {
    return baseline::pick_tiny_kernel<Real>(choice);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNELS_BASELINE_HPP
