#include "phongrast/io/aov_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/text_file.hpp"
#include "png_bytes.hpp"

namespace phongrast::io {
namespace {

void require_format(const std::string& path, ImageFormat expected, const char* what) {
    if (image_format_for(path) != expected) throw FileError(path + ": " + what);
}

void require_plane_size(std::size_t size, const Image& image, const std::string& path, const char* plane) {
    if (size != 0 && size != image.pixels.size()) {
        throw FileError(path + ": the " + std::string(plane) + " plane has " + std::to_string(size) +
                        " values for " + std::to_string(image.pixels.size()) + " pixels");
    }
}


void open_output(OIIO::ImageOutput& output, const std::string& temporary, const std::string& path,
                 const OIIO::ImageSpec& spec) {
    if (!output.open(temporary, spec)) throw FileError(path + ": cannot write: " + output.geterror());
}

void finish_output(OIIO::ImageOutput& output, bool written, const std::string& path) {
    const bool closed = output.close();
    if (!written || !closed) throw FileError(path + ": write failed: " + output.geterror());
}

}  // namespace

void write_exr_with_aovs(const Image& image, const AovPlanes& aovs, const std::string& path) {
    require_format(path, ImageFormat::exr, "expected a file name ending in .exr for the extra outputs");
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    validate_image(image);  // pixels.size() == rows * columns, within the size limit
    require_plane_size(aovs.alpha.size(), image, path, "alpha");
    require_plane_size(aovs.depth.size(), image, path, "depth");
    require_plane_size(aovs.normal.size(), image, path, "normal");
    require_plane_size(aovs.id.size(), image, path, "id");

    // Channel names and where each value comes from; every channel is 4 bytes wide.
    std::vector<std::string> names;
    std::vector<OIIO::TypeDesc> formats;
    const auto add_channel = [&](const char* name, OIIO::TypeDesc format) {
        names.push_back(name);
        formats.push_back(format);
    };
    for (const char* name : {"R", "G", "B"}) add_channel(name, OIIO::TypeDesc::FLOAT);
    if (!aovs.alpha.empty()) add_channel("A", OIIO::TypeDesc::FLOAT);
    if (!aovs.depth.empty()) add_channel("Z", OIIO::TypeDesc::FLOAT);
    if (!aovs.normal.empty()) {
        for (const char* name : {"N.X", "N.Y", "N.Z"}) add_channel(name, OIIO::TypeDesc::FLOAT);
    }
    if (!aovs.id.empty()) add_channel("id", OIIO::TypeDesc::UINT);
    const std::size_t channels = names.size();
    std::vector<std::uint32_t> words(image.pixels.size() * channels);  // raw 4-byte values, channel-interleaved
    const auto bits = [](float value) {
        std::uint32_t word;
        std::memcpy(&word, &value, sizeof word);
        return word;
    };
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        std::uint32_t* out = &words[p * channels];
        for (int c = 0; c < 3; ++c) *out++ = bits(image.pixels[p][c]);
        if (!aovs.alpha.empty()) *out++ = bits(aovs.alpha[p]);
        if (!aovs.depth.empty()) *out++ = bits(aovs.depth[p]);
        if (!aovs.normal.empty()) {
            for (int c = 0; c < 3; ++c) *out++ = bits(aovs.normal[p][c]);
        }
        if (!aovs.id.empty()) *out++ = static_cast<std::uint32_t>(aovs.id[p]);
    }

