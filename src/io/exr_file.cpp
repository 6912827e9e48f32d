#include "exr_file.hpp"

#include <algorithm>
#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include "phongrast/io/error.hpp"

namespace phongrast::io::detail {
namespace {

Imf::PixelType pixel_type(const ExrChannel& channel) {
    return channel.unsigned_int ? Imf::UINT : Imf::FLOAT;
}

/// The frame buffer of `channels` for a data window starting at (x0, y0).
Imf::FrameBuffer frame_buffer(const std::vector<ExrChannel>& channels, int columns, int x0, int y0) {
    Imf::FrameBuffer buffer;
    for (const ExrChannel& channel : channels) {
        const std::size_t row_stride = channel.stride * static_cast<std::size_t>(columns);
        // OpenEXR addresses pixel (x, y) as base + x * xStride + y * yStride.
        char* origin = channel.base - static_cast<std::ptrdiff_t>(x0) * static_cast<std::ptrdiff_t>(channel.stride) -
                       static_cast<std::ptrdiff_t>(y0) * static_cast<std::ptrdiff_t>(row_stride);
        buffer.insert(channel.name, Imf::Slice(pixel_type(channel), origin, channel.stride, row_stride));
    }
    return buffer;
}

}  // namespace

void write_exr(const std::string& file, const std::string& path, int columns, int rows,
               const std::vector<ExrChannel>& channels) {
    try {
        Imf::Header header(columns, rows);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const ExrChannel& channel : channels) header.channels().insert(channel.name, Imf::Channel(pixel_type(channel)));
        Imf::OutputFile output(file.c_str(), header);
        output.setFrameBuffer(frame_buffer(channels, columns, 0, 0));
        output.writePixels(rows);
    } catch (const std::exception& error) {
        throw FileError(path + ": write failed: " + error.what());
    }
}

struct ExrReader::File {
    explicit File(const std::string& path) : input(path.c_str()) {}
    Imf::InputFile input;
};

ExrReader::ExrReader(const std::string& path) : path_(path) {
    try {
        file_ = std::make_unique<File>(path);
        const Imath::Box2i window = file_->input.header().dataWindow();
        columns_ = window.max.x - window.min.x + 1;
        rows_ = window.max.y - window.min.y + 1;
        for (auto it = file_->input.header().channels().begin(); it != file_->input.header().channels().end(); ++it) {
            names_.push_back(it.name());
        }
    } catch (const std::exception& error) {
        throw FileError(path + ": cannot read image: " + error.what());
    }
    if (columns_ < 1 || rows_ < 1 || columns_ > 32768 || rows_ > 32768) {
        throw FileError(path + ": EXR of " + std::to_string(columns_) + "x" + std::to_string(rows_) +
                        " pixels; expected 1 to 32768 per side");
    }
}

ExrReader::~ExrReader() = default;

bool ExrReader::has(const std::string& name) const {
    return std::find(names_.begin(), names_.end(), name) != names_.end();
}

void ExrReader::read(const std::vector<ExrChannel>& channels) {
    try {
        const Imath::Box2i window = file_->input.header().dataWindow();
        file_->input.setFrameBuffer(frame_buffer(channels, columns_, window.min.x, window.min.y));
        file_->input.readPixels(window.min.y, window.max.y);
    } catch (const std::exception& error) {
        throw FileError(path_ + ": cannot read image: " + error.what());
    }
}

}  // namespace phongrast::io::detail
