// How the benchmarks time things: one definition of the median, of
// interleaved rounds (every contender once per round, so a change in the
// machine's load hits all of them alike and their ratios stay fair), and of
// peak memory.
#ifndef PHONGRAST_SUPPORT_TIMING_HPP
#define PHONGRAST_SUPPORT_TIMING_HPP

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

namespace phongrast::support {

/// The middle value; for an even count the mean of the two middle values.
/// Throws std::invalid_argument for no values.
double median(std::vector<double> values);

/// Milliseconds on the steady clock since `start`.
inline double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// Milliseconds one call of `work` takes.
double time_ms(const std::function<void()>& work);

/// The process's CPU time in milliseconds (every thread's): on a VM, unlike
/// wall time, not counting what the host takes from it.
double process_cpu_ms();

/// Every timing a contender gave in the timed rounds, in round order.
using Samples = std::vector<double>;

/// Calls every contender `warmup` times (untimed), then `rounds` rounds that call
/// each contender once in turn; a contender returns its own measurement (e.g.
/// milliseconds). Returns each contender's samples.
std::vector<Samples> interleaved_rounds(int rounds, int warmup, const std::vector<std::function<double()>>& contenders);

/// The median of each contender's samples of interleaved_rounds().
std::vector<double> interleaved_medians(int rounds, int warmup, const std::vector<std::function<double()>>& contenders);

/// interleaved_medians() with one warm-up round and at least `rounds` rounds,
/// more if fewer than that would take `seconds` (judged by the warm-up round's
/// wall time), at most `max_rounds`: cases of a millisecond or two get enough
/// rounds that the few disturbed by other work on a shared machine do not move
/// the median, while cases of seconds keep `rounds`.
std::vector<double> interleaved_medians_filling(double seconds, int rounds, int max_rounds,
                                                const std::vector<std::function<double()>>& contenders);

/// Hands freed heap memory back to the system and restarts the peak resident
/// memory count from what is resident now (Linux: /proc/self/clear_refs), so
/// that peak_resident_bytes() leaves out what came and went before, such as a
/// mesh generator's scratch. False where that cannot be done: the peak then
/// still counts everything since the process started.
bool restart_peak_resident();

/// The peak resident memory since the process started or since the last
/// successful restart_peak_resident(), in bytes (VmHWM of /proc/self/status;
/// getrusage where that is missing).
std::uint64_t peak_resident_bytes();

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_TIMING_HPP
