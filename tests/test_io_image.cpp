// PNG/EXR writing (format from the extension, clamping, no gamma, atomic
// replacement), the labelled sheet, and automatic framing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include <sys/stat.h>

#include "io/png_bytes.hpp"
#include "io/png_encoder.hpp"
#include "io_test_files.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/sheet.hpp"
#include "phongrast/io/text_file.hpp"

using namespace phongrast;
using Catch::Matchers::Contains;

namespace {

Image test_pattern() {
    Image image(2, 3);
    image.at(0, 0) = {0.0f, 0.5f, 1.0f};
    image.at(0, 1) = {-1.0f, 2.0f, 0.25f};  // out of [0,1]: clamped in PNG, kept in EXR
    image.at(0, 2) = {0.2f, 0.4f, 0.6f};
    image.at(1, 0) = {1.0f, 0.0f, 0.0f};
    image.at(1, 1) = {0.0f, 1.0f, 0.0f};
    image.at(1, 2) = {0.0f, 0.0f, 1.0f};
    return image;
}

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("PNG is 8-bit, clamped to [0,1], without a gamma curve") {
    TemporaryFolder folder;
    const std::string path = folder.file("pattern.png");
    io::write_image(test_pattern(), path);
    const Image back = io::read_image(path);
    REQUIRE(back.rows == 2);
    REQUIRE(back.columns == 3);
    // 0.5 -> 128/255 (a gamma curve would give 186); 0.25 -> 64/255.
    CHECK(back.at(0, 0).y == Approx(128.0f / 255.0f));
    CHECK(back.at(0, 1).x == 0.0f);
    CHECK(back.at(0, 1).y == 1.0f);
    CHECK(back.at(0, 1).z == Approx(64.0f / 255.0f));
    CHECK(back.at(0, 2).x == Approx(51.0f / 255.0f));
    CHECK(back.at(1, 2) == glm::vec3(0, 0, 1));
    CHECK(folder.entry_count() == 1);
}

TEST_CASE("PNG's 8-bit conversion of a whole image gives to_8_bit's value for each float") {
    // The image's values go through the array form (four at a time with SSE2,
    // the rest one by one); to_8_bit(float) is the definition.
    std::vector<float> values;
    const auto from_bits = [](std::uint32_t bits) {
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    };
    // Every 61st float of [0, 1], and [-1, 0) more sparsely.
    for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 61) values.push_back(from_bits(bits));
    for (std::uint32_t bits = 0x80000000u; bits <= 0xbf800000u; bits += 9973) values.push_back(from_bits(bits));
    // 64 floats on each side of every rounding boundary (k + 0.5) / 255.
    for (int k = 0; k < 255; ++k) {
        float below = (static_cast<float>(k) + 0.5f) / 255.0f, above = below;
        for (int step = 0; step < 64; ++step) {
            values.push_back(below = std::nextafter(below, 0.0f));
            values.push_back(above = std::nextafter(above, 1.0f));
        }
    }
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const float special : {nan, -nan, inf, -inf, 0.0f, -0.0f, 1.0f, std::nextafter(1.0f, 2.0f), 2.0f, 1e30f,
                                -1e30f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                                std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()}) {
        values.push_back(special);
    }
    // Every start and length modulo 4, so that each value meets both paths.
    for (std::size_t skip = 0; skip < 4; ++skip) {
        const std::size_t count = values.size() - skip - (3 - skip);
        std::vector<std::uint8_t> bytes(count);
        io::detail::to_8_bit(values.data() + skip, bytes.data(), count);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < count; ++i) wrong += bytes[i] != io::detail::to_8_bit(values[skip + i]) ? 1 : 0;
        INFO("start " << skip << ", " << count << " values");
        CHECK(wrong == 0);
    }
    CHECK(io::detail::to_8_bit(nan) == 0);
    CHECK(io::detail::to_8_bit(inf) == 255);
    CHECK(io::detail::to_8_bit(-inf) == 0);
    CHECK(io::detail::to_8_bit(1.0f) == 255);
}

