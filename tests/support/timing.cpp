#include "timing.hpp"

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace phongrast::support {

double median(std::vector<double> values) {
    if (values.empty()) throw std::invalid_argument("median: no values");
    const std::size_t n = values.size();
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(n / 2), values.end());
    const double upper = values[n / 2];
    if (n % 2) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(n / 2));
    return 0.5 * (lower + upper);
}

double process_cpu_ms() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

double time_ms(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return milliseconds_since(start);
}

std::vector<Samples> interleaved_rounds(int rounds, int warmup, const std::vector<std::function<double()>>& contenders) {
    for (int round = 0; round < warmup; ++round) {
        for (const auto& run : contenders) run();
    }
    std::vector<Samples> samples(contenders.size());
    for (int round = 0; round < rounds; ++round) {
        for (std::size_t k = 0; k < contenders.size(); ++k) samples[k].push_back(contenders[k]());
    }
    return samples;
}

std::vector<double> interleaved_medians(int rounds, int warmup, const std::vector<std::function<double()>>& contenders) {
    std::vector<double> medians;
    for (Samples& values : interleaved_rounds(rounds, warmup, contenders)) medians.push_back(median(std::move(values)));
    return medians;
}

std::vector<double> interleaved_medians_filling(double seconds, int rounds, int max_rounds,
                                                const std::vector<std::function<double()>>& contenders) {
    const auto start = std::chrono::steady_clock::now();
    for (const auto& run : contenders) run();  // the warm-up round, timed as a whole
    const double round_seconds = milliseconds_since(start) / 1e3;
    if (round_seconds > 0.0 && seconds > round_seconds * rounds) {
        rounds = static_cast<int>(std::min<double>(max_rounds, std::ceil(seconds / round_seconds)));
    }
    return interleaved_medians(std::max(rounds, 1), 0, contenders);
}

bool restart_peak_resident() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    std::ofstream clear_refs("/proc/self/clear_refs");
    clear_refs << "5";  // "5": reset the peak resident set size to the current one (proc(5))
    clear_refs.flush();
    return bool(clear_refs);
}

std::uint64_t peak_resident_bytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;  // "VmHWM:  1234 kB"
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
}

}  // namespace phongrast::support
