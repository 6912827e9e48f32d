// The --stages line of the speed benchmarks (bench_speed_once,
// bench_mesh_order): the median of each render-pass stage over the timed
// passes (src/stage_times.hpp) and what the frame spends outside them.
#ifndef PHONGRAST_BENCH_STAGE_TABLE_HPP
#define PHONGRAST_BENCH_STAGE_TABLE_HPP

#include <string>
#include <vector>

#include "stage_times.hpp"

namespace phongrast_bench {

/// "stages, median ms per pass over N passes: vertices 1.234 | ... | outside
/// the passes X": stages a scene skips (median 0) are left out; "outside" is
/// `frame_ms` (the frame's median) less the stages' medians: validation, the
/// mesh order's check, resolve, the result's hand-over. Right for one pass per
/// frame, not for a supersampled frame of several passes.
std::string stage_medians_line(const std::vector<phongrast::detail::PassStageTimes>& passes, double frame_ms);

}  // namespace phongrast_bench

#endif
