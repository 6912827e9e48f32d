// How far one render is from another, as the tests, the accuracy report and
// the llvmpipe comparison state it.
//
// Colours are compared as a PNG would show them: every channel clamped to
// [0, 1]. Over all pixels and channels:
//   RMSE       sqrt(mean of squared channel differences)
//   PSNR       20 log10(1 / RMSE) in dB (+infinity for identical images)
//   max error  the largest channel difference
//   share off  the fraction of pixels with some channel off by more than 1/255
// Coverage (ImageAgreement) is compared before clamping: a pixel is
// "background" when it equals the scene's background colour exactly (both
// renderers clear to it, and a lit surface with positive colours and ambient
// light never lands on it exactly).
#ifndef PHONGRAST_SUPPORT_IMAGE_COMPARE_HPP
#define PHONGRAST_SUPPORT_IMAGE_COMPARE_HPP

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::support {

/// The step of an 8-bit channel: differences above it change a PNG's bytes.
constexpr double kOneLevel = 1.0 / 255.0;

struct ErrorMetrics {
    double rmse = 0.0;
    double psnr_db = std::numeric_limits<double>::infinity();
    double max_abs = 0.0;
    double share_off = 0.0;  ///< of pixels, in [0, 1]
};

/// Per-pixel largest channel difference (clamped values), row-major.
/// Throws std::invalid_argument when the sizes differ (as do the others below).
std::vector<double> error_map(const Image& image, const Image& reference);

ErrorMetrics compare(const Image& image, const Image& reference);

/// Two independent renders of one scene side by side: colour differences,
/// coverage, and the same away from the silhouette.
struct ImageAgreement {
    std::size_t pixels = 0;
    std::size_t covered_in_both = 0;
    std::size_t only_in_first = 0;   ///< covered by the first image, background in the second
    std::size_t only_in_second = 0;  ///< covered by the second image, background in the first
    std::size_t above_1 = 0;         ///< pixels whose largest channel difference exceeds 1/255
    std::size_t above_2 = 0;         ///< ... exceeds 2/255
    std::size_t above_8 = 0;         ///< ... exceeds 8/255
    double max_difference = 0.0;     ///< largest channel difference anywhere
    int max_row = -1;                ///< where it is
    int max_column = -1;
    double rmse = 0.0;  ///< over every channel of every pixel
    /// The same counts over pixels covered in both images whose 3x3 neighbourhood
    /// is covered in both too (no silhouette pixel): differences here cannot be
    /// explained by coverage at the object's outline.
    std::size_t interior_pixels = 0;
    std::size_t interior_above_8 = 0;
    double interior_max_difference = 0.0;

    double share(std::size_t count) const { return pixels ? double(count) / double(pixels) : 0.0; }
};

ImageAgreement agreement(const Image& first, const Image& second, const glm::vec3& background);

/// One line with the counts, shares, largest difference, RMSE and coverage.
std::string summary(const ImageAgreement& agreement);

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_IMAGE_COMPARE_HPP
