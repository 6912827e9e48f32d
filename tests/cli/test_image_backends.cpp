// Every image phongrast writes decodes, with OpenImageIO (the library that
// wrote them before), to the same values it wrote then: PNG 8-bit RGB at each
// --png-compression, RGBA (--transparent), 16-bit, EXR colour and extra
// outputs. And read_image reads what other writers wrote exactly: 8-bit k as
// k/255, 16-bit k as k/65535, grey and alpha variants, JPEG as libjpeg
// decodes it, other formats through the OpenImageIO module.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "io_test_files.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"

using namespace phongrast;
using Catch::Matchers::Contains;

namespace {

// The conversion every PNG phongrast wrote used (png_bytes.hpp before and after).
std::uint8_t old_8_bit(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::lround(value * 255.0f));
}

// Values on both sides of every 8-bit rounding boundary, out of range, and random.
Image awkward_image(int rows, int columns) {
    Image image(rows, columns);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> any(-0.1f, 1.1f);
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        const float boundary = (static_cast<float>(p % 256) + 0.5f) / 255.0f;
        image.pixels[p] = {std::nextafter(boundary, 0.0f), std::nextafter(boundary, 1.0f), any(random)};
    }
    image.pixels[0] = {-1.0f, 2.0f, 0.0f};
    image.pixels[1] = {1.0f, 1e30f, -0.0f};
    return image;
}

template <typename T>
std::vector<T> decode_with_openimageio(const std::string& path, int channels, OIIO::TypeDesc type, int& rows,
                                       int& columns) {
    // The values as stored: OpenImageIO would otherwise premultiply the colour by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path, &config);
    REQUIRE(input);
    REQUIRE(input->spec().nchannels == channels);
    rows = input->spec().height;
    columns = input->spec().width;
    std::vector<T> values(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns) *
                          static_cast<std::size_t>(channels));
    REQUIRE(input->read_image(0, 0, 0, channels, type, values.data()));
    return values;
}

void write_with_openimageio(const std::string& path, int rows, int columns, int channels, OIIO::TypeDesc type,
                            const void* data) {
    auto output = OIIO::ImageOutput::create(path);
    REQUIRE(output);
    OIIO::ImageSpec spec(columns, rows, channels, type);
    if (channels == 2 || channels == 4) {
        spec.alpha_channel = channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    REQUIRE(output->open(path, spec));
    REQUIRE(output->write_image(type, data));
    REQUIRE(output->close());
}

}  // namespace

TEST_CASE("8-bit RGB PNG decodes to the values OpenImageIO wrote before, at every compression") {
    TemporaryFolder folder;
    const Image image = awkward_image(37, 53);
    for (io::PngCompression compression : {io::PngCompression::fast, io::PngCompression::standard, io::PngCompression::small}) {
        INFO(io::to_string(compression));
        io::ImageWriteOptions options;
        options.png_compression = compression;
        const std::string path = folder.file(std::string(io::to_string(compression)) + ".png");
        io::write_image(image, path, options);
        int rows = 0, columns = 0;
        const auto bytes = decode_with_openimageio<std::uint8_t>(path, 3, OIIO::TypeDesc::UINT8, rows, columns);
        REQUIRE(rows == 37);
        REQUIRE(columns == 53);
        for (std::size_t p = 0; p < image.pixels.size(); ++p) {
            for (int c = 0; c < 3; ++c) REQUIRE(bytes[3 * p + static_cast<std::size_t>(c)] == old_8_bit(image.pixels[p][c]));
        }
    }
    CHECK(io::parse_png_compression("default") == io::PngCompression::standard);
    CHECK_THROWS_WITH(io::parse_png_compression("tiny"), Contains("fast, default or small"));
}

