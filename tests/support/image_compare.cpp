#include "image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace phongrast::support {
namespace {

double displayed(float value) { return std::clamp(static_cast<double>(value), 0.0, 1.0); }

void require_same_size(const Image& a, const Image& b) {
    if (a.rows != b.rows || a.columns != b.columns) {
        throw std::invalid_argument("image comparison: the images differ in size (" + std::to_string(a.columns) + "x" +
                                    std::to_string(a.rows) + " and " + std::to_string(b.columns) + "x" +
                                    std::to_string(b.rows) + ")");
    }
}

/// Every pixel covered in both images and with its 3x3 neighbourhood covered in both.
std::vector<bool> interior_mask(const Image& first, const Image& second, const glm::vec3& background) {
    const auto covered = [&](int row, int column) {
        return first.at(row, column) != background && second.at(row, column) != background;
    };
    std::vector<bool> interior(first.pixels.size(), false);
    for (int row = 1; row + 1 < first.rows; ++row) {
        for (int column = 1; column + 1 < first.columns; ++column) {
            bool all = true;
            for (int dr = -1; dr <= 1 && all; ++dr) {
                for (int dc = -1; dc <= 1 && all; ++dc) all = covered(row + dr, column + dc);
            }
            interior[std::size_t(row) * std::size_t(first.columns) + std::size_t(column)] = all;
        }
    }
    return interior;
}

}  // namespace

std::vector<double> error_map(const Image& image, const Image& reference) {
    require_same_size(image, reference);
    std::vector<double> errors(image.pixels.size());
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        double worst = 0.0;
        for (int channel = 0; channel < 3; ++channel) {
            worst = std::max(worst, std::abs(displayed(image.pixels[p][channel]) - displayed(reference.pixels[p][channel])));
        }
        errors[p] = worst;
    }
    return errors;
}

ErrorMetrics compare(const Image& image, const Image& reference) {
    require_same_size(image, reference);
    ErrorMetrics metrics;
    if (image.pixels.empty()) return metrics;
    double squares = 0.0;
    std::size_t off = 0;
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        double worst = 0.0;
        for (int channel = 0; channel < 3; ++channel) {
            const double d = std::abs(displayed(image.pixels[p][channel]) - displayed(reference.pixels[p][channel]));
            squares += d * d;
            worst = std::max(worst, d);
        }
        metrics.max_abs = std::max(metrics.max_abs, worst);
        if (worst > kOneLevel) ++off;
    }
    metrics.rmse = std::sqrt(squares / (3.0 * static_cast<double>(image.pixels.size())));
    metrics.psnr_db =
        metrics.rmse > 0.0 ? 20.0 * std::log10(1.0 / metrics.rmse) : std::numeric_limits<double>::infinity();
    metrics.share_off = static_cast<double>(off) / static_cast<double>(image.pixels.size());
    return metrics;
}

ImageAgreement agreement(const Image& first, const Image& second, const glm::vec3& background) {
    const std::vector<double> map = error_map(first, second);
    const std::vector<bool> interior = interior_mask(first, second, background);
    ImageAgreement result;
    result.pixels = map.size();
    for (std::size_t i = 0; i < map.size(); ++i) {
        const bool in_first = first.pixels[i] != background;
        const bool in_second = second.pixels[i] != background;
        result.covered_in_both += in_first && in_second;
        result.only_in_first += in_first && !in_second;
        result.only_in_second += !in_first && in_second;
        const double d = map[i];
        result.above_1 += d > 1.0 * kOneLevel;
        result.above_2 += d > 2.0 * kOneLevel;
        result.above_8 += d > 8.0 * kOneLevel;
        if (d > result.max_difference) {
            result.max_difference = d;
            result.max_row = int(i / std::size_t(first.columns));
            result.max_column = int(i % std::size_t(first.columns));
        }
        if (interior[i]) {
            ++result.interior_pixels;
            result.interior_above_8 += d > 8.0 * kOneLevel;
            result.interior_max_difference = std::max(result.interior_max_difference, d);
        }
    }
    result.rmse = compare(first, second).rmse;
    return result;
}

std::string summary(const ImageAgreement& a) {
    char text[640];
    std::snprintf(text, sizeof text,
                  "of %zu pixels, differing by >1/255: %zu (%.4f%%), >2/255: %zu, >8/255: %zu; max %.4f at (row %d, "
                  "col %d); rmse %.6f; coverage: both %zu, only first %zu, only second %zu; interior (3x3 covered in "
                  "both): %zu pixels, >8/255: %zu, max %.4f",
                  a.pixels, a.above_1, 100.0 * a.share(a.above_1), a.above_2, a.above_8, a.max_difference, a.max_row,
                  a.max_column, a.rmse, a.covered_in_both, a.only_in_first, a.only_in_second, a.interior_pixels,
                  a.interior_above_8, a.interior_max_difference);
    return text;
}

}  // namespace phongrast::support
