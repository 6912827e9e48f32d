// The avx2 fill kernels in double (fill_kernel_sets.hpp: one translation unit per set).
#include "fill_kernels_avx2.hpp"

namespace phongrast::detail {

template FillKernel<double> pick_kernel_avx2<double>(const KernelChoice&);
template TinyFillKernel<double> pick_tiny_kernel_avx2<double>(const KernelChoice&);

}  // namespace phongrast::detail