TEST_CASE("16-bit PNG decodes to round(v * 65535), clamped, at every compression") {
    TemporaryFolder folder;
    const Image image = awkward_image(9, 300);
    io::ImageWriteOptions options;
    options.png_bit_depth = 16;
    const std::string path = folder.file("deep.png");
    std::vector<std::uint16_t> words;
    for (io::PngCompression compression : {io::PngCompression::fast, io::PngCompression::standard, io::PngCompression::small}) {
        INFO(io::to_string(compression));
        options.png_compression = compression;
        io::write_image(image, path, options);
        int rows = 0, columns = 0;
        words = decode_with_openimageio<std::uint16_t>(path, 3, OIIO::TypeDesc::UINT16, rows, columns);
        REQUIRE(rows == 9);
        REQUIRE(columns == 300);
        for (std::size_t p = 0; p < image.pixels.size(); ++p) {
            for (int c = 0; c < 3; ++c) {
                const float v = image.pixels[p][c];
                const std::uint16_t expected =
                    !(v > 0.0f) ? 0 : v >= 1.0f ? 65535 : static_cast<std::uint16_t>(std::lround(v * 65535.0f));
                REQUIRE(words[3 * p + static_cast<std::size_t>(c)] == expected);
            }
        }
    }
    // And read back by phongrast as k / 65535.
    const Image back = io::read_image(path);
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        REQUIRE(back.pixels[p].x == static_cast<float>(words[3 * p]) / 65535.0f);
    }
    options.png_bit_depth = 12;
    CHECK_THROWS_AS(io::write_image(image, folder.file("bad.png"), options), io::FileError);
}

