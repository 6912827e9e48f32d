// phongrast::io::load_texture: texels exactly as the file stores them (8-bit
// k/255, 16-bit k/65535, float as is), grey to equal r, g, b, alpha dropped
// (and never multiplied in), row 0 the top row; one read per file, shared.
#include <catch2/catch.hpp>

#include <thread>

#include "io_test_files.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/texture_file.hpp"
#include "png_test_writer.hpp"

using Catch::Matchers::Contains;
using phongrast::io::load_texture;

namespace {

/// Writes a 2 x 3 PNG whose sample i is `value(i)`.
std::string write_png(const TemporaryFolder& folder, const std::string& name, int bits, int color_type,
                      std::uint16_t (*value)(int)) {
    const int channels = png_test::channels_of(color_type);
    std::vector<std::uint16_t> samples(static_cast<std::size_t>(2 * 3 * channels));
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = value(static_cast<int>(i));
    return folder.write(name, png_test::encode(2, 3, bits, color_type, samples));
}

std::uint16_t eight_bit(int i) { return static_cast<std::uint16_t>((i * 37 + 1) % 256); }
std::uint16_t sixteen_bit(int i) { return static_cast<std::uint16_t>((i * 9973 + 7) % 65536); }

}  // namespace

TEST_CASE("texture texels: 8 and 16 bits, grey, grey + alpha, RGB and RGBA, exactly as stored") {
    TemporaryFolder folder;
    struct Case {
        int bits;
        int color_type;
    };
    for (const Case c : {Case{8, 0}, Case{8, 4}, Case{8, 2}, Case{8, 6}, Case{16, 0}, Case{16, 4}, Case{16, 2}, Case{16, 6}}) {
        INFO("bits " << c.bits << ", PNG colour type " << c.color_type);
        const auto value = c.bits == 8 ? eight_bit : sixteen_bit;
        const float maximum = c.bits == 8 ? 255.0f : 65535.0f;
        const std::string path = write_png(folder, "t" + std::to_string(c.bits) + "_" + std::to_string(c.color_type) + ".png",
                                           c.bits, c.color_type, value);
        std::string why;
        const auto image = load_texture(path, &why);
        REQUIRE(image);
        CHECK(why.empty());
        REQUIRE(image->rows == 2);
        REQUIRE(image->columns == 3);
        const int channels = png_test::channels_of(c.color_type);
        for (int row = 0; row < 2; ++row) {
            for (int column = 0; column < 3; ++column) {
                const int first = (row * 3 + column) * channels;
                const glm::vec3 expected =
                    channels < 3 ? glm::vec3(float(value(first)) / maximum)
                                 : glm::vec3(float(value(first)) / maximum, float(value(first + 1)) / maximum,
                                             float(value(first + 2)) / maximum);
                // Exactly the float nearest k / 255 (or k / 65535): no premultiplied alpha, no gamma.
                CHECK(image->at(row, column) == expected);
            }
        }
    }
}

TEST_CASE("texture texels: a float EXR as stored, row 0 the top row") {
    TemporaryFolder folder;
    phongrast::Image exr(2, 2);
    exr.pixels = {glm::vec3(0.1f, 2.5f, -0.25f), glm::vec3(1e-3f, 0.3f, 7.0f), glm::vec3(0.0f), glm::vec3(1.0f / 3.0f)};
    const std::string path = folder.file("float.exr");
    phongrast::io::write_image(exr, path);
    const auto image = load_texture(path);
    REQUIRE(image);
    CHECK(image->at(0, 0) == exr.pixels[0]);
    CHECK(image->at(0, 1) == exr.pixels[1]);
    CHECK(image->at(1, 1) == exr.pixels[3]);
}

TEST_CASE("textures are read once per file and shared, from several threads too") {
    TemporaryFolder folder;
    const std::string path = write_png(folder, "shared.png", 8, 2, eight_bit);
    std::vector<std::shared_ptr<const phongrast::TextureImage>> loaded(4);
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < loaded.size(); ++i) {
        threads.emplace_back([&, i] { loaded[i] = load_texture(path); });
    }
    for (std::thread& thread : threads) thread.join();
    REQUIRE(loaded[0]);
    for (const auto& image : loaded) CHECK(image.get() == loaded[0].get());
    // The same file by another spelling of its path is the same image.
    CHECK(load_texture(folder.file("./shared.png")).get() == loaded[0].get());
    CHECK(phongrast::io::texture_cache_size() >= 1);
    phongrast::io::clear_texture_cache();
    CHECK(phongrast::io::texture_cache_size() == 0);
    const auto again = load_texture(path);
    REQUIRE(again);
    CHECK(again->texels == loaded[0]->texels);  // read again after the cache was cleared
}

TEST_CASE("a missing or unreadable texture: null and why, and nothing cached") {
    TemporaryFolder folder;
    std::string why;
    CHECK_FALSE(load_texture(folder.file("absent.png"), &why));
    CHECK_THAT(why, Contains("absent.png") && Contains("no such file"));
    why.clear();
    CHECK_FALSE(load_texture(folder.write("broken.png", "not a png at all"), &why));
    CHECK_THAT(why, Contains("broken.png"));
    CHECK_FALSE(why.empty());
    why.clear();
    CHECK_FALSE(load_texture(folder.file(""), &why));
    CHECK_THAT(why, Contains("folder"));
    // A file that appears later is read then (failures are not cached).
    const std::string late = folder.file("late.png");
    CHECK_FALSE(load_texture(late));
    write_png(folder, "late.png", 8, 0, eight_bit);
    CHECK(load_texture(late));
}
