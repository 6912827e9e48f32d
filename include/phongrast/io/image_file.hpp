// Images out and in. The common formats go through their own libraries
// (PNG: libdeflate out, libspng in; EXR: OpenEXR; JPEG in: libjpeg-turbo);
// any other image read_image meets is read by OpenImageIO, which is loaded
// only then (docs/startup.md says why and how it is found).
// PNG: 8 bits per channel (16 on request), values clamped to [0,1] and
// written as they are (no gamma curve). EXR: linear 32-bit float, not
// clamped. The format comes from the file extension; anything else is an
// error raised before rendering.
#ifndef PHONGRAST_IO_IMAGE_FILE_HPP
#define PHONGRAST_IO_IMAGE_FILE_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::io {

enum class ImageFormat { png, exr };

/// The format named by the path's extension (.png or .exr, any letter case).
/// Throws FileError naming the path and the supported extensions otherwise.
ImageFormat image_format_for(const std::string& path);

/// How hard PNG files are compressed (--png-compression): the pixels are the
/// same whichever is chosen, only the file size and the time change.
enum class PngCompression {
    fast,      ///< "fast": about 1.2x the default's size, fastest
    standard,  ///< "default": the size OpenImageIO's encoder gave, several times faster
    small,     ///< "small": smallest files, slowest
};
/// "fast", "default" or "small"; throws std::invalid_argument otherwise.
PngCompression parse_png_compression(std::string_view text);
const char* to_string(PngCompression compression);

struct ImageWriteOptions {
    PngCompression png_compression = PngCompression::standard;
    int png_bit_depth = 8;  ///< 8 or 16 (values rounded to k/255 or k/65535)
};

/// Writes to a temporary file in the destination folder, then renames it over
/// `path`, so a failure never leaves a truncated image or destroys an old one.
/// Throws FileError.
void write_image(const Image& image, const std::string& path);
void write_image(const Image& image, const std::string& path, const ImageWriteOptions& options);

/// An image as an 8-bit PNG stores it: r, g, b bytes per pixel, rows top to
/// bottom, each the float value clamped to [0,1] and rounded (no gamma curve).
struct Rgb8Image {
    int rows = 0;
    int columns = 0;
    std::vector<std::uint8_t> values;  ///< rows x columns x 3
};

/// `image`'s values as write_image stores them in an 8-bit PNG, into `out`
/// (whose memory is reused). A batch converts in its render lanes and hands
/// the writer thread a quarter of the bytes of the float image.
void convert_to_8_bit(const Image& image, Rgb8Image& out);

/// Writes `image` as an 8-bit RGB PNG, as write_image writes the float image
/// it was converted from (the same file, byte for byte), atomically. `path`
/// must name a .png file. Throws FileError.
void write_png_8_bit(const Rgb8Image& image, const std::string& path,
                     PngCompression compression = PngCompression::standard);

/// Reads an image into float RGB: an 8-bit value k becomes k/255 and a 16-bit
/// one k/65535 (correctly rounded to float), float as stored; grey gives equal
/// r, g, b; alpha is dropped. PNG, JPEG and EXR are read by their own
/// libraries, any other format OpenImageIO understands through OpenImageIO.
/// Throws FileError.
Image read_image(const std::string& path);

/// An image's values as its file stores them (what textures need): 8-bit k
/// becomes the float nearest k/255, 16-bit k the float nearest k/65535, half
/// and float values as they are; no colour transform; grey gives equal r, g,
/// b and alpha is dropped (so `channels` is 3). Row 0 is the top row.
struct StoredImage {
    int rows = 0;
    int columns = 0;
    int channels = 0;           ///< 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA, ...
    std::vector<float> values;  ///< rows x columns x channels, row-major
};

/// Reads any image read_image reads (PNG, JPEG, EXR, others through OpenImageIO) as stored.
/// Throws FileError naming the file and why.
StoredImage read_stored_image(const std::string& path);
/// The same for an image held in memory (embedded in a glTF file); `name`
/// is for messages; PNG and JPEG (glTF's image types), told by their first bytes.
StoredImage read_stored_image(std::string_view bytes, const std::string& name);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_IMAGE_FILE_HPP
