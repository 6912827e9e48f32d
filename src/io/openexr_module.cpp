// phongrast_openexr.so: EXR files through OpenEXR, behind the plain C
// table of openexr_module.hpp (exr_file.cpp loads it on first use).
#include "openexr_module.hpp"

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

namespace {

void set_error(char* error, std::size_t size, const char* message) {
    if (error != nullptr && size > 0) std::snprintf(error, size, "%s", message);
}

/// Runs `work` and returns its result; an exception (none may cross the C
/// table) becomes its message in `error` and the result `failed`.
template <typename Result, typename Work>
Result guarded(Result failed, char* error, std::size_t error_size, Work&& work) {
    try {
        return work();
    } catch (const std::exception& failure) {
        set_error(error, error_size, failure.what());
    } catch (...) {
        set_error(error, error_size, "unknown error");
    }
    return failed;
}

Imf::PixelType pixel_type(const PhongrastExrChannel& channel) {
    return channel.unsigned_int != 0 ? Imf::UINT : Imf::FLOAT;
}

/// The frame buffer of `channels` for a data window starting at (x0, y0).
Imf::FrameBuffer frame_buffer(const PhongrastExrChannel* channels, std::size_t count, int columns, int x0, int y0) {
    Imf::FrameBuffer buffer;
    for (std::size_t i = 0; i < count; ++i) {
        const PhongrastExrChannel& channel = channels[i];
        const std::size_t row_stride = channel.stride * static_cast<std::size_t>(columns);
        // OpenEXR addresses pixel (x, y) as base + x * xStride + y * yStride.
        char* origin = channel.base - static_cast<std::ptrdiff_t>(x0) * static_cast<std::ptrdiff_t>(channel.stride) -
                       static_cast<std::ptrdiff_t>(y0) * static_cast<std::ptrdiff_t>(row_stride);
        buffer.insert(channel.name, Imf::Slice(pixel_type(channel), origin, channel.stride, row_stride));
    }
    return buffer;
}

struct Reader {
    explicit Reader(const char* file) : input(file) {}
    Imf::InputFile input;
    std::vector<std::string> names;
};

int write(const char* file, int columns, int rows, const PhongrastExrChannel* channels, std::size_t count,
          char* error, std::size_t error_size) {
    return guarded(1, error, error_size, [&] {
        Imf::Header header(columns, rows);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (std::size_t i = 0; i < count; ++i) {
            header.channels().insert(channels[i].name, Imf::Channel(pixel_type(channels[i])));
        }
        Imf::OutputFile output(file, header);
        output.setFrameBuffer(frame_buffer(channels, count, columns, 0, 0));
        output.writePixels(rows);
        return 0;
    });
}

void* open(const char* file, int* columns, int* rows, char* error, std::size_t error_size) {
    return guarded<void*>(nullptr, error, error_size, [&]() -> void* {
        auto reader = std::make_unique<Reader>(file);
        const Imath::Box2i window = reader->input.header().dataWindow();
        *columns = window.max.x - window.min.x + 1;
        *rows = window.max.y - window.min.y + 1;
        const Imf::ChannelList& list = reader->input.header().channels();
        for (auto it = list.begin(); it != list.end(); ++it) reader->names.push_back(it.name());
        return reader.release();
    });
}

std::size_t channel_count(void* handle) { return static_cast<Reader*>(handle)->names.size(); }

const char* channel_name(void* handle, std::size_t index) {
    return static_cast<Reader*>(handle)->names.at(index).c_str();
}

int read(void* handle, const PhongrastExrChannel* channels, std::size_t count, char* error, std::size_t error_size) {
    return guarded(1, error, error_size, [&] {
        Imf::InputFile& input = static_cast<Reader*>(handle)->input;
        const Imath::Box2i window = input.header().dataWindow();
        const int columns = window.max.x - window.min.x + 1;
        input.setFrameBuffer(frame_buffer(channels, count, columns, window.min.x, window.min.y));
        input.readPixels(window.min.y, window.max.y);
        return 0;
    });
}

void close(void* handle) { delete static_cast<Reader*>(handle); }

const PhongrastOpenExrModule kModule{phongrast::io::detail::kPhongrastOpenExrModuleVersion,
                                     write,
                                     open,
                                     channel_count,
                                     channel_name,
                                     read,
                                     close};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PhongrastOpenExrModule* phongrast_openexr_module(void) {
    return &kModule;
}
