#include "png_encoder.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <libdeflate.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include "phongrast/io/error.hpp"

namespace phongrast::io::detail {
namespace {

constexpr std::size_t kLargestChunk = std::size_t{1} << 30;  // PNG allows 2^31 - 1 bytes per chunk

void put_u32(std::string& out, std::uint32_t value) {
    const char bytes[4] = {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                           static_cast<char>(value >> 8), static_cast<char>(value)};
    out.append(bytes, 4);
}

void put_chunk(std::string& out, const char type[4], const unsigned char* data, std::size_t size) {
    put_u32(out, static_cast<std::uint32_t>(size));
    const std::size_t start = out.size();
    out.append(type, 4);
    if (size > 0) out.append(reinterpret_cast<const char*>(data), size);
    const std::uint32_t crc = libdeflate_crc32(0, out.data() + start, size + 4);
    put_u32(out, crc);
}

std::uint8_t paeth(std::uint8_t a, std::uint8_t b, std::uint8_t c) {
    const int p = int{a} + int{b} - int{c};
    const int pa = std::abs(p - int{a});
    const int pb = std::abs(p - int{b});
    const int pc = std::abs(p - int{c});
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

/// One row filtered into `out` (its first byte the filter type). `previous`
/// is the row above, unfiltered, or null for the first row (PNG's zeros).
void filter_row(PngFilter filter, const std::uint8_t* row, const std::uint8_t* previous, std::size_t size,
                std::size_t bpp, std::uint8_t* out) {
    *out++ = static_cast<std::uint8_t>(filter);
    switch (filter) {
    case PngFilter::none:
        std::memcpy(out, row, size);
        return;
    case PngFilter::sub:
        for (std::size_t i = 0; i < std::min(bpp, size); ++i) out[i] = row[i];
        for (std::size_t i = bpp; i < size; ++i) out[i] = static_cast<std::uint8_t>(row[i] - row[i - bpp]);
        return;
    case PngFilter::up:
        if (!previous) {
            std::memcpy(out, row, size);
            return;
        }
        for (std::size_t i = 0; i < size; ++i) out[i] = static_cast<std::uint8_t>(row[i] - previous[i]);
        return;
    case PngFilter::average:
        for (std::size_t i = 0; i < size; ++i) {
            const int left = i >= bpp ? row[i - bpp] : 0;
            const int up = previous ? previous[i] : 0;
            out[i] = static_cast<std::uint8_t>(row[i] - ((left + up) >> 1));
        }
        return;
    case PngFilter::paeth:
        for (std::size_t i = 0; i < size; ++i) {
            const std::uint8_t left = i >= bpp ? row[i - bpp] : 0;
            const std::uint8_t up = previous ? previous[i] : 0;
            const std::uint8_t corner = previous && i >= bpp ? previous[i - bpp] : 0;
            out[i] = static_cast<std::uint8_t>(row[i] - paeth(left, up, corner));
        }
        return;
    }
}

/// The `up` filter of a row of 16-bit values, straight from the machine's
/// words: one pass instead of a big-endian copy and a filter pass over it
/// (the copy cost a quarter of the encoder's time at 16 bits). Each of the
/// two bytes differs from the byte above on its own, as PNG's filters work
/// byte by byte.
void up_filter_words(const std::uint16_t* row, const std::uint16_t* previous, std::size_t count, std::uint8_t* out) {
    *out++ = static_cast<std::uint8_t>(PngFilter::up);
    if (!previous) {
        for (std::size_t i = 0; i < count; ++i) {
            out[2 * i] = static_cast<std::uint8_t>(row[i] >> 8);
            out[2 * i + 1] = static_cast<std::uint8_t>(row[i]);
        }
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        out[2 * i] = static_cast<std::uint8_t>((row[i] >> 8) - (previous[i] >> 8));
        out[2 * i + 1] = static_cast<std::uint8_t>(row[i] - previous[i]);
    }
}

struct CompressorDeleter {
    void operator()(libdeflate_compressor* compressor) const { libdeflate_free_compressor(compressor); }
};

/// libdeflate's compressor for `level`, kept per thread (a level-12 one
/// allocates about 1 MB; a batch's writer thread reuses it image after image).
libdeflate_compressor& compressor_for(int level) {
    thread_local std::array<std::unique_ptr<libdeflate_compressor, CompressorDeleter>, 13> compressors;
    auto& slot = compressors.at(static_cast<std::size_t>(level));
    if (!slot) {
        slot.reset(libdeflate_alloc_compressor(level));
        if (!slot) throw std::bad_alloc();
    }
    return *slot;
}

}  // namespace

PngSettings png_settings(PngCompression compression) {
    // Chosen with bench/png_encode.cpp on rendered images (docs/startup.md):
    // `up` is the best single filter on renders (flat backgrounds, smooth
    // shading) and costs one subtraction a byte. The default is the fastest
    // level within 10% of the size OpenImageIO's writer gave: 2 for 8-bit
    // samples, 3 for 16-bit ones (a dataset's depth and id images 0-7%
    // larger, 16-bit colour 8-9%; at 2, colour is 12-13% larger).
    switch (compression) {
    case PngCompression::fast: return {1, PngFilter::up};
    case PngCompression::small: return {9, PngFilter::up};
    case PngCompression::standard: break;
    }
    return {2, PngFilter::up, 3};
}

namespace {

/// std::allocator whose resize() leaves new bytes unset instead of zeroing
/// them: the filtered rows are all written before they are read, and of
/// the compressed buffer (deflate's worst case) only the stream's bytes are
/// written. Zeroing touched every page of both in a one-off process
/// (`phongrast render ... -o t.png`: about 100 fresh pages at 256x256, most
/// of them never needed for the stream).
template <typename T>
struct UninitializedAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <typename U>
    UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
    template <typename U>
    void construct(U* place) noexcept {
        ::new (static_cast<void*>(place)) U;  // default-initialised: no zeroing
    }
    template <typename U, typename... Args>
    void construct(U* place, Args&&... args) {
        ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
    }
};
using Bytes = std::vector<std::uint8_t, UninitializedAllocator<std::uint8_t>>;

/// The zlib stream of the filtered rows, in a buffer kept per thread: a batch
/// writes image after image, and fresh megabyte buffers cost more in page
/// faults and zero-filling than the encoding itself. Returns its size.
std::size_t compress_rows(const PngPixels& pixels, PngSettings settings, Bytes*& out) {
    if (pixels.columns < 1 || pixels.rows < 1) throw std::invalid_argument("PNG: the image is empty");
    if (pixels.channels < 1 || pixels.channels > 4) throw std::invalid_argument("PNG: 1 to 4 channels");
    if (pixels.bit_depth != 8 && pixels.bit_depth != 16) throw std::invalid_argument("PNG: 8 or 16 bits");
    const std::size_t bytes_per_value = static_cast<std::size_t>(pixels.bit_depth / 8);
    const int level = bytes_per_value == 2 && settings.level_16_bit >= 0 ? settings.level_16_bit : settings.level;
    if (level < 0 || level > 12) throw std::invalid_argument("PNG: deflate level 0 to 12");
    const std::size_t bpp = static_cast<std::size_t>(pixels.channels) * bytes_per_value;
    const std::size_t row_size = static_cast<std::size_t>(pixels.columns) * bpp;
    const std::size_t rows = static_cast<std::size_t>(pixels.rows);

    // The rows as PNG stores them (16-bit values big-endian), each filtered behind its type byte.
    thread_local Bytes filtered;
    thread_local Bytes compressed;
    thread_local std::vector<std::uint8_t> swapped[2];
    filtered.resize((row_size + 1) * rows);
    const std::uint8_t* previous = nullptr;
    const bool words_up = bytes_per_value == 2 && settings.filter == PngFilter::up;
    for (std::size_t y = 0; y < rows; ++y) {
        const std::uint8_t* row = static_cast<const std::uint8_t*>(pixels.data) + y * row_size;
        if (words_up) {
            const auto* words = reinterpret_cast<const std::uint16_t*>(row);
            up_filter_words(words, y > 0 ? words - row_size / 2 : nullptr, row_size / 2, &filtered[y * (row_size + 1)]);
            continue;
        }
        if (bytes_per_value == 2) {
            std::vector<std::uint8_t>& big_endian = swapped[y % 2];
            big_endian.resize(row_size);
            const std::uint16_t* values = reinterpret_cast<const std::uint16_t*>(row);
            for (std::size_t i = 0; i < row_size / 2; ++i) {
                big_endian[2 * i] = static_cast<std::uint8_t>(values[i] >> 8);
                big_endian[2 * i + 1] = static_cast<std::uint8_t>(values[i]);
            }
            row = big_endian.data();
        }
        filter_row(settings.filter, row, previous, row_size, bpp, &filtered[y * (row_size + 1)]);
        previous = row;
    }

    libdeflate_compressor& compressor = compressor_for(level);
    compressed.resize(libdeflate_zlib_compress_bound(&compressor, filtered.size()));
    const std::size_t compressed_size =
        libdeflate_zlib_compress(&compressor, filtered.data(), filtered.size(), compressed.data(), compressed.size());
    if (compressed_size == 0) throw std::runtime_error("PNG: deflate failed");
    out = &compressed;
    return compressed_size;
}

/// Everything before the image data: the signature and the IHDR chunk.
std::string png_header(const PngPixels& pixels) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const std::uint8_t colour_types[5] = {0, 0, 4, 2, 6};  // by channel count: grey, grey+alpha, RGB, RGBA
    std::string out(reinterpret_cast<const char*>(signature), 8);
    unsigned char header[13] = {};
    for (int i = 0; i < 4; ++i) {
        header[i] = static_cast<unsigned char>(static_cast<std::uint32_t>(pixels.columns) >> (24 - 8 * i));
        header[4 + i] = static_cast<unsigned char>(static_cast<std::uint32_t>(pixels.rows) >> (24 - 8 * i));
    }
    header[8] = static_cast<unsigned char>(pixels.bit_depth);
    header[9] = colour_types[pixels.channels];
    // header[10..12]: deflate compression, adaptive filtering (method 0), no interlace.
    put_chunk(out, "IHDR", header, sizeof header);
    return out;
}

}  // namespace

