// The benchmarks' pictures, drawn with OpenImageIO: the accuracy report's
// log-log error-versus-time plot with its Pareto front and its strip of error
// heat maps, and the llvmpipe comparison's renders and difference heat maps.
// Every file is written to a temporary name next to it and renamed, so a
// failure leaves no partial file.
#ifndef PHONGRAST_BENCH_PICTURES_HPP
#define PHONGRAST_BENCH_PICTURES_HPP

#include <string>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast_bench {

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
    phongrast::Image image;      ///< shown as is (clamped) when errors is empty
    std::vector<double> errors;  ///< per-pixel error: shown as a heat map instead
};

/// Writes a PNG: the panels side by side with their captions and a heat-map legend.
void write_panels(const std::string& path, const std::vector<Panel>& panels);

/// The image clamped to [0, 1] as an 8-bit PNG.
void write_png(const std::string& path, const phongrast::Image& image);

/// Heat map of the largest channel difference per pixel (clamped colours):
/// dark grey where both cover the pixel and agree within 1/255, black where
/// both show background, a black-red-yellow-white ramp saturating at 16/255,
/// magenta where only `first` covers the pixel and cyan where only `second` does.
/// Throws std::runtime_error when the file cannot be written.
void write_difference_map(const std::string& path, const phongrast::Image& first, const phongrast::Image& second,
                          const glm::vec3& background);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_PICTURES_HPP