TEST_CASE("files are written with a new file's permissions (0666 less the umask), no temporary file left") {
    TemporaryFolder folder;
    const mode_t old_mask = ::umask(027);
    io::write_image(test_pattern(), folder.file("a.png"));
    io::write_image(test_pattern(), folder.file("a.png"));  // replaced
    io::write_image(test_pattern(), folder.file("b.exr"));
    io::write_text_file(folder.file("c.json"), "{}");
    ::umask(old_mask);
    for (const char* name : {"a.png", "b.exr", "c.json"}) {
        struct stat status {};
        REQUIRE(::stat(folder.file(name).c_str(), &status) == 0);
        CHECK((status.st_mode & 0777) == 0640);
    }
    CHECK(folder.entry_count() == 3);
}

TEST_CASE("the PNG writer's file holds exactly the encoded PNG, into a new empty file or over longer contents") {
    // It opens its file without O_TRUNC (ext4 would write a file truncated to
    // zero out on close); a file that is not empty is still truncated first.
    TemporaryFolder folder;
    const std::vector<std::uint8_t> rgb = {0, 128, 255, 10, 20, 30, 200, 100, 50, 1, 2, 3};
    io::detail::PngPixels pixels;
    pixels.data = rgb.data();
    pixels.rows = 2;
    pixels.columns = 2;
    const io::detail::PngSettings settings = io::detail::png_settings(io::PngCompression::standard);
    const std::string expected = io::detail::encode_png(pixels, settings);
    const std::string fresh = folder.file("fresh.png");
    { std::ofstream create(fresh, std::ios::binary); }
    io::detail::write_png(fresh, fresh, pixels, settings);
    CHECK(contents(fresh) == expected);
    const std::string longer = folder.file("longer.png");
    { std::ofstream old(longer, std::ios::binary); old << std::string(expected.size() + 1000, 'x'); }
    io::detail::write_png(longer, longer, pixels, settings);
    CHECK(contents(longer) == expected);
    io::detail::write_png(folder.file("new.png"), "new.png", pixels, settings);  // created when missing
    CHECK(contents(folder.file("new.png")) == expected);
}

