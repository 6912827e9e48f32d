// phongrast_openimageio.so: the only code that links OpenImageIO, loaded by
// openimageio_loader.cpp when an image format needs it.
#include "openimageio_module.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

namespace {

void copy_error(const std::string& message, char* error, std::size_t size) {
    if (size == 0) return;
    const std::size_t length = std::min(message.size(), size - 1);
    std::memcpy(error, message.data(), length);
    error[length] = '\0';
}

int read_rgb(const char* path, int* rows, int* columns, float** rgb, char* error, std::size_t error_size) {
    try {
        auto input = OIIO::ImageInput::open(path);
        if (!input) return copy_error("cannot read image: " + OIIO::geterror(), error, error_size), 1;
        const OIIO::ImageSpec& spec = input->spec();
        if (spec.nchannels < 1) return copy_error("image has no channels", error, error_size), 1;
        const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
        const std::size_t channels = static_cast<std::size_t>(spec.nchannels);
        std::vector<float> values(pixels * channels);
        if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, values.data())) {
            return copy_error("cannot read image: " + input->geterror(), error, error_size), 1;
        }
        float* out = static_cast<float*>(std::malloc(pixels * 3 * sizeof(float)));
        if (!out) return copy_error("out of memory", error, error_size), 1;
        for (std::size_t i = 0; i < pixels; ++i) {
            for (std::size_t c = 0; c < 3; ++c) out[3 * i + c] = values[i * channels + std::min(c, channels - 1)];
        }
        *rows = spec.height;
        *columns = spec.width;
        *rgb = out;
        return 0;
    } catch (const std::exception& failure) {
        copy_error(failure.what(), error, error_size);
        return 1;
    }
}

void free_pixels(float* rgb) { std::free(rgb); }

const PhongrastOpenImageIoModule the_module = {phongrast::io::detail::kPhongrastOpenImageIoModuleVersion, read_rgb,
                                               free_pixels};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PhongrastOpenImageIoModule* phongrast_openimageio_module(void) {
    return &the_module;
}
