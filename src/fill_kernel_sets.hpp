// The fill kernels of each instruction set and precision (internal header):
// what fill_dispatch.cpp chooses between. Each set is its own translation
// unit (fill_kernels_baseline_float.cpp, ..._double.cpp and, on x86-64 GCC
// builds, fill_kernels_avx2_float.cpp, ..._double.cpp): the kernels'
// instantiations are most of the library's compile time (minutes each under
// the sanitizers), and four files let a parallel build compile them side by
// side instead of waiting for one long file at the end.
#ifndef PHONGRAST_SRC_FILL_KERNEL_SETS_HPP
#define PHONGRAST_SRC_FILL_KERNEL_SETS_HPP

#include "fill_dispatch.hpp"

namespace phongrast::detail {

/// The kernel for `choice` compiled for the build's target (x86-64: SSE2).
template <typename Real>
FillKernel<Real> pick_kernel_baseline(const KernelChoice& choice);
extern template FillKernel<float> pick_kernel_baseline<float>(const KernelChoice&);
extern template FillKernel<double> pick_kernel_baseline<double>(const KernelChoice&);
template <typename Real>
TinyFillKernel<Real> pick_tiny_kernel_baseline(const KernelChoice& choice);
extern template TinyFillKernel<float> pick_tiny_kernel_baseline<float>(const KernelChoice&);
extern template TinyFillKernel<double> pick_tiny_kernel_baseline<double>(const KernelChoice&);

#if PHONGRAST_HAVE_AVX2_KERNELS
/// The kernel for `choice` compiled for AVX2 (fill_kernels_avx2.hpp).
template <typename Real>
FillKernel<Real> pick_kernel_avx2(const KernelChoice& choice);
extern template FillKernel<float> pick_kernel_avx2<float>(const KernelChoice&);
extern template FillKernel<double> pick_kernel_avx2<double>(const KernelChoice&);
template <typename Real>
TinyFillKernel<Real> pick_tiny_kernel_avx2(const KernelChoice& choice);
extern template TinyFillKernel<float> pick_tiny_kernel_avx2<float>(const KernelChoice&);
extern template TinyFillKernel<double> pick_tiny_kernel_avx2<double>(const KernelChoice&);
#endif

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNEL_SETS_HPP
