#include "image_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace llvmpipe_compare {
namespace {

bool is_background(const glm::vec3& pixel, const glm::vec3& background) { return pixel == background; }

float clamp01(float value) { return std::min(1.0f, std::max(0.0f, value)); }

}  // namespace

std::vector<float> difference_map(const phongrast::Image& first, const phongrast::Image& second) {
    if (first.rows != second.rows || first.columns != second.columns) {
        throw std::invalid_argument("compare_images: the images differ in size");
    }
    std::vector<float> map(first.pixels.size());
    for (std::size_t i = 0; i < map.size(); ++i) {
        float largest = 0.0f;
        for (int channel = 0; channel < 3; ++channel) {
            largest = std::max(largest,
                               std::abs(clamp01(first.pixels[i][channel]) - clamp01(second.pixels[i][channel])));
        }
        map[i] = largest;
    }
    return map;
}

ImageAgreement compare_images(const phongrast::Image& first, const phongrast::Image& second,
                              const glm::vec3& background) {
    const std::vector<float> map = difference_map(first, second);
    ImageAgreement result;
    result.pixels = map.size();
    const auto covered_in_both = [&](int row, int column) {
        return !is_background(first.at(row, column), background) && !is_background(second.at(row, column), background);
    };
    double squared_sum = 0.0;
    for (int row = 0; row < first.rows; ++row) {
        for (int column = 0; column < first.columns; ++column) {
            const std::size_t i = std::size_t(row) * std::size_t(first.columns) + std::size_t(column);
            const bool in_first = !is_background(first.pixels[i], background);
            const bool in_second = !is_background(second.pixels[i], background);
            if (in_first && in_second) ++result.covered_in_both;
            if (in_first && !in_second) ++result.only_in_first;
            if (!in_first && in_second) ++result.only_in_second;

            const double d = map[i];
            if (d > 1.0 / 255.0) ++result.above_1;
            if (d > 2.0 / 255.0) ++result.above_2;
            if (d > 8.0 / 255.0) ++result.above_8;
            if (d > result.max_difference) {
                result.max_difference = d;
                result.max_row = row;
                result.max_column = column;
            }
            for (int channel = 0; channel < 3; ++channel) {
                const double e = double(clamp01(first.pixels[i][channel])) - double(clamp01(second.pixels[i][channel]));
                squared_sum += e * e;
            }

            bool interior = true;
            for (int dr = -1; dr <= 1 && interior; ++dr) {
                for (int dc = -1; dc <= 1 && interior; ++dc) {
                    const int r = row + dr, c = column + dc;
                    interior = r >= 0 && c >= 0 && r < first.rows && c < first.columns && covered_in_both(r, c);
                }
            }
            if (interior) {
                ++result.interior_pixels;
                if (d > 8.0 / 255.0) ++result.interior_above_8;
                result.interior_max_difference = std::max(result.interior_max_difference, d);
            }
        }
    }
    result.rmse = result.pixels ? std::sqrt(squared_sum / double(3 * result.pixels)) : 0.0;
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

}  // namespace llvmpipe_compare
