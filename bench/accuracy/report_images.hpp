// The accuracy report's pictures, drawn with OpenImageIO's ImageBufAlgo:
// a log-log error-versus-time plot with the Pareto front, and a strip of
// error heat maps.
#ifndef PHONGRAST_BENCH_ACCURACY_REPORT_IMAGES_HPP
#define PHONGRAST_BENCH_ACCURACY_REPORT_IMAGES_HPP

#include <string>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::accuracy {

enum class PointKind { screened, from_seed, from_exact, front_only };

struct PlotPoint {
    double milliseconds = 0.0;
    double rmse = 0.0;
    PointKind kind = PointKind::screened;
    std::string label;  ///< drawn next to the point when not empty
};

/// Writes a PNG: every point, and a line through `front` (indices into points, fastest first).
void write_error_time_plot(const std::string& path, const std::string& title,
                           const std::vector<PlotPoint>& points, const std::vector<std::size_t>& front);

struct Panel {
    std::string caption;
    Image image;                 ///< shown as is (clamped) when errors is empty
    std::vector<double> errors;  ///< per-pixel error: shown as a heat map instead
};

/// Writes a PNG: the panels side by side with their captions and a heat-map legend.
void write_panels(const std::string& path, const std::vector<Panel>& panels);

}  // namespace phongrast::accuracy

#endif  // PHONGRAST_BENCH_ACCURACY_REPORT_IMAGES_HPP
