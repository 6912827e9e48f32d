// Writes PNGs for looking at a disagreement: a difference heat map and the two renders.
#ifndef PHONGRAST_BENCH_LLVMPIPE_HEAT_MAP_HPP
#define PHONGRAST_BENCH_LLVMPIPE_HEAT_MAP_HPP

#include <string>

#include "phongrast/image.hpp"

namespace llvmpipe_compare {

/// Heat map of the largest channel difference per pixel (clamped colours):
/// dark grey where both cover the pixel and agree within 1/255, black where
/// both show background, a black-red-yellow-white ramp saturating at 16/255,
/// magenta where only `first` covers the pixel and cyan where only `second` does.
/// Throws std::runtime_error when the file cannot be written (no partial file is left).
void write_heat_map(const std::string& path, const phongrast::Image& first, const phongrast::Image& second,
                    const glm::vec3& background);

/// The image clamped to [0, 1] as an 8-bit PNG, via a temporary file and rename.
void write_png(const std::string& path, const phongrast::Image& image);

}  // namespace llvmpipe_compare

#endif  // PHONGRAST_BENCH_LLVMPIPE_HEAT_MAP_HPP
