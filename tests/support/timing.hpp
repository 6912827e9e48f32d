// How the benchmarks time things: one definition of the median, of
// interleaved rounds (every contender once per round, so a change in the
// machine's load hits all of them alike and their ratios stay fair), and of
// peak memory.
#ifndef PHONGRAST_SUPPORT_TIMING_HPP
#define PHONGRAST_SUPPORT_TIMING_HPP

#include <chrono>
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

/// Every timing a contender gave in the timed rounds, in round order.
using Samples = std::vector<double>;

/// Calls every contender `warmup` times (untimed), then `rounds` rounds that call
/// each contender once in turn; a contender returns its own measurement (e.g.
/// milliseconds). Returns each contender's samples.
std::vector<Samples> interleaved_rounds(int rounds, int warmup, const std::vector<std::function<double()>>& contenders);

/// The median of each contender's samples of interleaved_rounds().
std::vector<double> interleaved_medians(int rounds, int warmup, const std::vector<std::function<double()>>& contenders);

/// The process's peak resident memory so far, in MiB (getrusage).
double peak_rss_mib();

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_TIMING_HPP
