#include "stage_table.hpp"

#include <cstdio>

#include "support/timing.hpp"

namespace phongrast_bench {

std::string stage_medians_line(const std::vector<phongrast::detail::PassStageTimes>& passes, double frame_ms) {
    using phongrast::detail::Stage;
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "stages, median ms per pass over %zu passes:", passes.size());
    std::string line = buffer;
    double sum = 0.0;
    for (std::size_t stage = 0; stage < phongrast::detail::kStageCount; ++stage) {
        std::vector<double> ms;
        for (const phongrast::detail::PassStageTimes& pass : passes) ms.push_back(pass[stage] * 1e3);
        const double median = ms.empty() ? 0.0 : phongrast::support::median(ms);
        if (median == 0.0) continue;  // a stage this scene skips
        sum += median;
        std::snprintf(buffer, sizeof buffer, " %s %.3f |", phongrast::detail::stage_name(static_cast<Stage>(stage)),
                      median);
        line += buffer;
    }
    std::snprintf(buffer, sizeof buffer, " outside the passes %.3f", frame_ms - sum);
    return line + buffer;
}

}  // namespace phongrast_bench