std::string encode_png(const PngPixels& pixels, PngSettings settings) {
    Bytes* compressed = nullptr;
    const std::size_t compressed_size = compress_rows(pixels, settings, compressed);
    std::string out = png_header(pixels);
    out.reserve(out.size() + compressed_size + 24 + 12 * (compressed_size / kLargestChunk));
    for (std::size_t at = 0; at < compressed_size; at += kLargestChunk) {
        put_chunk(out, "IDAT", compressed->data() + at, std::min(kLargestChunk, compressed_size - at));
    }
    put_chunk(out, "IEND", nullptr, 0);
    return out;
}

void write_png(const std::string& file, const std::string& path, const PngPixels& pixels, PngSettings settings) {
    Bytes* compressed = nullptr;
    const std::size_t compressed_size = compress_rows(pixels, settings, compressed);
    // The image data goes from the compressor's buffer to the file without a
    // copy, the whole file in one writev (stdio made several writes and an
    // fstat per image). Around the pieces of image data: frames[0] (the
    // header, then the first IDAT's length and type), then each chunk's CRC
    // followed by the next chunk's length and type, the last CRC by IEND.
    std::vector<std::string> frames(1, png_header(pixels));
    for (std::size_t at = 0; at < compressed_size; at += kLargestChunk) {
        const std::size_t size = std::min(kLargestChunk, compressed_size - at);
        put_u32(frames.back(), static_cast<std::uint32_t>(size));
        frames.back() += "IDAT";
        const std::uint32_t crc = libdeflate_crc32(libdeflate_crc32(0, "IDAT", 4), compressed->data() + at, size);
        frames.emplace_back();
        put_u32(frames.back(), crc);
    }
    put_chunk(frames.back(), "IEND", nullptr, 0);
    std::vector<iovec> parts;
    parts.push_back({frames[0].data(), frames[0].size()});
    std::size_t frame = 1;
    for (std::size_t at = 0; at < compressed_size; at += kLargestChunk, ++frame) {
        parts.push_back({compressed->data() + at, std::min(kLargestChunk, compressed_size - at)});
        parts.push_back({frames[frame].data(), frames[frame].size()});
    }
    // Not O_TRUNC: on ext4, truncating a file to size 0 marks it to have its
    // data written out when it is closed (auto_da_alloc, meant for programs
    // that rewrite a file in place without fsync), so every image's close()
    // started its disk write on the spot (a batch writes images one after
    // another). The file is replace_file_atomically()'s new, empty temporary;
    // one that is not empty is truncated all the same.
    const int out = ::open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
    if (out < 0) throw FileError(path + ": cannot write: " + std::strerror(errno));
    struct stat status {};
    if (::fstat(out, &status) != 0 || (status.st_size != 0 && ::ftruncate(out, 0) != 0)) {
        const int error = errno;
        ::close(out);
        throw FileError(path + ": cannot write: " + std::strerror(error));
    }
    bool written = true;
    for (std::size_t first = 0; written && first < parts.size();) {
        const int count = static_cast<int>(std::min<std::size_t>(parts.size() - first, IOV_MAX));
        const ssize_t wrote = ::writev(out, &parts[first], count);
        if (wrote < 0 && errno == EINTR) continue;
        if (wrote <= 0) {
            written = false;
            break;
        }
        // Skip what was written (a short write leaves part of one piece).
        auto left = static_cast<std::size_t>(wrote);
        while (first < parts.size() && left >= parts[first].iov_len) left -= parts[first++].iov_len;
        if (left > 0) {
            parts[first].iov_base = static_cast<char*>(parts[first].iov_base) + left;
            parts[first].iov_len -= left;
        }
    }
    const int write_errno = errno;
    const bool closed = ::close(out) == 0;
    if (!written || !closed) throw FileError(path + ": write failed: " + std::strerror(written ? errno : write_errno));
}

std::uint16_t to_16_bit(float value) {
    // As to_8_bit (png_bytes.hpp): std::lround's rounding, exact in double for a product below 65536.
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    return static_cast<std::uint16_t>(static_cast<int>(static_cast<double>(clamped * 65535.0f) + 0.5));
}

}  // namespace phongrast::io::detail
