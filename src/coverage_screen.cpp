// The coverage screen's baseline copy, and the choice of instruction set: the
// fill's (kernel_isa()), as for the lighting lanes (lighting_dispatch.cpp).
#include "coverage_screen.hpp"

#include <atomic>

#include "fill_dispatch.hpp"

namespace phongrast::detail {
namespace {
std::atomic<bool> screening{true};
}  // namespace

bool use_coverage_screen(bool on) { return screening.exchange(on); }
bool coverage_screen_in_use() { return screening.load(std::memory_order_relaxed); }

void screen_coverage_dispatched(const CoverageScreenInput& in, std::size_t begin, std::size_t end,
                                ScreenVerdict* verdicts, TinyCoverageBlock* tiny) {
#if PHONGRAST_HAVE_AVX2_KERNELS
    if (kernel_isa() == KernelIsa::avx2) return screen_coverage_avx2(in, begin, end, verdicts, tiny);
#endif
    screen_coverage(in, begin, end, verdicts, tiny);
}

}  // namespace phongrast::detail
