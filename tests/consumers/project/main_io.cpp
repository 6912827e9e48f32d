// The installed phongrast::io in use: render the triangle, write it as EXR (linear
// floats, so nothing is rounded), read it back and check the same pixels. This
// links OpenEXR through phongrast::io's exported link-only dependencies.
#include <cstdio>
#include <exception>

#include <phongrast/io/image_file.hpp>
#include <phongrast/phongrast.hpp>

#include "triangle_scene.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <output.exr>\n", argv[0]);
        return 2;
    }
    try {
        const phongrast::RenderResult result =
            phongrast::render(consumer::triangle_scene(), phongrast::RenderOptions::exact());
        phongrast::io::write_image(result.image, argv[1]);
        if (!consumer::image_is_right(phongrast::io::read_image(argv[1]))) return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
    std::printf("phongrast::io: the triangle survived an EXR round trip through %s\n", argv[1]);
    return 0;
}
