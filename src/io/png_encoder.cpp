#include "png_encoder.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <libdeflate.h>
#include <tbb/task_group.h>
#include <zlib.h>
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
/// (the copy cost about a sixth of the encoder's time at 16 bits). Each of the
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
    // Chosen with bench/png_encode.cpp on rendered images and a dataset's
    // depth and id images (docs/startup.md): `up` is the best single filter
    // on them (flat backgrounds, smooth shading) and costs one subtraction a
    // byte. The default keeps within 10% of the size OpenImageIO's writer
    // gave: libdeflate level 2 for 8-bit samples, 4 for 16-bit ones (at 3 an
    // id image came out 11% larger). A large image's first rows go to zlib
    // (level 4, 16-bit 5; fast: 1), deflated while libdeflate deflates the
    // rest. `small` stays one libdeflate stream.
    switch (compression) {
    case PngCompression::fast: return {1, PngFilter::up, -1, 1};
    case PngCompression::small: return {9, PngFilter::up};
    case PngCompression::standard: break;
    }
    return {2, PngFilter::up, 4, 4, 5};
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

/// Rows [first, end) as PNG stores them (16-bit values big-endian), each
/// filtered behind its type byte, into `filtered` at row `first`'s place.
void filter_rows(const PngPixels& pixels, PngFilter filter, std::size_t first, std::size_t end, std::uint8_t* filtered) {
    const std::size_t bytes_per_value = static_cast<std::size_t>(pixels.bit_depth / 8);
    const std::size_t bpp = static_cast<std::size_t>(pixels.channels) * bytes_per_value;
    const std::size_t row_size = static_cast<std::size_t>(pixels.columns) * bpp;
    const auto* image = static_cast<const std::uint8_t*>(pixels.data);
    if (bytes_per_value == 2 && filter == PngFilter::up) {
        for (std::size_t y = first; y < end; ++y) {
            const auto* words = reinterpret_cast<const std::uint16_t*>(image + y * row_size);
            up_filter_words(words, y > 0 ? words - row_size / 2 : nullptr, row_size / 2, filtered + y * (row_size + 1));
        }
        return;
    }
    if (bytes_per_value == 1) {
        for (std::size_t y = first; y < end; ++y) {
            filter_row(filter, image + y * row_size, y > 0 ? image + (y - 1) * row_size : nullptr, row_size, bpp,
                       filtered + y * (row_size + 1));
        }
        return;
    }
    // Other filters of 16-bit rows: each row copied big-endian first (two copies, the row above kept).
    std::vector<std::uint8_t> swapped[2];
    const std::uint8_t* previous = nullptr;
    const auto big_endian_row = [&](std::size_t y, std::vector<std::uint8_t>& into) {
        into.resize(row_size);
        const auto* values = reinterpret_cast<const std::uint16_t*>(image + y * row_size);
        for (std::size_t i = 0; i < row_size / 2; ++i) {
            into[2 * i] = static_cast<std::uint8_t>(values[i] >> 8);
            into[2 * i + 1] = static_cast<std::uint8_t>(values[i]);
        }
        return into.data();
    };
    if (first > 0) previous = big_endian_row(first - 1, swapped[(first - 1) % 2]);
    for (std::size_t y = first; y < end; ++y) {
        const std::uint8_t* row = big_endian_row(y, swapped[y % 2]);
        filter_row(filter, row, previous, row_size, bpp, filtered + y * (row_size + 1));
        previous = row;
    }
}

struct ZStreamDeleter {
    void operator()(z_stream* stream) const {
        deflateEnd(stream);
        delete stream;
    }
};

