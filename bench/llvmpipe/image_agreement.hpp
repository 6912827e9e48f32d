// How closely two renders of one scene agree: the numbers the llvmpipe
// comparison prints and its test asserts on.
//
// Colours are compared after clamping to [0, 1], as a PNG would store them.
// Coverage is compared before clamping: a pixel is "background" when it equals
// the scene's background colour exactly (both renderers clear to it and a lit
// surface with positive colours and ambient light never lands on it exactly).
#ifndef PHONGRAST_BENCH_LLVMPIPE_IMAGE_AGREEMENT_HPP
#define PHONGRAST_BENCH_LLVMPIPE_IMAGE_AGREEMENT_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "phongrast/image.hpp"

namespace llvmpipe_compare {

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
    double rmse = 0.0;               ///< over every channel of every pixel
    /// The same counts over pixels covered in both images whose 3x3 neighbourhood
    /// is covered in both too (no silhouette pixel): differences here cannot be
    /// explained by coverage at the object's outline.
    std::size_t interior_pixels = 0;
    std::size_t interior_above_8 = 0;
    double interior_max_difference = 0.0;

    double share(std::size_t count) const { return pixels ? double(count) / double(pixels) : 0.0; }
};

/// Throws std::invalid_argument when the sizes differ.
ImageAgreement compare_images(const phongrast::Image& first, const phongrast::Image& second,
                              const glm::vec3& background);

/// One line with the counts, shares, largest difference, RMSE and coverage.
std::string summary(const ImageAgreement& agreement);

/// Per-pixel largest channel difference after clamping.
std::vector<float> difference_map(const phongrast::Image& first, const phongrast::Image& second);

}  // namespace llvmpipe_compare

#endif  // PHONGRAST_BENCH_LLVMPIPE_IMAGE_AGREEMENT_HPP
