// PNG in through libspng: every colour type and bit depth decoded to RGBA
// (8-bit, or 16-bit for 16-bit files), no gamma or transparency applied.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <spng.h>

#include "image_decoders.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io::detail {
namespace {

struct ContextDeleter {
    void operator()(spng_ctx* context) const { spng_ctx_free(context); }
};

void check(int status, const std::string& path) {
    if (status != 0) throw FileError(path + ": cannot read PNG: " + spng_strerror(status));
}

}  // namespace

bool looks_like_png(const char* data, std::size_t size) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return size >= 8 && std::equal(signature, signature + 8, reinterpret_cast<const unsigned char*>(data));
}

Image decode_png(const char* data, std::size_t size, const std::string& path) {
    std::unique_ptr<spng_ctx, ContextDeleter> context(spng_ctx_new(0));
    if (!context) throw FileError(path + ": cannot read PNG: out of memory");
    spng_set_crc_action(context.get(), SPNG_CRC_ERROR, SPNG_CRC_ERROR);
    check(spng_set_png_buffer(context.get(), data, size), path);
    spng_ihdr header{};
    check(spng_get_ihdr(context.get(), &header), path);
    const bool sixteen = header.bit_depth == 16;
    const int format = sixteen ? SPNG_FMT_RGBA16 : SPNG_FMT_RGBA8;
    std::size_t bytes = 0;
    check(spng_decoded_image_size(context.get(), format, &bytes), path);
    const int rows = static_cast<int>(header.height);
    const int columns = static_cast<int>(header.width);
    if (header.height > 32768 || header.width > 32768) {
        throw FileError(path + ": PNG of " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                        " pixels; at most 32768 per side is read");
    }
    Image image(rows, columns);
    const std::size_t pixels = image.pixels.size();
    if (sixteen) {
        std::vector<std::uint16_t> values(bytes / 2);
        check(spng_decode_image(context.get(), values.data(), bytes, format, 0), path);
        for (std::size_t p = 0; p < pixels; ++p) {
            for (int c = 0; c < 3; ++c) {
                image.pixels[p][c] = static_cast<float>(values[4 * p + static_cast<std::size_t>(c)]) / 65535.0f;
            }
        }
    } else {
        std::vector<std::uint8_t> values(bytes);
        check(spng_decode_image(context.get(), values.data(), bytes, format, 0), path);
        float to_float[256];
        for (int k = 0; k < 256; ++k) to_float[k] = static_cast<float>(k) / 255.0f;
        for (std::size_t p = 0; p < pixels; ++p) {
            for (int c = 0; c < 3; ++c) image.pixels[p][c] = to_float[values[4 * p + static_cast<std::size_t>(c)]];
        }
    }
    return image;
}

}  // namespace phongrast::io::detail
