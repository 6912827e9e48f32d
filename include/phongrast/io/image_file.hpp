// Images out (and back in, for tests and tools) through OpenImageIO.
// PNG: 8 bits per channel, values clamped to [0,1] and written as they are
// (no gamma curve). EXR: linear 32-bit float, not clamped. The format comes
// from the file extension; anything else is an error raised before rendering.
#ifndef PHONGRAST_IO_IMAGE_FILE_HPP
#define PHONGRAST_IO_IMAGE_FILE_HPP

#include <string>
#include <string_view>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::io {

enum class ImageFormat { png, exr };

/// The format named by the path's extension (.png or .exr, any letter case).
/// Throws FileError naming the path and the supported extensions otherwise.
ImageFormat image_format_for(const std::string& path);

/// Writes to a temporary file in the destination folder, then renames it over
/// `path`, so a failure never leaves a truncated image or destroys an old one.
/// Throws FileError.
void write_image(const Image& image, const std::string& path);

/// Reads any image OpenImageIO understands into float RGB (PNG values become
/// value / 255). Throws FileError.
Image read_image(const std::string& path);

/// An image's channels exactly as its file stores them (what textures need):
/// 8-bit k becomes the float nearest k/255, 16-bit k the float nearest
/// k/65535, half and float values as they are; no colour transform, and
/// colour channels not multiplied by alpha. Row 0 is the top row.
struct StoredImage {
    int rows = 0;
    int columns = 0;
    int channels = 0;           ///< 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA, ...
    std::vector<float> values;  ///< rows x columns x channels, row-major
};

/// Reads any image OpenImageIO reads (PNG, JPEG, EXR, ...) as stored.
/// Throws FileError naming the file and why.
StoredImage read_stored_image(const std::string& path);
/// The same for an image held in memory (embedded in a glTF file); `name`
/// is for messages, and its extension (.png, .jpg) picks the decoder.
StoredImage read_stored_image(std::string_view bytes, const std::string& name);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_IMAGE_FILE_HPP
