// Images with extra outputs: one EXR holding the colour and the requested
// planes as named channels, and PNG with an alpha channel (transparent background).
#ifndef PHONGRAST_IO_AOV_FILE_HPP
#define PHONGRAST_IO_AOV_FILE_HPP

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "phongrast/aov.hpp"
#include "phongrast/image.hpp"
#include "phongrast/io/image_file.hpp"

namespace phongrast::io {

/// One multi-channel EXR: R, G, B (linear float, as write_image), then
/// whichever planes `aovs` holds: A (alpha), Z (camera depth, +inf on the
/// background), distance (from the eye, +inf on the background), N.X, N.Y,
/// N.Z (world-space unit normal), uv.s, uv.t (texture coordinates), id
/// (32-bit unsigned integer channel holding the triangle index; the
/// background's -1 is stored as 4294967295). Written to a temporary file and renamed, like
/// write_image. Throws FileError (also for a path not ending in .exr).
void write_exr_with_aovs(const Image& image, const AovPlanes& aovs, const std::string& path);

/// Reads back what write_exr_with_aovs wrote: the colour, and the planes
/// whose channels the file has (the others are left empty). Throws FileError.
void read_exr_with_aovs(const std::string& path, Image& image, AovPlanes& aovs);

/// An 8-bit RGBA PNG: alpha is the covered fraction, and the colour of
/// partly covered pixels is the surface's alone (the render mixed it with
/// `background` in proportion 1 - alpha; that share is taken out), so the
/// picture composites over any background. Fully transparent pixels are
/// black. Throws FileError (also for a path not ending in .png, or an alpha
/// plane of the wrong size).
void write_png_with_alpha(const Image& image, const std::vector<float>& alpha, const glm::vec3& background,
                          const std::string& path);
/// The same with a choice of PNG compression (options.png_bit_depth is not used: always 8-bit).
void write_png_with_alpha(const Image& image, const std::vector<float>& alpha, const glm::vec3& background,
                          const std::string& path, const ImageWriteOptions& options);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_AOV_FILE_HPP
