// Wall time of each stage of a render pass, for benchmarks (internal
// header): `bench_speed_once --stages` shows where a frame's time goes, so
// that per-frame costs (a stage that does not speed up with threads, a
// stage slower at 2 threads than at 1) are found by a command anyone can
// re-run rather than by a temporary edit.
//
// Off unless a benchmark turns it on: then every pass reads the clock at
// each stage boundary and records its times under a lock, once per pass.
// Off, a pass pays one relaxed atomic load.
#ifndef PHONGRAST_SRC_STAGE_TIMES_HPP
#define PHONGRAST_SRC_STAGE_TIMES_HPP

#include <array>
#include <chrono>
#include <cstddef>
#include <vector>

namespace phongrast::detail {

/// The stages of render_pass() (pipeline.cpp), in order.
enum class Stage : std::size_t {
    vertices,       ///< transform_vertices(): positions, normals, colours to camera and sample space
    faces,          ///< near plane, which back faces to cull, light rigs, fill plan, textures
    vertex_lights,  ///< Gouraud with exact vectors: each vertex lit
    setup,          ///< set_up_triangles()
    painter_order,  ///< painter_order()
    binning,        ///< bin_draws()
    fill,           ///< fill_bins()
    walk,           ///< fill_in_mesh_order(): set-up and fill in walks of the mesh, instead of set-up to fill
    extra_outputs,  ///< run_aov_pass()
    count
};
constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::count);

/// One pass's seconds per stage (zero for a stage it skipped).
using PassStageTimes = std::array<double, kStageCount>;

/// The stage's name as the benchmark prints it.
const char* stage_name(Stage stage);

/// Turns the recording on or off; returns whether it was on.
bool record_stage_times(bool on);
/// The passes recorded since the last call, oldest first, and forgets them.
std::vector<PassStageTimes> take_stage_times();

/// Times one pass's stages: lap(s) charges the time since the last lap (or
/// since construction) to stage s; the destructor records the pass.
class StageClock {
public:
    StageClock();
    ~StageClock();
    StageClock(const StageClock&) = delete;
    StageClock& operator=(const StageClock&) = delete;

    void lap(Stage stage) {
        if (!on_) return;
        const auto now = std::chrono::steady_clock::now();
        times_[static_cast<std::size_t>(stage)] += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_;
    PassStageTimes times_{};
};

}  // namespace phongrast::detail

#endif
