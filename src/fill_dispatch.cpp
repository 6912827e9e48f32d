// Chooses the instruction set of the fill kernels: the baseline ones, or the
// AVX2 ones when this build has them and the CPU runs them
// (fill_kernel_sets.hpp). Decided once per process; tests may override it.
#include <atomic>
#include <stdexcept>
#include <string>

#include "fill_dispatch.hpp"
#include "fill_kernel_sets.hpp"

namespace phongrast::detail {

namespace {

bool cpu_runs_avx2() {
#if PHONGRAST_HAVE_AVX2_KERNELS
    static const bool supported = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return supported;
#else
    return false;
#endif
}

constexpr int kNoOverride = -1;
std::atomic<int> overridden_isa{kNoOverride};

}  // namespace

bool kernel_isa_available(KernelIsa isa) {
    switch (isa) {
        case KernelIsa::baseline: return true;
        case KernelIsa::avx2: return cpu_runs_avx2();
    }
    return false;
}

KernelIsa kernel_isa() {
    const int forced = overridden_isa.load(std::memory_order_relaxed);
    if (forced != kNoOverride) return static_cast<KernelIsa>(forced);
    return cpu_runs_avx2() ? KernelIsa::avx2 : KernelIsa::baseline;
}

void override_kernel_isa(std::optional<KernelIsa> isa) {
    if (isa && !kernel_isa_available(*isa)) {
        throw std::invalid_argument(std::string("override_kernel_isa: ") + to_string(*isa) +
                                    " kernels are not in this build or not supported by this CPU");
    }
    overridden_isa.store(isa ? static_cast<int>(*isa) : kNoOverride, std::memory_order_relaxed);
}

const char* to_string(KernelIsa isa) {
    switch (isa) {
        case KernelIsa::baseline: return "baseline";
        case KernelIsa::avx2: return "avx2";
    }
    return "unknown";
}

template <typename Real>
FillKernel<Real> pick_fill_kernel(const KernelChoice& choice) {
#if PHONGRAST_HAVE_AVX2_KERNELS
    if (kernel_isa() == KernelIsa::avx2) return pick_kernel_avx2<Real>(choice);
#endif
    return pick_kernel_baseline<Real>(choice);
}

template FillKernel<float> pick_fill_kernel<float>(const KernelChoice&);
template FillKernel<double> pick_fill_kernel<double>(const KernelChoice&);

template <typename Real>
TinyFillKernel<Real> pick_tiny_fill_kernel(const KernelChoice& choice) {
#if PHONGRAST_HAVE_AVX2_KERNELS
    if (kernel_isa() == KernelIsa::avx2) return pick_tiny_kernel_avx2<Real>(choice);
#endif
    return pick_tiny_kernel_baseline<Real>(choice);
}

template TinyFillKernel<float> pick_tiny_fill_kernel<float>(const KernelChoice&);
template TinyFillKernel<double> pick_tiny_fill_kernel<double>(const KernelChoice&);

}  // namespace phongrast::detail
