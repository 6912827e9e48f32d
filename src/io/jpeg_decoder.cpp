// JPEG in through libjpeg-turbo, with the library's default decoding (the
// accurate integer IDCT, smooth chroma upsampling: what OpenImageIO's JPEG
// reader asks of the same library, so the texels are the same).
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <jpeglib.h>

#include "image_decoders.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io::detail {
namespace {

/// libjpeg reports errors through error_exit, which must not return: it
/// jumps back to decode_jpeg's setjmp with the message kept here.
struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
    ErrorManager* errors = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->jump, 1);
}

void on_message(j_common_ptr, int) {}  // warnings (corrupt but readable data) are not printed

/// The part between setjmp and the end: no object with a destructor lives
/// here (longjmp would skip it); `rgb` is sized before and filled in place.
/// Returns false on a libjpeg error (message in `errors`), true otherwise;
/// `columns`/`rows` 0 means an unsupported colour space.
bool run_decoder(const char* data, std::size_t size, ErrorManager& errors, std::vector<std::uint8_t>& rgb,
                 int& rows, int& columns) {
    jpeg_decompress_struct info;
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = on_error;
    errors.base.emit_message = on_message;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(data), static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {
        jpeg_destroy_decompress(&info);
        rows = columns = 0;
        return true;
    }
    info.out_color_space = JCS_RGB;  // grey is repeated into r, g, b by the library
    jpeg_calc_output_dimensions(&info);
    rows = static_cast<int>(info.output_height);
    columns = static_cast<int>(info.output_width);
    if (rows > 32768 || columns > 32768) {
        jpeg_destroy_decompress(&info);
        return true;  // the caller refuses the size
    }
    rgb.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns) * 3);
    jpeg_start_decompress(&info);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = rgb.data() + static_cast<std::size_t>(info.output_scanline) * static_cast<std::size_t>(columns) * 3;
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return true;
}

}  // namespace

bool looks_like_jpeg(const char* data, std::size_t size) {
    return size >= 3 && static_cast<unsigned char>(data[0]) == 0xff && static_cast<unsigned char>(data[1]) == 0xd8 &&
           static_cast<unsigned char>(data[2]) == 0xff;
}

Image decode_jpeg(const char* data, std::size_t size, const std::string& path, bool& unsupported) {
    ErrorManager errors{};
    std::vector<std::uint8_t> rgb;
    // A header that promises a huge image: reserve nothing before the size is checked.
    int rows = 0;
    int columns = 0;
    if (!run_decoder(data, size, errors, rgb, rows, columns)) {
        throw FileError(path + ": cannot read JPEG: " + errors.message);
    }
    unsupported = rows == 0 && columns == 0;
    if (unsupported) return Image();
    if (rows > 32768 || columns > 32768) {
        throw FileError(path + ": JPEG of " + std::to_string(columns) + "x" + std::to_string(rows) +
                        " pixels; at most 32768 per side is read");
    }
    Image image(rows, columns);
    float to_float[256];
    for (int k = 0; k < 256; ++k) to_float[k] = static_cast<float>(k) / 255.0f;
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        for (int c = 0; c < 3; ++c) image.pixels[p][c] = to_float[rgb[3 * p + static_cast<std::size_t>(c)]];
    }
    return image;
}

}  // namespace phongrast::io::detail
