#include "phongrast/io/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "phongrast/io/error.hpp"
#include "phongrast/io/text_file.hpp"
#include "png_bytes.hpp"

namespace phongrast::io {
namespace {

std::string lower_case_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}


void write_with_openimageio(const Image& image, const std::string& temporary,
                            const std::string& path, ImageFormat format) {
    auto output = OIIO::ImageOutput::create(temporary);
    if (!output) throw FileError(path + ": cannot write: " + OIIO::geterror());
    const bool png = format == ImageFormat::png;
    OIIO::ImageSpec spec(image.columns, image.rows, 3, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    if (!png) spec.attribute("compression", "zip");
    if (!output->open(temporary, spec)) {
        throw FileError(path + ": cannot write: " + output->geterror());
    }
    bool written = false;
    if (png) {
        std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) bytes[3 * i + static_cast<std::size_t>(c)] = detail::to_8_bit(image.pixels[i][c]);
        }
        written = output->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    const bool closed = output->close();
    if (!written || !closed) throw FileError(path + ": write failed: " + output->geterror());
}

/// Reads an opened image's first subimage in its own type and converts each
/// value with one correctly rounded division (OpenImageIO's own conversion
/// multiplies by a rounded reciprocal, which can be one unit off).
StoredImage read_stored(OIIO::ImageInput& input, const std::string& name) {
    const OIIO::ImageSpec& spec = input.spec();
    if (spec.nchannels < 1 || spec.width < 1 || spec.height < 1) throw FileError(name + ": image has no pixels");
    StoredImage image;
    image.rows = spec.height;
    image.columns = spec.width;
    image.channels = spec.nchannels;
    const std::size_t count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                              static_cast<std::size_t>(spec.nchannels);
    image.values.resize(count);
    const bool uniform = spec.channelformats.empty();
    const auto read = [&](OIIO::TypeDesc type, void* data) {
        if (!input.read_image(0, 0, 0, spec.nchannels, type, data)) {
            throw FileError(name + ": cannot read image: " + input.geterror());
        }
    };
    const auto convert = [&](auto sample, float maximum) {
        std::vector<decltype(sample)> raw(count);
        read(OIIO::BaseTypeFromC<decltype(sample)>::value, raw.data());
        for (std::size_t i = 0; i < count; ++i) image.values[i] = static_cast<float>(raw[i]) / maximum;
    };
    if (uniform && spec.format == OIIO::TypeDesc::UINT8) {
        convert(std::uint8_t{}, 255.0f);
    } else if (uniform && spec.format == OIIO::TypeDesc::UINT16) {
        convert(std::uint16_t{}, 65535.0f);
    } else {
        read(OIIO::TypeDesc::FLOAT, image.values.data());  // half and float exactly
    }
    return image;
}

/// Do not multiply colour by alpha (OpenImageIO's PNG reader does by default).
OIIO::ImageSpec stored_values_config() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

}  // namespace

ImageFormat image_format_for(const std::string& path) {
    const std::string extension = lower_case_extension(path);
    if (extension == ".png") return ImageFormat::png;
    if (extension == ".exr") return ImageFormat::exr;
    throw FileError(path + ": unknown image format '" + extension +
                    "'; expected a file name ending in .png (8-bit) or .exr (linear float)");
}

void write_image(const Image& image, const std::string& path) {
    const ImageFormat format = image_format_for(path);
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    replace_file_atomically(path, [&](const std::string& temporary) {
        write_with_openimageio(image, temporary, path, format);
    });
}

Image read_image(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw FileError(path + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.nchannels < 1) throw FileError(path + ": image has no channels");
    std::vector<float> values(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                              static_cast<std::size_t>(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, values.data())) {
        throw FileError(path + ": cannot read image: " + input->geterror());
    }
    Image image(spec.height, spec.width);
    const std::size_t channels = static_cast<std::size_t>(spec.nchannels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            image.pixels[i][static_cast<int>(c)] = values[i * channels + std::min(c, channels - 1)];
        }
    }
    return image;
}

}  // namespace phongrast::io

namespace phongrast::io {

StoredImage read_stored_image(const std::string& path) {
    const OIIO::ImageSpec config = stored_values_config();
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input) throw FileError(path + ": cannot read image: " + OIIO::geterror());
    return read_stored(*input, path);
}

StoredImage read_stored_image(std::string_view bytes, const std::string& name) {
    OIIO::ImageSpec config = stored_values_config();
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    // The proxy as a configuration hint: OpenImageIO 2.4's open(name, config,
    // proxy) still looks for a file called `name`.
    void* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::open(name, &config);
    if (!input) throw FileError(name + ": cannot read image: " + OIIO::geterror());
    return read_stored(*input, name);
}

}  // namespace phongrast::io