/// The first piece of a split image: raw deflate by zlib, ended by a sync
/// flush (an empty stored block: byte-aligned, not final) so that
/// libdeflate's piece can follow it in the same stream. zlib's state is
/// kept per thread and level (about 270 KB), reset for each image.
std::size_t deflate_head(const std::uint8_t* in, std::size_t size, int level, Bytes& out) {
    thread_local std::array<std::unique_ptr<z_stream, ZStreamDeleter>, 10> streams;
    auto& stream = streams.at(static_cast<std::size_t>(level));
    if (!stream) {
        auto fresh = std::make_unique<z_stream>();
        // windowBits -15: raw deflate, no zlib header or trailer (written around both pieces).
        if (deflateInit2(fresh.get(), level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::bad_alloc();
        stream.reset(fresh.release());
    } else if (deflateReset(stream.get()) != Z_OK) {
        throw std::runtime_error("PNG: zlib could not reset");
    }
    if (size > UINT32_MAX / 2) throw std::invalid_argument("PNG: image too large to split");
    out.resize(deflateBound(stream.get(), static_cast<uLong>(size)) + 16);  // + the sync flush's empty block
    stream->next_in = const_cast<Bytef*>(in);
    stream->avail_in = static_cast<uInt>(size);
    stream->next_out = out.data();
    stream->avail_out = static_cast<uInt>(out.size());
    if (deflate(stream.get(), Z_SYNC_FLUSH) != Z_OK || stream->avail_in != 0) {
        throw std::runtime_error("PNG: zlib's deflate failed");
    }
    return out.size() - stream->avail_out;
}

/// The zlib stream of the filtered rows, in a buffer kept per thread: a batch
/// writes image after image, and fresh megabyte buffers cost more in page
/// faults and zero-filling than the encoding itself. Returns its size.
///
/// An image of at least kSplitBytes filtered bytes (with a head level set) is
/// deflated in two pieces, at once on two threads when allowed: its first
/// head_rows_per_mille() of the rows by zlib (deflate_head), the rest by
/// libdeflate as the final piece, with no reference back into the first (it
/// has no dictionary input: a few bytes lost at one boundary). The stream is
/// the zlib header, both pieces and the Adler-32 of all the filtered bytes.
/// The split depends only on the image's size, so the file's bytes do not
/// depend on the threads.
std::size_t compress_rows(const PngPixels& pixels, PngSettings settings, Bytes*& out) {
    if (pixels.columns < 1 || pixels.rows < 1) throw std::invalid_argument("PNG: the image is empty");
    if (pixels.channels < 1 || pixels.channels > 4) throw std::invalid_argument("PNG: 1 to 4 channels");
    if (pixels.bit_depth != 8 && pixels.bit_depth != 16) throw std::invalid_argument("PNG: 8 or 16 bits");
    const std::size_t bytes_per_value = static_cast<std::size_t>(pixels.bit_depth / 8);
    const int level = bytes_per_value == 2 && settings.level_16_bit >= 0 ? settings.level_16_bit : settings.level;
    if (level < 0 || level > 12) throw std::invalid_argument("PNG: deflate level 0 to 12");
    const int head_level =
        bytes_per_value == 2 && settings.head_zlib_level_16_bit >= 0 ? settings.head_zlib_level_16_bit : settings.head_zlib_level;
    if (head_level < 0 || head_level > 9) throw std::invalid_argument("PNG: zlib level 0 to 9");
    const std::size_t row_size = static_cast<std::size_t>(pixels.columns) * static_cast<std::size_t>(pixels.channels) * bytes_per_value;
    const std::size_t rows = static_cast<std::size_t>(pixels.rows);

    thread_local Bytes filtered;
    thread_local Bytes compressed;
    filtered.resize((row_size + 1) * rows);
    const std::size_t head_rows =
        // (Past 4 GiB of rows, zlib's piece would outgrow its 32-bit counts: one piece.)
        head_level > 0 && filtered.size() >= kSplitBytes && filtered.size() <= UINT32_MAX && rows >= 8
            ? rows * static_cast<std::size_t>(head_rows_per_mille(head_level)) / 1000
            : 0;
    if (head_rows == 0) {
        filter_rows(pixels, settings.filter, 0, rows, filtered.data());
        libdeflate_compressor& compressor = compressor_for(level);
        compressed.resize(libdeflate_zlib_compress_bound(&compressor, filtered.size()));
        const std::size_t compressed_size =
            libdeflate_zlib_compress(&compressor, filtered.data(), filtered.size(), compressed.data(), compressed.size());
        if (compressed_size == 0) throw std::runtime_error("PNG: deflate failed");
        out = &compressed;
        return compressed_size;
    }

    const std::size_t head_size = head_rows * (row_size + 1);
    const std::size_t tail_size = filtered.size() - head_size;
    thread_local Bytes head;
    thread_local Bytes tail;
    // The lambdas name this thread's buffers through these references: a
    // thread_local named inside a lambda that runs on another thread would be
    // that thread's own.
    std::uint8_t* const filtered_rows = filtered.data();
    Bytes& head_out = head;
    Bytes& tail_out = tail;
    std::size_t head_deflated = 0, tail_deflated = 0;
    std::uint32_t head_adler = 1, tail_adler = 1;
    // Each piece filters its own rows (the row above the tail's first is the image's, not filtered).
    const auto deflate_first_rows = [&] {
        filter_rows(pixels, settings.filter, 0, head_rows, filtered_rows);
        head_adler = libdeflate_adler32(1, filtered_rows, head_size);
        head_deflated = deflate_head(filtered_rows, head_size, head_level, head_out);
    };
    const auto deflate_last_rows = [&] {
        filter_rows(pixels, settings.filter, head_rows, rows, filtered_rows);
        const std::uint8_t* in = filtered_rows + head_size;
        tail_adler = libdeflate_adler32(1, in, tail_size);
        libdeflate_compressor& compressor = compressor_for(level);
        tail_out.resize(libdeflate_deflate_compress_bound(&compressor, tail_size));
        tail_deflated = libdeflate_deflate_compress(&compressor, in, tail_size, tail_out.data(), tail_out.size());
        if (tail_deflated == 0) throw std::runtime_error("PNG: deflate failed");
    };
    if (settings.concurrent) {
        tbb::task_group both;
        both.run(deflate_first_rows);
        // The first piece's task uses this frame's locals: it is waited for
        // even when the last piece throws (wait() rethrows the task's own).
        std::exception_ptr last_rows_error;
        try {
            deflate_last_rows();
        } catch (...) {
            last_rows_error = std::current_exception();
        }
        both.wait();
        if (last_rows_error) std::rethrow_exception(last_rows_error);
    } else {
        deflate_first_rows();
        deflate_last_rows();
    }
    // zlib header: deflate with a 32 KB window, default-level flag, (0x78 << 8 | 0x9c) % 31 == 0.
    compressed.resize(2 + head_deflated + tail_deflated + 4);
    compressed[0] = 0x78;
    compressed[1] = 0x9c;
    std::memcpy(compressed.data() + 2, head.data(), head_deflated);
    std::memcpy(compressed.data() + 2 + head_deflated, tail.data(), tail_deflated);
    const auto adler = static_cast<std::uint32_t>(adler32_combine(head_adler, tail_adler, static_cast<z_off_t>(tail_size)));
    std::uint8_t* trailer = compressed.data() + 2 + head_deflated + tail_deflated;
    for (int i = 0; i < 4; ++i) trailer[i] = static_cast<std::uint8_t>(adler >> (24 - 8 * i));
    out = &compressed;
    return compressed.size();
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