TEST_CASE("16-bit PNGs decode to the words written, with each of the five row filters") {
    // `up` filters 16-bit rows straight from the machine's words (one pass);
    // the other filters go through a big-endian copy. libspng decodes both.
    TemporaryFolder folder;
    for (const int channels : {1, 3, 4}) {
        const int columns = 37, rows = 11;
        std::vector<std::uint16_t> words(static_cast<std::size_t>(columns * rows * channels));
        for (std::size_t i = 0; i < words.size(); ++i) {
            // Every byte value in both halves, carries and borrows between rows included.
            words[i] = static_cast<std::uint16_t>(static_cast<std::uint32_t>(i) * 40503u + (i % 7 == 0 ? 0xff00u : 0u));
        }
        for (const io::detail::PngFilter filter : {io::detail::PngFilter::none, io::detail::PngFilter::sub,
                                                   io::detail::PngFilter::up, io::detail::PngFilter::average,
                                                   io::detail::PngFilter::paeth}) {
            INFO(channels << " channels, filter " << static_cast<int>(filter));
            io::detail::PngPixels pixels;
            pixels.data = words.data();
            pixels.columns = columns;
            pixels.rows = rows;
            pixels.channels = channels;
            pixels.bit_depth = 16;
            const std::string path = folder.file("words.png");
            io::detail::write_png(path, path, pixels, {3, filter});
            const Image back = io::read_image(path);
            REQUIRE(back.rows == rows);
            REQUIRE(back.columns == columns);
            std::size_t wrong = 0;
            for (std::size_t p = 0; p < back.pixels.size(); ++p) {
                // read_image gives k / 65535 for each colour channel (grey: all three the same).
                for (int c = 0; c < std::min(channels, 3); ++c) {
                    const std::uint16_t word = words[p * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
                    wrong += back.pixels[p][c] != static_cast<float>(word) / 65535.0f ? 1 : 0;
                }
            }
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("a large PNG is deflated in two pieces that decode as one stream, the same bytes on one thread or two") {
    // zlib deflates the first third or so of the rows (ended by a sync flush),
    // libdeflate the rest; libspng checks the stream and its Adler-32.
    TemporaryFolder folder;
    for (const int bit_depth : {8, 16}) {
        const int columns = 700, rows = 520;  // 8-bit RGB: 1.09 MB filtered, over the split's 1 MiB
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(columns * rows * 3));
        std::vector<std::uint16_t> words(bytes.size());
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            const std::uint32_t noise = static_cast<std::uint32_t>(i) * 2654435761u;
            words[i] = static_cast<std::uint16_t>((i / 3 % 700) * 90 + (noise >> 27));
            bytes[i] = static_cast<std::uint8_t>(words[i] >> 8);
        }
        io::detail::PngPixels pixels;
        pixels.data = bit_depth == 8 ? static_cast<const void*>(bytes.data()) : words.data();
        pixels.columns = columns;
        pixels.rows = rows;
        pixels.bit_depth = bit_depth;
        for (const io::PngCompression compression : {io::PngCompression::fast, io::PngCompression::standard}) {
            INFO(bit_depth << "-bit, " << io::to_string(compression));
            io::detail::PngSettings settings = io::detail::png_settings(compression);
            REQUIRE(settings.head_zlib_level > 0);
            REQUIRE(settings.head_zlib_level_16_bit != 0);
            const std::string two_threads = io::detail::encode_png(pixels, settings);
            settings.concurrent = false;
            const std::string one_thread = io::detail::encode_png(pixels, settings);
            CHECK(two_threads == one_thread);
            settings.head_zlib_level = settings.head_zlib_level_16_bit = 0;  // one libdeflate stream: other bytes
            CHECK(io::detail::encode_png(pixels, settings) != one_thread);
            const std::string path = folder.file("split.png");
            {
                std::ofstream out(path, std::ios::binary);
                out << two_threads;
            }
            const Image back = io::read_image(path);
            REQUIRE(back.rows == rows);
            REQUIRE(back.columns == columns);
            std::size_t wrong = 0;
            for (std::size_t i = 0; i < bytes.size(); ++i) {
                const float value = back.pixels[i / 3][static_cast<int>(i % 3)];
                wrong += value != (bit_depth == 8 ? bytes[i] / 255.0f : words[i] / 65535.0f) ? 1 : 0;
            }
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("the default PNG compression deflates 8-bit samples at level 2 and 16-bit samples at level 4") {
    // Each the fastest level within 10% of OpenImageIO's size on renders (docs/startup.md).
    // A smooth gradient with noise, large enough for the levels' outputs to differ.
    const int side = 96;
    std::vector<std::uint8_t> rgb8(side * side * 3);
    std::vector<std::uint16_t> rgb16(side * side * 3);
    for (std::size_t i = 0; i < rgb8.size(); ++i) {
        const std::uint32_t noise = static_cast<std::uint32_t>(i) * 2654435761u;
        rgb16[i] = static_cast<std::uint16_t>(i * 7 + (noise >> 28));
        rgb8[i] = static_cast<std::uint8_t>(rgb16[i] >> 4);
    }
    const io::detail::PngSettings standard = io::detail::png_settings(io::PngCompression::standard);
    const auto encoded = [](const void* data, int bit_depth, io::detail::PngSettings settings) {
        io::detail::PngPixels pixels;
        pixels.data = data;
        pixels.rows = pixels.columns = 96;
        pixels.bit_depth = bit_depth;
        return io::detail::encode_png(pixels, settings);
    };
    const std::string eight = encoded(rgb8.data(), 8, standard);
    CHECK(eight == encoded(rgb8.data(), 8, {2, io::detail::PngFilter::up}));
    CHECK(eight != encoded(rgb8.data(), 8, {4, io::detail::PngFilter::up}));
    const std::string sixteen = encoded(rgb16.data(), 16, standard);
    CHECK(sixteen == encoded(rgb16.data(), 16, {4, io::detail::PngFilter::up}));
    CHECK(sixteen != encoded(rgb16.data(), 16, {3, io::detail::PngFilter::up}));
    CHECK(sixteen != encoded(rgb16.data(), 16, {2, io::detail::PngFilter::up}));
}

TEST_CASE("an image converted to 8-bit values and written as PNG is write_image's file, byte for byte") {
    TemporaryFolder folder;
    Image image(37, 53);  // odd sizes: the conversion's four-at-a-time steps end mid-pixel
    for (int r = 0; r < image.rows; ++r) {
        for (int c = 0; c < image.columns; ++c) {
            // Out of range, halfway values and plain ones.
            image.at(r, c) = {static_cast<float>(r * c) / 900.0f - 0.5f, (r + 0.5f) / 37.0f, 127.5f / 255.0f};
        }
    }
    io::Rgb8Image bytes;
    bytes.values.assign(10, 7);  // memory reused: what was in it does not matter
    io::convert_to_8_bit(image, bytes);
    REQUIRE(bytes.rows == 37);
    REQUIRE(bytes.columns == 53);
    REQUIRE(bytes.values.size() == 37u * 53u * 3u);
    CHECK(bytes.values[3 * 53 + 1] == io::detail::to_8_bit(image.at(1, 0).y));
    for (const io::PngCompression compression :
         {io::PngCompression::fast, io::PngCompression::standard, io::PngCompression::small}) {
        io::ImageWriteOptions options;
        options.png_compression = compression;
        io::write_image(image, folder.file("floats.png"), options);
        io::write_png_8_bit(bytes, folder.file("bytes.png"), compression);
        CHECK(contents(folder.file("bytes.png")) == contents(folder.file("floats.png")));
    }
    CHECK(folder.entry_count() == 2);  // no temporary file left
    CHECK_THROWS_AS(io::write_png_8_bit(bytes, folder.file("bytes.exr")), io::FileError);
    CHECK_THROWS_AS(io::write_png_8_bit(io::Rgb8Image{}, folder.file("empty.png")), io::FileError);
    io::Rgb8Image short_of_values = bytes;
    short_of_values.values.pop_back();
    CHECK_THROWS_AS(io::write_png_8_bit(short_of_values, folder.file("short.png")), std::invalid_argument);
    CHECK(folder.entry_count() == 2);
}

TEST_CASE("EXR keeps linear unclamped floats") {
    TemporaryFolder folder;
    const std::string path = folder.file("pattern.EXR");
    io::write_image(test_pattern(), path);
    const Image back = io::read_image(path);
    CHECK(back.pixels == test_pattern().pixels);
}

TEST_CASE("an unknown extension is an error, and a failed write leaves the old file") {
    TemporaryFolder folder;
    CHECK_THROWS_WITH(io::image_format_for("out.jpg"), Contains("out.jpg") && Contains(".png") && Contains(".exr"));
    CHECK_THROWS_AS(io::image_format_for("noextension"), io::FileError);
    const std::string path = folder.write("keep.png", "old contents");
    Image empty;
    CHECK_THROWS_AS(io::write_image(empty, path), io::FileError);
    CHECK(contents(path) == "old contents");
    CHECK_THROWS_WITH(io::write_image(test_pattern(), folder.file("no-such-folder/x.png")),
                      Contains("x.png") && Contains("cannot write"));
    CHECK(folder.entry_count() == 1);
}

TEST_CASE("the sheet lays cells out in a grid and draws dark label text") {
    std::vector<io::SheetCell> cells;
    for (int i = 0; i < 8; ++i) cells.push_back({Image(40, 60, glm::vec3(0.0f, 0.0f, 1.0f)), "Phong, full"});
    const Image sheet = io::compose_sheet(cells, 4);
    CHECK(sheet.columns > 4 * 60);
    CHECK(sheet.rows > 2 * 40);
    std::size_t blue = 0;
    std::size_t dark_text = 0;
    for (const glm::vec3& p : sheet.pixels) {
        if (p == glm::vec3(0, 0, 1)) ++blue;
        if (p.x < 0.5f && p.x == p.y && p.y == p.z) ++dark_text;
    }
    CHECK(blue == 8u * 40u * 60u);  // every cell pixel, untouched
    CHECK(dark_text > 50);          // the labels were drawn (the font was found)
}

TEST_CASE("sheet labels: text wider than its cell is clipped, broken UTF-8 is drawn as replacement glyphs") {
    const std::string long_label(400, 'W');
    const std::string broken_utf8 = "a\xC3 \xE2\x82 \xFF\xF0\x9F\x98\x80";  // cut sequences, a byte never valid, one emoji
    std::vector<io::SheetCell> cells{{Image(20, 20, glm::vec3(1.0f)), long_label},
                                     {Image(20, 20, glm::vec3(1.0f)), broken_utf8},
                                     {Image(20, 20, glm::vec3(1.0f)), "\xC3\xA9t\xC3\xA9"}};
    Image sheet;
    REQUIRE_NOTHROW(sheet = io::compose_sheet(cells, 3));  // ASan build: no write outside the sheet
    std::size_t dark_in_last_column = 0;
    for (int row = 0; row < sheet.rows; ++row) dark_in_last_column += sheet.at(row, sheet.columns - 1).x < 0.5f;
    CHECK(dark_in_last_column > 0);  // the W's reach the right edge, and stop there
    for (const glm::vec3& p : sheet.pixels) {
        REQUIRE(std::isfinite(p.x));
        REQUIRE(p.x >= 0.0f);
        REQUIRE(p.x <= 1.0f);
    }
}

TEST_CASE("automatic framing: every vertex inside the image with a margin") {
    Mesh mesh;
    mesh.positions = {{10, 20, 30}, {14, 21, 30}, {10, 26, 33}, {12, 20, 31}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    const Scene scene = io::frame_mesh(mesh, 300, 400);
    CHECK(scene.camera.lookat == glm::dvec3(12, 23, 31.5));
    CHECK(scene.lights.size() == 3);
    const CameraFrame frame = make_camera_frame(scene.camera, 300, 400);
    double nearest_edge = 1e9;
    for (const glm::dvec3& p : mesh.positions) {
        const ProjectedPoint q = frame.project(p);
        nearest_edge = std::min({nearest_edge, q.column, 400 - q.column, q.row, 300 - q.row});
    }
    CHECK(nearest_edge > 0.03 * 300);   // a margin on every side
    CHECK(nearest_edge < 0.06 * 400);   // and tight: the mesh fills the frame on one axis
}

TEST_CASE("write_image refuses a pixel buffer that disagrees with rows x columns, and a size past the limit, "
          "before touching the file") {
    TemporaryFolder folder;
    const std::string path = folder.write("keep.png", "old contents");
    Image short_buffer = test_pattern();
    short_buffer.pixels.resize(short_buffer.pixels.size() / 2);
    CHECK_THROWS_AS(io::write_image(short_buffer, path), std::invalid_argument);
    CHECK_THROWS_WITH(io::write_image(short_buffer, path),
                      Contains("image.pixels.size()") && Contains("image.rows * image.columns"));
    Image long_buffer = test_pattern();
    long_buffer.pixels.push_back(glm::vec3(1.0f));
    CHECK_THROWS_AS(io::write_image(long_buffer, folder.file("x.exr")), std::invalid_argument);
    Image huge;  // the size fields alone: the check comes before any pixel is read
    huge.rows = 100000;
    huge.columns = 100000;
    CHECK_THROWS_AS(io::write_image(huge, path), std::length_error);
    CHECK_THROWS_WITH(io::write_image(huge, path), Contains("100000 x 100000") && Contains("GiB"));
    CHECK_THROWS_AS(io::write_exr_with_aovs(short_buffer, AovPlanes{}, folder.file("y.exr")), std::invalid_argument);
    std::vector<io::SheetCell> cells = {{short_buffer, "short"}};
    CHECK_THROWS_AS(io::compose_sheet(cells, 1), std::invalid_argument);
    CHECK(contents(path) == "old contents");
    CHECK(folder.entry_count() == 1);
}

TEST_CASE("the mesh writers refuse an index past the vertices (std::out_of_range), writing nothing") {
    TemporaryFolder folder;
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    CHECK_THROWS_AS(io::write_stl(mesh, folder.file("m.stl")), std::out_of_range);
    CHECK_THROWS_WITH(io::write_stl(mesh, folder.file("m.stl")), Contains("mesh.triangles[1][2] = 3"));
    CHECK_THROWS_AS(io::write_glb(mesh, folder.file("m.glb")), std::out_of_range);
    CHECK_THROWS_AS(io::write_ply(mesh, folder.file("m.ply")), std::out_of_range);
    CHECK(folder.entry_count() == 0);
}
