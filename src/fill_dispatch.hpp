// What chooses the fill kernel (internal header): the choice, and the
// instruction set the kernels run in; defined in fill_dispatch.cpp, and, like
// fill_types.hpp, compiled for the baseline instruction set only.
#ifndef PHONGRAST_SRC_FILL_DISPATCH_HPP
#define PHONGRAST_SRC_FILL_DISPATCH_HPP

#include <optional>

#include "fill_types.hpp"

namespace phongrast::detail {

/// What decides the kernel.
struct KernelChoice {
    bool phong = false;
    bool flat = false;
    bool perspective = true;
    bool specialized = true;
    bool per_sample_vectors = true;
    bool uniform_color = true;
    bool textured = false;  ///< some material has a texture: the textured kernels
    EffectSet effects;
};

/// The kernel for `choice` compiled for the best instruction set this build
/// and this CPU have (kernel_isa()). Every instruction set computes the same
/// image bit for bit: the same IEEE operations in the same order, no fused
/// multiply-add.
template <typename Real>
FillKernel<Real> pick_fill_kernel(const KernelChoice& choice);
/// The kernel that fills a TinyDraw as pick_fill_kernel(choice) fills the
/// same triangle set up, from the same instruction set; null where there is none.
template <typename Real>
TinyFillKernel<Real> pick_tiny_fill_kernel(const KernelChoice& choice);

enum class KernelIsa {
    baseline,  ///< the build's target (x86-64: SSE2, 4 floats per instruction)
    avx2,      ///< AVX2: 8 floats per instruction (x86-64 GCC builds, on CPUs that have it)
};
/// What pick_fill_kernel() uses now.
KernelIsa kernel_isa();
const char* to_string(KernelIsa isa);
/// For tests that compare instruction sets: use `isa` from now on (it must
/// be one kernel_isa_available() accepts), or the best one again with nullopt.
void override_kernel_isa(std::optional<KernelIsa> isa);
/// Whether this build has kernels for `isa` and this CPU can run them.
bool kernel_isa_available(KernelIsa isa);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_DISPATCH_HPP
