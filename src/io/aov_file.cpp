#include "phongrast/io/aov_file.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "exr_file.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/text_file.hpp"
#include "png_bytes.hpp"
#include "png_encoder.hpp"

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

}  // namespace

void write_exr_with_aovs(const Image& image, const AovPlanes& aovs, const std::string& path) {
    require_format(path, ImageFormat::exr, "expected a file name ending in .exr for the extra outputs");
    if (image.rows < 1 || image.columns < 1) throw FileError(path + ": cannot write an empty image");
    validate_image(image);  // pixels.size() == rows * columns, within the size limit
    require_plane_size(aovs.alpha.size(), image, path, "alpha");
    require_plane_size(aovs.depth.size(), image, path, "depth");
    require_plane_size(aovs.normal.size(), image, path, "normal");
    require_plane_size(aovs.id.size(), image, path, "id");
    require_plane_size(aovs.uv.size(), image, path, "uv");
    require_plane_size(aovs.distance.size(), image, path, "distance");

    // One channel per plane, each read in place by OpenEXR (OpenEXR stores them in alphabetical order).
    const auto floats = [](const auto& plane, std::size_t offset) {
        return const_cast<char*>(reinterpret_cast<const char*>(plane.data())) + offset;
    };
    std::vector<detail::ExrChannel> channels;
    for (int c = 0; c < 3; ++c) {
        channels.push_back({std::string(1, "RGB"[c]), false, floats(image.pixels, 4 * static_cast<std::size_t>(c)),
                            sizeof(glm::vec3)});
    }
    if (!aovs.alpha.empty()) channels.push_back({"A", false, floats(aovs.alpha, 0), sizeof(float)});
    if (!aovs.depth.empty()) channels.push_back({"Z", false, floats(aovs.depth, 0), sizeof(float)});
    if (!aovs.distance.empty()) channels.push_back({"distance", false, floats(aovs.distance, 0), sizeof(float)});
    if (!aovs.normal.empty()) {
        for (int c = 0; c < 3; ++c) {
            channels.push_back({std::string("N.") + "XYZ"[c], false, floats(aovs.normal, 4 * static_cast<std::size_t>(c)),
                                sizeof(glm::vec3)});
        }
    }
    if (!aovs.uv.empty()) {
        for (int c = 0; c < 2; ++c) {
            channels.push_back({std::string("uv.") + "st"[c], false, floats(aovs.uv, 4 * static_cast<std::size_t>(c)),
                                sizeof(glm::vec2)});
        }
    }
    // The triangle index as a 32-bit unsigned channel: the background's -1 becomes 4294967295.
    std::vector<std::uint32_t> ids(aovs.id.size());
    for (std::size_t p = 0; p < ids.size(); ++p) ids[p] = static_cast<std::uint32_t>(aovs.id[p]);
    if (!aovs.id.empty()) channels.push_back({"id", true, floats(ids, 0), sizeof(std::uint32_t)});
    replace_file_atomically(path, [&](const std::string& temporary) {
        detail::write_exr(temporary, path, image.columns, image.rows, channels);
    });
}

void read_exr_with_aovs(const std::string& path, Image& image, AovPlanes& aovs) {
    detail::ExrReader reader(path);
    image = Image(reader.rows(), reader.columns());
    aovs = AovPlanes{};
    aovs.rows = reader.rows();
    aovs.columns = reader.columns();
    const std::size_t pixels = image.pixels.size();
    const auto at = [](auto& plane, std::size_t offset) { return reinterpret_cast<char*>(plane.data()) + offset; };
    std::vector<detail::ExrChannel> channels;
    for (int c = 0; c < 3; ++c) {
        const std::string name(1, "RGB"[c]);
        if (!reader.has(name)) throw FileError(path + ": no channel " + name);
        channels.push_back({name, false, at(image.pixels, 4 * static_cast<std::size_t>(c)), sizeof(glm::vec3)});
    }
    if (reader.has("A")) {
        aovs.alpha.resize(pixels);
        channels.push_back({"A", false, at(aovs.alpha, 0), sizeof(float)});
    }
    if (reader.has("Z")) {
        aovs.depth.resize(pixels);
        channels.push_back({"Z", false, at(aovs.depth, 0), sizeof(float)});
    }
    if (reader.has("distance")) {
        aovs.distance.resize(pixels);
        channels.push_back({"distance", false, at(aovs.distance, 0), sizeof(float)});
    }
    if (reader.has("N.X") && reader.has("N.Y") && reader.has("N.Z")) {
        aovs.normal.resize(pixels);
        for (int c = 0; c < 3; ++c) {
            channels.push_back({std::string("N.") + "XYZ"[c], false, at(aovs.normal, 4 * static_cast<std::size_t>(c)),
                                sizeof(glm::vec3)});
        }
    }
    if (reader.has("uv.s") && reader.has("uv.t")) {
        aovs.uv.resize(pixels);
        for (int c = 0; c < 2; ++c) {
            channels.push_back({std::string("uv.") + "st"[c], false, at(aovs.uv, 4 * static_cast<std::size_t>(c)),
                                sizeof(glm::vec2)});
        }
    }
    std::vector<std::uint32_t> ids;
    if (reader.has("id")) {
        ids.resize(pixels);
        channels.push_back({"id", true, at(ids, 0), sizeof(std::uint32_t)});
    }
    reader.read(channels);
    if (!ids.empty()) {
        aovs.id.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) aovs.id[p] = static_cast<std::int32_t>(ids[p]);
    }
}

void write_png_with_alpha(const Image& image, const std::vector<float>& alpha, const glm::vec3& background,
                          const std::string& path) {
    write_png_with_alpha(image, alpha, background, path, ImageWriteOptions{});
}

void write_png_with_alpha(const Image& image, const std::vector<float>& alpha, const glm::vec3& background,
                          const std::string& path, const ImageWriteOptions& options) {
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
    // The colour is not premultiplied by alpha (PNG's convention).
    detail::PngPixels pixels;
    pixels.data = bytes.data();
    pixels.columns = image.columns;
    pixels.rows = image.rows;
    pixels.channels = 4;
    replace_file_atomically(path, [&](const std::string& temporary) {
        detail::write_png(temporary, path, pixels, detail::png_settings(options.png_compression));
    });
}

}  // namespace phongrast::io
