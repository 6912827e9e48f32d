#include "heat_map.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <glm/common.hpp>

#include "image_agreement.hpp"

namespace llvmpipe_compare {
namespace {

float clamp01(float value) { return std::min(1.0f, std::max(0.0f, value)); }

void write_rgb8(const std::string& path, int rows, int columns, const std::vector<float>& rgb) {
    const std::string temporary = path + ".tmp.png";
    auto output = OIIO::ImageOutput::create(path);
    if (!output) throw std::runtime_error(path + ": OpenImageIO cannot write this format");
    const OIIO::ImageSpec spec(columns, rows, 3, OIIO::TypeDesc::UINT8);
    if (!output->open(temporary, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) ||
        !output->close()) {
        const std::string error = output->geterror();
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": " + error);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": cannot rename the temporary file into place");
    }
}

}  // namespace

void write_png(const std::string& path, const phongrast::Image& image) {
    std::vector<float> rgb;
    rgb.reserve(image.pixels.size() * 3);
    for (const glm::vec3& p : image.pixels) rgb.insert(rgb.end(), {clamp01(p.x), clamp01(p.y), clamp01(p.z)});
    write_rgb8(path, image.rows, image.columns, rgb);
}

void write_heat_map(const std::string& path, const phongrast::Image& first, const phongrast::Image& second,
                    const glm::vec3& background) {
    const std::vector<float> map = difference_map(first, second);
    std::vector<float> rgb;
    rgb.reserve(map.size() * 3);
    for (std::size_t i = 0; i < map.size(); ++i) {
        const bool in_first = first.pixels[i] != background;
        const bool in_second = second.pixels[i] != background;
        glm::vec3 colour(0.0f);
        if (in_first && !in_second) {
            colour = {1.0f, 0.0f, 1.0f};
        } else if (!in_first && in_second) {
            colour = {0.0f, 1.0f, 1.0f};
        } else if (map[i] > 1.0f / 255.0f) {
            const float t = std::min(1.0f, map[i] / (16.0f / 255.0f));
            colour = {clamp01(3.0f * t), clamp01(3.0f * t - 1.0f), clamp01(3.0f * t - 2.0f)};
            colour = glm::max(colour, glm::vec3(0.35f, 0.0f, 0.0f));  // even 2/255 stays visible
        } else if (in_first) {
            colour = glm::vec3(0.15f);
        }
        rgb.insert(rgb.end(), {colour.x, colour.y, colour.z});
    }
    write_rgb8(path, first.rows, first.columns, rgb);
}

}  // namespace llvmpipe_compare
