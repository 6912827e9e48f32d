// PNG and JPEG files to float RGB (internal header): PNG through libspng,
// JPEG through libjpeg-turbo, both from the bytes in memory.
// Values: an 8-bit k is k/255, a 16-bit k is k/65535 (float division,
// correctly rounded); grey repeats into r, g, b; alpha is dropped.
#ifndef PHONGRAST_SRC_IO_IMAGE_DECODERS_HPP
#define PHONGRAST_SRC_IO_IMAGE_DECODERS_HPP

#include <cstddef>
#include <string>

#include "phongrast/image.hpp"

namespace phongrast::io::detail {

bool looks_like_png(const char* data, std::size_t size);
bool looks_like_jpeg(const char* data, std::size_t size);

/// Throws FileError naming `path`.
Image decode_png(const char* data, std::size_t size, const std::string& path);

/// Throws FileError naming `path`. Sets `unsupported` (and returns an empty
/// image) for colour spaces libjpeg-turbo does not turn into RGB (CMYK, YCCK),
/// which OpenImageIO then reads.
Image decode_jpeg(const char* data, std::size_t size, const std::string& path, bool& unsupported);

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_IMAGE_DECODERS_HPP
