#include "timing.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <stdexcept>

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

double peak_rss_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace phongrast::support
