// The baseline fill kernels in float (fill_kernel_sets.hpp: one translation unit per set).
#include "fill_kernels_baseline.hpp"

namespace phongrast::detail {

template FillKernel<float> pick_kernel_baseline<float>(const KernelChoice&);
template TinyFillKernel<float> pick_tiny_kernel_baseline<float>(const KernelChoice&);

}  // namespace phongrast::detail
