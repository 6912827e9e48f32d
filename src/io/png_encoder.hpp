// PNG encoding with libdeflate (internal header): one fixed row filter and
// one deflate call per image, no per-row filter search. bench/png_encode.cpp
// measured the choices (docs/startup.md, "PNG encoding").
#ifndef PHONGRAST_SRC_IO_PNG_ENCODER_HPP
#define PHONGRAST_SRC_IO_PNG_ENCODER_HPP

#include <cstddef>
#include <cstdint>
#include <string>

#include "phongrast/io/image_file.hpp"

namespace phongrast::io::detail {

/// Pixels to encode: `channels` (1 grey, 2 grey+alpha, 3 RGB, 4 RGBA)
/// interleaved, rows top to bottom, no padding. 8-bit: one byte per value;
/// 16-bit: one std::uint16_t per value in the machine's byte order.
struct PngPixels {
    const void* data = nullptr;
    int columns = 0;
    int rows = 0;
    int channels = 3;
    int bit_depth = 8;
};

/// The PNG row filter used for every row (the PNG specification's numbers).
enum class PngFilter : std::uint8_t { none = 0, sub = 1, up = 2, average = 3, paeth = 4 };

/// Deflate level and filter for each --png-compression choice.
struct PngSettings {
    int level;
    PngFilter filter;
    /// The level for 16-bit samples, whose low bytes compress worse (-1: `level`).
    int level_16_bit = -1;
    /// zlib's level for the first rows of a large image, deflated beside
    /// libdeflate's for the rest (0: the whole image in one libdeflate call).
    /// libdeflate cannot end a piece without ending the stream; zlib can.
    int head_zlib_level = 0;
    /// The same for 16-bit samples (-1: `head_zlib_level`).
    int head_zlib_level_16_bit = -1;
    /// Whether the two pieces of such an image may be deflated at once on
    /// two threads (oneTBB's); the file's bytes are the same either way.
    bool concurrent = true;
};

/// The share of a large image's rows deflated by zlib, in thousandths, for
/// zlib's `level`: both pieces should take about as long. zlib at level 4
/// costs about 1.6x libdeflate's time per byte at 2-4, at 5 about 2x
/// (bench_png_encode --survey-split): 3/8 and 1/3 of the rows.
constexpr int head_rows_per_mille(int level) { return level >= 5 ? 333 : 375; }
/// Images with fewer filtered bytes than this are deflated in one piece: below
/// it the second thread's start costs more than it saves.
constexpr std::size_t kSplitBytes = std::size_t{1} << 20;
PngSettings png_settings(PngCompression compression);

/// The complete PNG file: signature, IHDR, IDAT chunks, IEND.
/// Throws std::invalid_argument for sizes or depths PNG cannot hold.
std::string encode_png(const PngPixels& pixels, PngSettings settings);

/// Encodes and writes the PNG to `file` (a temporary file, normally new and
/// empty: replace_file_atomically()'s; `path` names the destination in
/// errors). Throws FileError.
void write_png(const std::string& file, const std::string& path, const PngPixels& pixels, PngSettings settings);

/// [0,1] clamp then round to 16 bits, no gamma curve; NaN (never expected) becomes 0.
std::uint16_t to_16_bit(float value);

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_PNG_ENCODER_HPP
