// The texture-filter rows of the accuracy report: what the filter a textured
// render samples with costs in error and in time, on a floor that runs to the
// horizon (the texture minified up to hundreds of texels per pixel) and on a
// plane close to the camera (each texel magnified to about 7 x 7 pixels at
// 256 x 256).
#ifndef PHONGRAST_BENCH_ACCURACY_TEXTURE_FILTERS_HPP
#define PHONGRAST_BENCH_ACCURACY_TEXTURE_FILTERS_HPP

#include <string>

namespace phongrast_bench {

/// Renders both scenes at `size` x `size` with each filter (and with 4 x 4
/// samples), compares each with the reference (bilinear, 8 x 8 samples,
/// double: the texture averaged over each pixel's area), times them (median
/// of `runs` after a warm-up, 1 thread and all threads) and returns the
/// report's Markdown section.
std::string texture_filter_section(int size, int runs);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_ACCURACY_TEXTURE_FILTERS_HPP
