// Images out (and back in, for tests and tools) through OpenImageIO.
// PNG: 8 bits per channel, values clamped to [0,1] and written as they are
// (no gamma curve). EXR: linear 32-bit float, not clamped. The format comes
// from the file extension; anything else is an error raised before rendering.
#ifndef PHONGRAST_IO_IMAGE_FILE_HPP
#define PHONGRAST_IO_IMAGE_FILE_HPP

#include <string>

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

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_IMAGE_FILE_HPP
