#include "stage_times.hpp"

#include <atomic>
#include <mutex>

namespace phongrast::detail {
namespace {

std::atomic<bool> recording{false};
std::mutex recorded_mutex;
std::vector<PassStageTimes> recorded;  // guarded by recorded_mutex

}  // namespace

const char* stage_name(Stage stage) {
    switch (stage) {
        case Stage::vertices: return "vertices";
        case Stage::faces: return "faces and plan";
        case Stage::vertex_lights: return "vertex lighting";
        case Stage::setup: return "set-up";
        case Stage::painter_order: return "painter's order";
        case Stage::binning: return "binning";
        case Stage::fill: return "fill";
        case Stage::walk: return "walks";
        case Stage::extra_outputs: return "extra outputs";
        case Stage::count: break;
    }
    return "?";
}

bool record_stage_times(bool on) { return recording.exchange(on); }

std::vector<PassStageTimes> take_stage_times() {
    const std::lock_guard<std::mutex> lock(recorded_mutex);
    std::vector<PassStageTimes> taken;
    taken.swap(recorded);
    return taken;
}

StageClock::StageClock() : on_(recording.load(std::memory_order_relaxed)) {
    if (on_) last_ = std::chrono::steady_clock::now();
}

StageClock::~StageClock() {
    if (!on_) return;
    try {
        const std::lock_guard<std::mutex> lock(recorded_mutex);
        recorded.push_back(times_);
    } catch (...) {
        // Out of memory or a failed lock: this pass goes unrecorded (a destructor must not throw).
    }
}

}  // namespace phongrast::detail
