// The coverage screen (coverage_screen.hpp) compiled for AVX2: four doubles
// per instruction where the baseline has two. As in lighting_avx2.cpp, every
// header it uses is included first, outside the target region, so only the
// screen's own function is compiled for AVX2.
#include <cstddef>
#include <cstdint>

#include "fill_types.hpp"
#include "raster.hpp"
#include "vertex_stage.hpp"

#define PHONGRAST_LANES_ISA avx2
#define PHONGRAST_SCREEN_LANES 4
#pragma GCC push_options
#pragma GCC target("avx2")
#include "coverage_screen.hpp"
#pragma GCC pop_options
static_assert(phongrast::detail::avx2::screen_lanes::kLanes == 4, "the AVX2 copy works on 4 doubles");

namespace phongrast::detail {

void screen_coverage_avx2(const CoverageScreenInput& in, std::size_t begin, std::size_t end, ScreenVerdict* verdicts,
                          TinyCoverageBlock* tiny) {
    avx2::screen_coverage(in, begin, end, verdicts, tiny);
}

}  // namespace phongrast::detail
