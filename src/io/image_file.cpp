// write_image and read_image: PNG out through libdeflate (png_encoder.cpp),
// EXR in and out through OpenEXR (exr_file.cpp), PNG and JPEG in through
// libspng and libjpeg-turbo (image_decoders.hpp), anything else in through the
// OpenImageIO module, loaded only then (openimageio_module.hpp).
#include "phongrast/io/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "exr_file.hpp"
#include "file_bytes.hpp"
#include "image_decoders.hpp"
#include "openimageio_module.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/text_file.hpp"
#include "png_bytes.hpp"
#include "png_encoder.hpp"

namespace phongrast::io {
namespace {

std::string lower_case_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

/// The image's values as one flat array, red, green, blue of each pixel in
/// turn: glm::vec3 is three packed floats (the EXR writer below relies on it too).
const float* rgb_values(const Image& image) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 must be three packed floats");
    return &image.pixels.data()->x;
}

void write_png_rgb(const Image& image, const std::string& temporary, const std::string& path,
                   const ImageWriteOptions& options) {
    detail::PngPixels pixels;
    pixels.columns = image.columns;
    pixels.rows = image.rows;
    pixels.channels = 3;
    pixels.bit_depth = options.png_bit_depth;
    const std::size_t values = image.pixels.size() * 3;
    const float* from = rgb_values(image);
    const detail::PngSettings settings = detail::png_settings(options.png_compression);
    // Kept per thread, as the encoder's buffers are: a batch's writer thread
    // converts image after image, and a fresh buffer is zeroed (and, past
    // malloc's mapping threshold, faulted in) before it is written over.
    if (options.png_bit_depth == 16) {
        thread_local std::vector<std::uint16_t> words;
        words.resize(values);
        for (std::size_t i = 0; i < values; ++i) words[i] = detail::to_16_bit(from[i]);
        pixels.data = words.data();
        detail::write_png(temporary, path, pixels, settings);
        return;
    }
    thread_local std::vector<std::uint8_t> bytes;
    bytes.resize(values);
    detail::to_8_bit(from, bytes.data(), values);
    pixels.data = bytes.data();
    detail::write_png(temporary, path, pixels, settings);
}

void write_exr_rgb(const Image& image, const std::string& temporary, const std::string& path) {
    // OpenEXR reads the values in place: three float channels, 12 bytes apart.
    char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
    const std::size_t stride = sizeof(glm::vec3);
    detail::write_exr(temporary, path, image.columns, image.rows,
                      {{"R", false, base, stride}, {"G", false, base + 4, stride}, {"B", false, base + 8, stride}});
}

bool looks_like_exr(const char* data, std::size_t size) {
    return size >= 4 && static_cast<unsigned char>(data[0]) == 0x76 && static_cast<unsigned char>(data[1]) == 0x2f &&
           static_cast<unsigned char>(data[2]) == 0x31 && static_cast<unsigned char>(data[3]) == 0x01;
}

Image read_exr_rgb(const std::string& path) {
    detail::ExrReader reader(path);
    Image image(reader.rows(), reader.columns());
    // R, G, B when present; else luminance Y as grey; else the file's first
    // channels (alphabetical), the last one repeated, as OpenImageIO read them.
    std::vector<std::string> names;
    if (reader.has("R") && reader.has("G") && reader.has("B")) {
        names = {"R", "G", "B"};
    } else if (reader.has("Y")) {
        names = {"Y", "Y", "Y"};
    } else {
        const std::vector<std::string>& all = reader.channel_names();
        if (all.empty()) throw FileError(path + ": image has no channels");
        for (std::size_t c = 0; c < 3; ++c) names.push_back(all[std::min(c, all.size() - 1)]);
    }
    char* base = reinterpret_cast<char*>(image.pixels.data());
    std::vector<detail::ExrChannel> channels;
    for (std::size_t c = 0; c < 3; ++c) {
        const auto first = std::find(names.begin(), names.end(), names[c]);
        if (first != names.begin() + static_cast<std::ptrdiff_t>(c)) continue;  // a repeated channel is read once
        channels.push_back({names[c], false, base + 4 * c, sizeof(glm::vec3)});
    }
    reader.read(channels);
    for (glm::vec3& pixel : image.pixels) {
        for (int c = 1; c < 3; ++c) {
            const auto first = std::find(names.begin(), names.end(), names[static_cast<std::size_t>(c)]) - names.begin();
            if (first != c) pixel[c] = pixel[static_cast<int>(first)];
        }
    }
    return image;
}

Image read_with_openimageio(const std::string& path) {
    const PhongrastOpenImageIoModule* module = nullptr;
    try {
        module = &detail::openimageio_module("reading this image format");
    } catch (const std::runtime_error& error) {
        throw FileError(path + ": " + error.what());
    }
    int rows = 0;
    int columns = 0;
    float* rgb = nullptr;
    char error[1024] = "";
    if (module->read_rgb(path.c_str(), &rows, &columns, &rgb, error, sizeof error) != 0) {
        throw FileError(path + ": " + error);
    }
    std::unique_ptr<float, void (*)(float*)> owned(rgb, module->free_pixels);
    Image image(rows, columns);
    std::memcpy(image.pixels.data(), rgb, image.pixels.size() * sizeof(glm::vec3));
    return image;
}

}  // namespace