    OIIO::ImageSpec spec(image.columns, image.rows, static_cast<int>(channels), OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.channelformats = formats;
    spec.alpha_channel = aovs.alpha.empty() ? -1 : 3;
    spec.z_channel = aovs.depth.empty() ? -1 : (aovs.alpha.empty() ? 3 : 4);
    spec.attribute("compression", "zip");
    replace_file_atomically(path, [&](const std::string& temporary) {
        auto output = OIIO::ImageOutput::create(temporary);
        if (!output) throw FileError(path + ": cannot write: " + OIIO::geterror());
        open_output(*output, temporary, path, spec);
        // TypeUnknown: the buffer is in the file's own per-channel formats.
        finish_output(*output, output->write_image(OIIO::TypeDesc::UNKNOWN, words.data()), path);
    });
}

void read_exr_with_aovs(const std::string& path, Image& image, AovPlanes& aovs) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw FileError(path + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    const auto channel = [&](const std::string& name) {
        const auto found = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
        return found == spec.channelnames.end() ? -1 : static_cast<int>(found - spec.channelnames.begin());
    };
    const auto read_float = [&](int index, std::vector<float>& values) {
        values.resize(pixels);
        if (!input->read_image(0, 0, index, index + 1, OIIO::TypeDesc::FLOAT, values.data())) {
            throw FileError(path + ": cannot read channel " + spec.channelnames[index] + ": " + input->geterror());
        }
    };
    image = Image(spec.height, spec.width);
    aovs = AovPlanes{};
    aovs.rows = spec.height;
    aovs.columns = spec.width;
    std::vector<float> values;
    for (int c = 0; c < 3; ++c) {
        const int index = channel(std::string(1, "RGB"[c]));
        if (index < 0) throw FileError(path + ": no channel " + std::string(1, "RGB"[c]));
        read_float(index, values);
        for (std::size_t p = 0; p < pixels; ++p) image.pixels[p][c] = values[p];
    }
    if (channel("A") >= 0) read_float(channel("A"), aovs.alpha);
    if (channel("Z") >= 0) read_float(channel("Z"), aovs.depth);
    if (channel("N.X") >= 0 && channel("N.Y") >= 0 && channel("N.Z") >= 0) {
        aovs.normal.resize(pixels);
        for (int c = 0; c < 3; ++c) {
            read_float(channel(std::string("N.") + "XYZ"[c]), values);
            for (std::size_t p = 0; p < pixels; ++p) aovs.normal[p][c] = values[p];
        }
    }
    if (channel("id") >= 0) {
        const int index = channel("id");
        std::vector<std::uint32_t> ids(pixels);
        if (!input->read_image(0, 0, index, index + 1, OIIO::TypeDesc::UINT, ids.data())) {
            throw FileError(path + ": cannot read channel id: " + input->geterror());
        }
        aovs.id.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) aovs.id[p] = static_cast<std::int32_t>(ids[p]);
    }
}

void write_png_with_alpha(const Image& image, const std::vector<float>& alpha, const glm::vec3& background,
                          const std::string& path) {
    require_format(path, ImageFormat::png, "expected a file name ending in .png for a transparent background");
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    validate_image(image);  // pixels.size() == rows * columns, within the size limit
    if (alpha.size() != image.pixels.size()) {
        throw FileError(path + ": the alpha plane has " + std::to_string(alpha.size()) + " values for " +
                        std::to_string(image.pixels.size()) + " pixels");
    }
    std::vector<std::uint8_t> bytes(image.pixels.size() * 4);
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        const float a = alpha[p];
        for (int c = 0; c < 3; ++c) {
            // pixel = a * surface + (1 - a) * background: solve for the surface.
            const float surface = a > 0.0f ? (image.pixels[p][c] - (1.0f - a) * background[c]) / a : 0.0f;
            bytes[4 * p + static_cast<std::size_t>(c)] = detail::to_8_bit(surface);
        }
        bytes[4 * p + 3] = detail::to_8_bit(a);
    }
    OIIO::ImageSpec spec(image.columns, image.rows, 4, OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 3;
    // The colour is not premultiplied by alpha (PNG's convention); tell OpenImageIO so it does not divide again.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    replace_file_atomically(path, [&](const std::string& temporary) {
        auto output = OIIO::ImageOutput::create(temporary);
        if (!output) throw FileError(path + ": cannot write: " + OIIO::geterror());
        open_output(*output, temporary, path, spec);
        finish_output(*output, output->write_image(OIIO::TypeDesc::UINT8, bytes.data()), path);
    });
}

}  // namespace phongrast::io
