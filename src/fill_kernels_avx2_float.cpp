// The avx2 fill kernels in float (fill_kernel_sets.hpp: one translation unit per set).
#include "fill_kernels_avx2.hpp"

namespace phongrast::detail {

template FillKernel<float> pick_kernel_avx2<float>(const KernelChoice&);
template TinyFillKernel<float> pick_tiny_kernel_avx2<float>(const KernelChoice&);

}  // namespace phongrast::detail
