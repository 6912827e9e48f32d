// The baseline fill kernels in double (fill_kernel_sets.hpp: one translation unit per set).
#include "fill_kernels_baseline.hpp"

namespace phongrast::detail {

template FillKernel<double> pick_kernel_baseline<double>(const KernelChoice&);
template TinyFillKernel<double> pick_tiny_kernel_baseline<double>(const KernelChoice&);

}  // namespace phongrast::detail
