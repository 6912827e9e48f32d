// Small PNG files written byte by byte for the texture tests: any bit depth
// (8, 16) and colour type (grey, grey + alpha, RGB, RGBA), stored (not
// compressed) deflate blocks, so the tests need no image library and the
// values they check are exactly the bytes they wrote.
#ifndef PHONGRAST_TESTS_PNG_TEST_WRITER_HPP
#define PHONGRAST_TESTS_PNG_TEST_WRITER_HPP

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace png_test {

inline std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= static_cast<unsigned char>(c);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

inline void put_u32(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((value >> shift) & 0xff));
}

inline void chunk(std::string& out, const char* type, const std::string& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::string typed = std::string(type) + data;
    out += typed;
    put_u32(out, crc32(typed));
}

/// PNG colour types: 0 grey, 4 grey + alpha, 2 RGB, 6 RGBA.
inline int channels_of(int color_type) { return color_type == 0 ? 1 : color_type == 4 ? 2 : color_type == 2 ? 3 : 4; }

/// A PNG of `rows` x `columns`; `samples` holds rows x columns x channels
/// values (each < 2^bits), row 0 the top row.
inline std::string encode(int rows, int columns, int bits, int color_type, const std::vector<std::uint16_t>& samples) {
    std::string raw;
    const int channels = channels_of(color_type);
    std::size_t at = 0;
    for (int r = 0; r < rows; ++r) {
        raw.push_back('\0');  // filter: none
        for (int i = 0; i < columns * channels; ++i) {
            const std::uint16_t v = samples[at++];
            if (bits == 16) raw.push_back(static_cast<char>(v >> 8));
            raw.push_back(static_cast<char>(v & 0xff));
        }
    }
    std::string zlib = "\x78\x01";
    for (std::size_t start = 0; start < raw.size() || start == 0; start += 65535) {
        const std::size_t length = std::min<std::size_t>(65535, raw.size() - start);
        const bool last = start + length >= raw.size();
        zlib.push_back(last ? '\x01' : '\x00');
        zlib.push_back(static_cast<char>(length & 0xff));
        zlib.push_back(static_cast<char>(length >> 8));
        zlib.push_back(static_cast<char>(~length & 0xff));
        zlib.push_back(static_cast<char>((~length >> 8) & 0xff));
        zlib += raw.substr(start, length);
        if (raw.empty()) break;
    }
    std::uint32_t a = 1, b = 0;
    for (const char c : raw) {
        a = (a + static_cast<unsigned char>(c)) % 65521;
        b = (b + a) % 65521;
    }
    put_u32(zlib, (b << 16) | a);
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string header;
    put_u32(header, static_cast<std::uint32_t>(columns));
    put_u32(header, static_cast<std::uint32_t>(rows));
    header.push_back(static_cast<char>(bits));
    header.push_back(static_cast<char>(color_type));
    header += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
    chunk(png, "IHDR", header);
    chunk(png, "IDAT", zlib);
    chunk(png, "IEND", "");
    return png;
}

}  // namespace png_test

#endif  // PHONGRAST_TESTS_PNG_TEST_WRITER_HPP
