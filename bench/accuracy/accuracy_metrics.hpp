// Error of a rendered image against a reference, as the accuracy report
// states it (header-only so the tests can use it without the benchmarks).
//
// Both images are compared as a PNG would show them: every channel clamped to
// [0, 1]. Over all pixels and channels:
//   RMSE       sqrt(mean of squared channel differences)
//   PSNR       20 log10(1 / RMSE) in dB (+infinity for identical images)
//   max error  the largest channel difference
//   share off  the fraction of pixels with some channel off by more than 1/255
#ifndef PHONGRAST_BENCH_ACCURACY_METRICS_HPP
#define PHONGRAST_BENCH_ACCURACY_METRICS_HPP

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::accuracy {

struct ErrorMetrics {
    double rmse = 0.0;
    double psnr_db = std::numeric_limits<double>::infinity();
    double max_abs = 0.0;
    double share_off = 0.0;  ///< of pixels, in [0, 1]
};

/// The step of an 8-bit channel: differences above it change a PNG's bytes.
constexpr double kOneLevel = 1.0 / 255.0;

inline double displayed(float value) { return std::clamp(static_cast<double>(value), 0.0, 1.0); }

/// Per-pixel largest channel difference (clamped values), row-major.
inline std::vector<double> error_map(const Image& image, const Image& reference) {
    if (image.rows != reference.rows || image.columns != reference.columns) {
        throw std::invalid_argument("error_map: images differ in size");
    }
    std::vector<double> errors(image.pixels.size());
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        double worst = 0.0;
        for (int channel = 0; channel < 3; ++channel) {
            worst = std::max(worst, std::abs(displayed(image.pixels[p][channel]) -
                                             displayed(reference.pixels[p][channel])));
        }
        errors[p] = worst;
    }
    return errors;
}

inline ErrorMetrics compare(const Image& image, const Image& reference) {
    if (image.rows != reference.rows || image.columns != reference.columns) {
        throw std::invalid_argument("compare: images differ in size");
    }
    ErrorMetrics metrics;
    if (image.pixels.empty()) return metrics;
    double squares = 0.0;
    std::size_t off = 0;
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        double worst = 0.0;
        for (int channel = 0; channel < 3; ++channel) {
            const double d = std::abs(displayed(image.pixels[p][channel]) -
                                      displayed(reference.pixels[p][channel]));
            squares += d * d;
            worst = std::max(worst, d);
        }
        metrics.max_abs = std::max(metrics.max_abs, worst);
        if (worst > kOneLevel) ++off;
    }
    metrics.rmse = std::sqrt(squares / (3.0 * static_cast<double>(image.pixels.size())));
    metrics.psnr_db = metrics.rmse > 0.0 ? 20.0 * std::log10(1.0 / metrics.rmse)
                                         : std::numeric_limits<double>::infinity();
    metrics.share_off = static_cast<double>(off) / static_cast<double>(image.pixels.size());
    return metrics;
}

}  // namespace phongrast::accuracy

#endif  // PHONGRAST_BENCH_ACCURACY_METRICS_HPP