TEST_CASE("large PNGs (deflated in two pieces, zlib's and libdeflate's) decode with OpenImageIO, 8-bit and 16-bit") {
    // 640x600 RGB: 1.15 MB filtered at 8 bits, 2.3 MB at 16, over the split's 1 MB.
    TemporaryFolder folder;
    const Image image = awkward_image(600, 640);
    for (const int depth : {8, 16}) {
        for (io::PngCompression compression : {io::PngCompression::fast, io::PngCompression::standard}) {
            INFO(depth << "-bit, " << io::to_string(compression));
            io::ImageWriteOptions options;
            options.png_bit_depth = depth;
            options.png_compression = compression;
            const std::string path = folder.file("large.png");
            io::write_image(image, path, options);
            int rows = 0, columns = 0;
            std::size_t wrong = 0;
            if (depth == 8) {
                const auto bytes = decode_with_openimageio<std::uint8_t>(path, 3, OIIO::TypeDesc::UINT8, rows, columns);
                for (std::size_t i = 0; i < bytes.size(); ++i) wrong += bytes[i] != old_8_bit(image.pixels[i / 3][static_cast<int>(i % 3)]);
            } else {
                const auto words = decode_with_openimageio<std::uint16_t>(path, 3, OIIO::TypeDesc::UINT16, rows, columns);
                for (std::size_t i = 0; i < words.size(); ++i) {
                    const float v = image.pixels[i / 3][static_cast<int>(i % 3)];
                    const std::uint16_t expected =
                        !(v > 0.0f) ? 0 : v >= 1.0f ? 65535 : static_cast<std::uint16_t>(std::lround(v * 65535.0f));
                    wrong += words[i] != expected;
                }
            }
            REQUIRE(rows == 600);
            REQUIRE(columns == 640);
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("RGBA PNG (--transparent) decodes to the colour with the background taken out, and the coverage") {
    TemporaryFolder folder;
    const Image image = awkward_image(16, 40);
    std::vector<float> alpha(image.pixels.size());
    for (std::size_t p = 0; p < alpha.size(); ++p) alpha[p] = static_cast<float>(p % 5) / 4.0f;
    const glm::vec3 background(0.25f, 0.5f, 1.0f);
    const std::string path = folder.file("alpha.png");
    io::write_png_with_alpha(image, alpha, background, path);
    int rows = 0, columns = 0;
    const auto bytes = decode_with_openimageio<std::uint8_t>(path, 4, OIIO::TypeDesc::UINT8, rows, columns);
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        const float a = alpha[p];
        for (int c = 0; c < 3; ++c) {
            const float surface = a > 0.0f ? (image.pixels[p][c] - (1.0f - a) * background[c]) / a : 0.0f;
            REQUIRE(bytes[4 * p + static_cast<std::size_t>(c)] == old_8_bit(surface));
        }
        REQUIRE(bytes[4 * p + 3] == old_8_bit(a));
    }
}

TEST_CASE("EXR colour and extra outputs decode to the same bits") {
    TemporaryFolder folder;
    Image image = awkward_image(11, 13);
    image.pixels[2] = {std::numeric_limits<float>::infinity(), -3.5f, 1e-40f};
    const std::string path = folder.file("colour.exr");
    io::write_image(image, path);
    int rows = 0, columns = 0;
    const auto floats = decode_with_openimageio<float>(path, 3, OIIO::TypeDesc::FLOAT, rows, columns);
    REQUIRE(std::memcmp(floats.data(), image.pixels.data(), floats.size() * sizeof(float)) == 0);
    CHECK(io::read_image(path).pixels == image.pixels);

    AovPlanes aovs;
    aovs.rows = image.rows;
    aovs.columns = image.columns;
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        aovs.alpha.push_back(static_cast<float>(p % 3) / 2.0f);
        aovs.depth.push_back(p % 7 == 0 ? std::numeric_limits<float>::infinity() : static_cast<float>(p) * 0.25f);
        aovs.normal.push_back({0.0f, -1.0f, static_cast<float>(p) / 200.0f});
        aovs.id.push_back(p % 4 == 0 ? -1 : static_cast<std::int32_t>(p * 1000));
    }
    const std::string aov_path = folder.file("aovs.exr");
    io::write_exr_with_aovs(image, aovs, aov_path);
    auto input = OIIO::ImageInput::open(aov_path);
    REQUIRE(input);
    const OIIO::ImageSpec& spec = input->spec();
    const auto channel = [&](const std::string& name) {
        for (int i = 0; i < spec.nchannels; ++i) {
            if (spec.channelnames[static_cast<std::size_t>(i)] == name) return i;
        }
        FAIL("no channel " << name);
        return -1;
    };
    const auto read_float = [&](const std::string& name) {
        std::vector<float> values(image.pixels.size());
        const int index = channel(name);
        REQUIRE(input->read_image(0, 0, index, index + 1, OIIO::TypeDesc::FLOAT, values.data()));
        return values;
    };
    CHECK(spec.channelformat(channel("id")) == OIIO::TypeDesc::UINT);
    const auto r = read_float("R"), a = read_float("A"), z = read_float("Z"), ny = read_float("N.Y"), nz = read_float("N.Z");
    std::vector<std::uint32_t> ids(image.pixels.size());
    REQUIRE(input->read_image(0, 0, channel("id"), channel("id") + 1, OIIO::TypeDesc::UINT, ids.data()));
    for (std::size_t p = 0; p < image.pixels.size(); ++p) {
        REQUIRE(std::memcmp(&r[p], &image.pixels[p].x, 4) == 0);
        REQUIRE(a[p] == aovs.alpha[p]);
        REQUIRE(z[p] == aovs.depth[p]);
        REQUIRE(ny[p] == -1.0f);
        REQUIRE(nz[p] == aovs.normal[p].z);
        REQUIRE(ids[p] == static_cast<std::uint32_t>(aovs.id[p]));
    }
    Image back;
    AovPlanes planes;
    io::read_exr_with_aovs(aov_path, back, planes);
    CHECK(std::memcmp(back.pixels.data(), image.pixels.data(), image.pixels.size() * sizeof(glm::vec3)) == 0);
    CHECK(planes.alpha == aovs.alpha);
    CHECK(planes.depth == aovs.depth);
    CHECK(planes.normal == aovs.normal);
    CHECK(planes.id == aovs.id);
}

TEST_CASE("read_image: 8-bit k is k/255 and 16-bit k is k/65535 exactly, for grey, grey+alpha, RGB and RGBA") {
    TemporaryFolder folder;
    const int columns = 256;
    for (int channels = 1; channels <= 4; ++channels) {
        INFO(channels << " channels");
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(columns * channels));
        std::vector<std::uint16_t> words(static_cast<std::size_t>(256 * columns * channels));
        for (int x = 0; x < columns; ++x) {
            for (int c = 0; c < channels; ++c) bytes[static_cast<std::size_t>(x * channels + c)] = static_cast<std::uint8_t>((x + 40 * c) % 256);
        }
        for (std::size_t i = 0; i < words.size(); ++i) words[i] = static_cast<std::uint16_t>((i * 7919) % 65536);
        const std::string eight = folder.file("eight" + std::to_string(channels) + ".png");
        const std::string sixteen = folder.file("sixteen" + std::to_string(channels) + ".png");
        write_with_openimageio(eight, 1, columns, channels, OIIO::TypeDesc::UINT8, bytes.data());
        write_with_openimageio(sixteen, 256, columns, channels, OIIO::TypeDesc::UINT16, words.data());
        const Image e = io::read_image(eight);
        const Image s = io::read_image(sixteen);
        REQUIRE(e.columns == columns);
        REQUIRE(s.rows == 256);
        const int colour = channels >= 3 ? 3 : 1;  // grey repeats into r, g, b; alpha is dropped
        for (std::size_t p = 0; p < e.pixels.size(); ++p) {
            for (int c = 0; c < 3; ++c) {
                const std::size_t from = p * static_cast<std::size_t>(channels) + static_cast<std::size_t>(colour == 3 ? c : 0);
                REQUIRE(e.pixels[p][c] == static_cast<float>(bytes[from]) / 255.0f);
            }
        }
        for (std::size_t p = 0; p < s.pixels.size(); ++p) {
            for (int c = 0; c < 3; ++c) {
                const std::size_t from = p * static_cast<std::size_t>(channels) + static_cast<std::size_t>(colour == 3 ? c : 0);
                REQUIRE(s.pixels[p][c] == static_cast<float>(words[from]) / 65535.0f);
            }
        }
    }
}