PngCompression parse_png_compression(std::string_view text) {
    if (text == "fast") return PngCompression::fast;
    if (text == "default") return PngCompression::standard;
    if (text == "small") return PngCompression::small;
    throw std::invalid_argument("png-compression: expected fast, default or small, got '" + std::string(text) + "'");
}

const char* to_string(PngCompression compression) {
    switch (compression) {
    case PngCompression::fast: return "fast";
    case PngCompression::small: return "small";
    case PngCompression::standard: break;
    }
    return "default";
}

ImageFormat image_format_for(const std::string& path) {
    const std::string extension = lower_case_extension(path);
    if (extension == ".png") return ImageFormat::png;
    if (extension == ".exr") return ImageFormat::exr;
    throw FileError(path + ": unknown image format '" + extension +
                    "'; expected a file name ending in .png (8-bit) or .exr (linear float)");
}

void write_image(const Image& image, const std::string& path) { write_image(image, path, ImageWriteOptions{}); }

void write_image(const Image& image, const std::string& path, const ImageWriteOptions& options) {
    // The caller's image first, apart from the encoding: an empty one is a
    // FileError as before; a size past the limit or a pixel buffer that
    // disagrees with rows x columns is the caller's mistake (invalid_argument,
    // length_error), refused before any file is touched.
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    validate_image(image);
    const ImageFormat format = image_format_for(path);
    if (options.png_bit_depth != 8 && options.png_bit_depth != 16) {
        throw FileError(path + ": PNG bit depth " + std::to_string(options.png_bit_depth) + "; expected 8 or 16");
    }
    replace_file_atomically(path, [&](const std::string& temporary) {
        if (format == ImageFormat::png) {
            write_png_rgb(image, temporary, path, options);
        } else {
            write_exr_rgb(image, temporary, path);
        }
    });
}

void convert_to_8_bit(const Image& image, Rgb8Image& out) {
    validate_image(image);
    out.rows = image.rows;
    out.columns = image.columns;
    out.values.resize(image.pixels.size() * 3);
    if (!out.values.empty()) detail::to_8_bit(rgb_values(image), out.values.data(), out.values.size());
}

void write_png_8_bit(const Rgb8Image& image, const std::string& path, PngCompression compression) {
    // What write_image checks of its image, and its format.
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    if (image.values.size() != static_cast<std::size_t>(image.rows) * static_cast<std::size_t>(image.columns) * 3) {
        throw std::invalid_argument(path + ": the 8-bit image holds " + std::to_string(image.values.size()) +
                                    " values; expected rows x columns x 3");
    }
    if (image_format_for(path) != ImageFormat::png) {
        throw FileError(path + ": an 8-bit RGB image is written as PNG; expected a file name ending in .png");
    }
    detail::PngPixels pixels;
    pixels.columns = image.columns;
    pixels.rows = image.rows;
    pixels.channels = 3;
    pixels.bit_depth = 8;
    pixels.data = image.values.data();
    replace_file_atomically(path, [&](const std::string& temporary) {
        detail::write_png(temporary, path, pixels, detail::png_settings(compression));
    });
}

Image read_image(const std::string& path) {
    bool exr = false;
    {
        // Chosen by the file's first bytes, not its name; the mapping ends before EXR or OpenImageIO reopen the file.
        const FileBytes bytes = FileBytes::read(path, "image");
        if (detail::looks_like_png(bytes.data(), bytes.size())) return detail::decode_png(bytes.data(), bytes.size(), path);
        if (detail::looks_like_jpeg(bytes.data(), bytes.size())) {
            bool unsupported = false;  // CMYK: left to OpenImageIO
            Image image = detail::decode_jpeg(bytes.data(), bytes.size(), path, unsupported);
            if (!unsupported) return image;
        }
        exr = looks_like_exr(bytes.data(), bytes.size());
    }
    return exr ? read_exr_rgb(path) : read_with_openimageio(path);
}

}  // namespace phongrast::io

namespace phongrast::io {
namespace {

/// An RGB image's values as a three-channel stored image (read_image has
/// already made grey r = g = b and dropped alpha, which is what textures need).
StoredImage stored_from_rgb(const Image& image) {
    StoredImage stored;
    stored.rows = image.rows;
    stored.columns = image.columns;
    stored.channels = 3;
    stored.values.resize(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) stored.values[3 * i + static_cast<std::size_t>(c)] = image.pixels[i][c];
    }
    return stored;
}

}  // namespace

// Textures go through the same decoders as read_image (libspng, libjpeg-turbo,
// OpenEXR, and OpenImageIO's module for the rest), so that reading a texture
// never loads OpenImageIO for PNG, JPEG or EXR (docs/startup.md).
StoredImage read_stored_image(const std::string& path) { return stored_from_rgb(read_image(path)); }

StoredImage read_stored_image(std::string_view bytes, const std::string& name) {
    // glTF embeds PNG and JPEG only (its core image types).
    if (detail::looks_like_png(bytes.data(), bytes.size())) {
        return stored_from_rgb(detail::decode_png(bytes.data(), bytes.size(), name));
    }
    if (detail::looks_like_jpeg(bytes.data(), bytes.size())) {
        bool unsupported = false;
        Image image = detail::decode_jpeg(bytes.data(), bytes.size(), name, unsupported);
        if (unsupported) throw FileError(name + ": an embedded CMYK/YCCK JPEG is not supported; expected RGB or grey");
        return stored_from_rgb(image);
    }
    throw FileError(name + ": embedded image is neither PNG nor JPEG (glTF's image types)");
}

}  // namespace phongrast::io