TEST_CASE("read_image: JPEG as libjpeg-turbo decodes it (OpenImageIO's values), other formats through OpenImageIO") {
    TemporaryFolder folder;
    const int rows = 24, columns = 40;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(rows * columns * 3));
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>((i * 37) % 256);
    for (const char* name : {"photo.jpg", "picture.tif", "picture.bmp", "picture.tga"}) {
        INFO(name);
        const std::string path = folder.file(name);
        write_with_openimageio(path, rows, columns, 3, OIIO::TypeDesc::UINT8, rgb.data());
        int r = 0, c = 0;
        const auto expected = decode_with_openimageio<std::uint8_t>(path, 3, OIIO::TypeDesc::UINT8, r, c);
        const Image image = io::read_image(path);
        REQUIRE(image.rows == rows);
        REQUIRE(image.columns == columns);
        for (std::size_t p = 0; p < image.pixels.size(); ++p) {
            for (int k = 0; k < 3; ++k) REQUIRE(std::lround(image.pixels[p][k] * 255.0f) == expected[3 * p + static_cast<std::size_t>(k)]);
        }
    }
    CHECK_THROWS_WITH(io::read_image(folder.write("junk.png", "not an image at all")), Contains("junk.png"));
    CHECK_THROWS_WITH(io::read_image(folder.file("missing.png")), Contains("missing.png"));
    // A truncated PNG names the file.
    const std::string whole = folder.file("whole.png");
    io::write_image(awkward_image(20, 20), whole);
    std::string bytes;
    {
        std::ifstream in(whole, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    CHECK_THROWS_WITH(io::read_image(folder.write("cut.png", bytes.substr(0, bytes.size() / 2))), Contains("cut.png"));
}

// Run by ctest with PHONGRAST_OPENIMAGEIO_MODULE naming a missing file
// (tests/cli/CMakeLists.txt): hidden from the normal run.
TEST_CASE("without the OpenImageIO module, another format is a clear error", "[.module-missing]") {
    TemporaryFolder folder;
    const std::string path = folder.file("picture.tif");
    const std::uint8_t grey[4] = {0, 85, 170, 255};
    write_with_openimageio(path, 2, 2, 1, OIIO::TypeDesc::UINT8, grey);
    CHECK_THROWS_WITH(io::read_image(path), Contains("picture.tif") && Contains("phongrast_openimageio.so") &&
                                                Contains("PHONGRAST_OPENIMAGEIO_MODULE"));
    // The formats phongrast reads itself do not need it.
    io::write_image(Image(2, 2, glm::vec3(0.5f)), folder.file("still.png"));
    CHECK(io::read_image(folder.file("still.png")).pixels[0].x == 128.0f / 255.0f);
}
