// The program's extra outputs and interruption: --aov writes the library's
// planes into one EXR, --transparent a PNG whose alpha is the coverage, and
// Ctrl-C stops render and sheet with status 130 and the folder unchanged.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_run.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/dataset_files.hpp"
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/render.hpp"

using namespace phongrast;

namespace {

const std::string default_scene = PHONGRAST_DEFAULT_SCENE;

RenderResult library_render(int size, const AovRequest& aovs, int samples = 1) {
    Scene scene = load_scene_with_library(default_scene);
    scene.image.rows = scene.image.columns = size;
    RenderOptions options = RenderOptions::exact();
    options.aovs = aovs;
    options.samples_per_axis = samples;
    return render(scene, options);
}

// Every file in the folder with its contents.
std::map<std::string, std::string> snapshot(const TemporaryFolder& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder.file(""))) {
        files[entry.path().filename().string()] = read_text(entry.path().string());
    }
    return files;
}

// Starts `phongrast ARGUMENTS...` in the folder, sends SIGINT after `delay`, and returns its exit status;
// its standard error goes to `error_file` (a path).
int interrupt_after(const TemporaryFolder& folder, std::vector<std::string> arguments, std::chrono::milliseconds delay,
                    const std::string& error_file = "/dev/null") {
    const pid_t child = fork();
    if (child == 0) {
        if (chdir(folder.file("").c_str()) != 0) _exit(127);
        const int null = open("/dev/null", O_WRONLY);
        const int errors = open(error_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(null, STDOUT_FILENO);
        dup2(errors, STDERR_FILENO);
        std::vector<char*> argv;
        static std::string program = PHONGRAST_CLI;
        argv.push_back(program.data());
        for (std::string& argument : arguments) argv.push_back(argument.data());
        argv.push_back(nullptr);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    // Until the program has installed its handler (SigCgt in /proc lists caught signals), a SIGINT
    // would end it before main(): starting takes a while on a busy machine (shared libraries).
    // Only after exec: before it, the child is this test process, whose Catch2 catches SIGINT too.
    const auto handler_installed = [child] {
        std::error_code error;
        const auto exe = std::filesystem::read_symlink("/proc/" + std::to_string(child) + "/exe", error);
        if (error || exe != std::filesystem::canonical(PHONGRAST_CLI, error)) return false;
        std::ifstream status("/proc/" + std::to_string(child) + "/status");
        std::string line;
        while (std::getline(status, line)) {
            if (line.rfind("SigCgt:", 0) == 0) return ((std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1)) & 1) != 0;
        }
        return false;
    };
    for (int tries = 0; tries < 3000 && !handler_installed(); ++tries) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    std::this_thread::sleep_for(delay);
    kill(child, SIGINT);
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("render with aov all writes the library's planes as named EXR channels") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + default_scene + "' --size 96x96 --aov all -o all.exr --quiet");
    INFO(run.err);
    REQUIRE(run.status == 0);
    Image image;
    AovPlanes planes;
    io::read_exr_with_aovs(folder.file("all.exr"), image, planes);
    const RenderResult expected = library_render(96, AovRequest::all());
    CHECK(image.pixels == expected.image.pixels);
    CHECK(planes.depth == expected.aovs.depth);
    CHECK(planes.normal == expected.aovs.normal);
    CHECK(planes.id == expected.aovs.id);
    CHECK(planes.alpha == expected.aovs.alpha);
    CHECK(planes.distance == expected.aovs.distance);
    CHECK(planes.distance.size() == 96 * 96);
    CHECK(std::count(planes.id.begin(), planes.id.end(), -1) > 0);  // some background, kept as -1
    CHECK(folder.entry_count() == 3);                               // the EXR and the two captured streams

    // Only what is asked for.
    REQUIRE(run_cli(folder, "render '" + default_scene + "' --size 32x32 --aov depth,id -o some.exr").status == 0);
    io::read_exr_with_aovs(folder.file("some.exr"), image, planes);
    CHECK(planes.depth.size() == 32 * 32);
    CHECK(planes.id.size() == 32 * 32);
    CHECK(planes.normal.empty());
    CHECK(planes.alpha.empty());
    CHECK(planes.distance.empty());
}

TEST_CASE("render with transparent writes an RGBA PNG whose alpha is the coverage") {
    TemporaryFolder folder;
    REQUIRE(run_cli(folder, "render '" + default_scene + "' --size 64x64 --samples 2 --transparent -o t.png").status == 0);
    auto input = OIIO::ImageInput::open(folder.file("t.png"));
    REQUIRE(input);
    REQUIRE(input->spec().nchannels == 4);
    std::vector<std::uint8_t> rgba(64 * 64 * 4);
    REQUIRE(input->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, rgba.data()));
    const RenderResult expected = library_render(64, AovRequest{false, false, false, true}, 2);
    int transparent = 0, opaque = 0, partial = 0;
    for (std::size_t p = 0; p < 64 * 64; ++p) {
        const float alpha = expected.aovs.alpha[p];
        CHECK(int(rgba[4 * p + 3]) == int(std::lround(alpha * 255.0f)));
        transparent += alpha == 0.0f;
        opaque += alpha == 1.0f;
        partial += alpha > 0.0f && alpha < 1.0f;
    }
    CHECK(transparent > 0);
    CHECK(opaque > 0);
    CHECK(partial > 0);  // anti-aliased edges
}

TEST_CASE("bad combinations of extra outputs and formats are refused before rendering") {
    TemporaryFolder folder;
    Run run = run_cli(folder, "render '" + default_scene + "' --aov depth -o x.png");
    CHECK(run.status == 2);
    CHECK_THAT(run.err, Catch::Contains("--aov: the extra outputs go into an EXR file"));
    run = run_cli(folder, "render '" + default_scene + "' --transparent -o x.exr");
    CHECK(run.status == 2);
    CHECK_THAT(run.err, Catch::Contains("--transparent: writes a PNG with alpha"));
    run = run_cli(folder, "render '" + default_scene + "' --aov depth,colour -o x.exr");
    CHECK(run.status == 2);
    CHECK_THAT(run.err, Catch::Contains("--aov: unknown output 'colour'"));
    CHECK(folder.entry_count() == 2);  // only the captured streams
}

TEST_CASE("Ctrl-C during render or sheet exits 130 and leaves the folder as it was") {
    TemporaryFolder folder;
    folder.write("out.png", "the user's earlier file");
    folder.write("sheet.png", "another earlier file");
    const auto before = snapshot(folder);
    // Long enough that the signal always comes first: thousands of frames, or eight large supersampled figures.
    CHECK(interrupt_after(folder, {"render", default_scene, "--repeat", "100000", "-o", "out.png"},
                          std::chrono::milliseconds(400)) == 130);
    CHECK(snapshot(folder) == before);
    CHECK(interrupt_after(folder, {"sheet", default_scene, "--size", "1536x1536", "--samples", "2", "-o", "sheet.png"},
                          std::chrono::milliseconds(400)) == 130);
    CHECK(snapshot(folder) == before);
}

TEST_CASE("Ctrl-C while the mesh loads exits 130 with a message, and writes nothing") {
    TemporaryFolder folder;
    // 1.3 million triangles: loading takes a few hundred milliseconds, and
    // the signal is sent within about 10 ms of the handler's installation,
    // which comes just before loading starts.
    REQUIRE(run_cli(folder, "generate --segments 16000 --sides 40 -o big.obj").status == 0);
    std::filesystem::remove(folder.file("stdout.txt"));
    std::filesystem::remove(folder.file("stderr.txt"));
    const auto before = snapshot(folder);
    const std::string errors = folder.file("interrupt-errors.txt");
    CHECK(interrupt_after(folder, {"render", "big.obj", "--size", "64x64", "-o", "big.png"}, std::chrono::milliseconds(0),
                          errors) == 130);
    CHECK(read_text(errors).find("interrupted; no output written") != std::string::npos);
    std::filesystem::remove(errors);  // the test's own capture
    CHECK(snapshot(folder) == before);
}

TEST_CASE("render with aov and no -o writes NAME.exr, not an error") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + default_scene + "' --aov depth --size 16x12 -q");
    CHECK(run.status == 0);
    REQUIRE(std::filesystem::exists(folder.file("default.exr")));
    CHECK_FALSE(std::filesystem::exists(folder.file("default.png")));
    Image image;
    AovPlanes planes;
    io::read_exr_with_aovs(folder.file("default.exr"), image, planes);
    CHECK(image.rows == 12);
    CHECK(planes.depth.size() == 16u * 12u);
}

namespace {

// The values of a one-file image as unsigned 16-bit (8-bit files are read as 0-255).
std::vector<std::uint16_t> read_values(const std::string& path, int expected_channels) {
    auto input = OIIO::ImageInput::open(path);
    REQUIRE(input);
    const OIIO::ImageSpec& spec = input->spec();
    REQUIRE(spec.nchannels == expected_channels);
    std::vector<std::uint16_t> values(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (spec.format == OIIO::TypeDesc::UINT8) {
        std::vector<std::uint8_t> bytes(values.size());
        REQUIRE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, bytes.data()));
        std::copy(bytes.begin(), bytes.end(), values.begin());
    } else {
        REQUIRE(spec.format == OIIO::TypeDesc::UINT16);
        REQUIRE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, values.data()));
    }
    return values;
}

std::uint8_t to_byte(float value) { return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

TEST_CASE("render with aov-files writes depth, mask, id, normal, object and distance files holding the library's planes") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + default_scene +
                                        "' --size 80x80 --samples 2 --aov-files all,depth16 --depth-scale 0.0005 -o k.png");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const RenderResult expected = library_render(80, AovRequest{true, true, true, true, false, true}, 2);
    const AovPlanes& planes = expected.aovs;
    const std::size_t pixels = 80 * 80;

    std::vector<float> depth(pixels);
    auto exr = OIIO::ImageInput::open(folder.file("k.depth.exr"));
    REQUIRE(exr);
    REQUIRE(exr->spec().channelnames == std::vector<std::string>{"Z"});
    REQUIRE(exr->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, depth.data()));
    CHECK(depth == planes.depth);  // +inf on the background, as the EXR channel

    std::vector<float> distance(pixels);
    auto distance_exr = OIIO::ImageInput::open(folder.file("k.distance.exr"));
    REQUIRE(distance_exr);
    REQUIRE(distance_exr->spec().channelnames == std::vector<std::string>{"Z"});  // the depth file's layout
    REQUIRE(distance_exr->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, distance.data()));
    CHECK(distance == planes.distance);  // +inf on the background, as depth

    const auto depth16 = read_values(folder.file("k.depth.png"), 1);
    const auto mask = read_values(folder.file("k.mask.png"), 1);
    const auto id = read_values(folder.file("k.id.png"), 1);
    const auto normal = read_values(folder.file("k.normal.png"), 3);
    const auto object = read_values(folder.file("k.object.png"), 1);
    std::size_t covered = 0, partly = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const bool background = planes.id[p] < 0;
        covered += !background;
        partly += planes.alpha[p] > 0.0f && planes.alpha[p] < 1.0f;
        CHECK(depth16[p] == (background ? 0 : std::lround(planes.depth[p] / 0.0005)));
        CHECK(mask[p] == to_byte(planes.alpha[p]));
        CHECK(id[p] == planes.id[p] + 1);
        CHECK(object[p] == (background ? 0 : 1));  // one mesh: object 0
        if (!background) CHECK(distance[p] > depth[p]);  // the default camera: no pixel on the optical axis
        for (int c = 0; c < 3; ++c) {
            CHECK(normal[3 * p + c] == (background ? 0 : to_byte((planes.normal[p][c] + 1.0f) * 0.5f)));
        }
    }
    CHECK(covered > pixels / 10);
    CHECK(partly > 0);  // edges: the mask is fractional, while id and depth stay whole
    CHECK(run.out.find("k.depth.png") != std::string::npos);
}

TEST_CASE("dataset files: object numbers, and values a 16-bit file cannot hold refused before anything is written") {
    TemporaryFolder folder;
    AovPlanes planes;
    planes.rows = 1;
    planes.columns = 4;
    planes.id = {-1, 9, 10, 30};
    planes.depth = {std::numeric_limits<float>::infinity(), 1.0f, 2.0f, 70.0f};
    io::DatasetFiles files;
    files.object = true;
    io::write_dataset_files(planes, {0, 10, 25}, folder.file("o.png"), files, io::DatasetFileOptions{});
    CHECK(read_values(folder.file("o.object.png"), 1) == std::vector<std::uint16_t>{0, 1, 2, 3});

    // 70 scene units at millimetre steps is past 65535: an error naming the scale it needs, and no file.
    files = io::DatasetFiles{};
    files.depth16 = true;
    files.mask = true;  // would be written too, but nothing is
    planes.alpha = {0.0f, 1.0f, 1.0f, 1.0f};
    CHECK_THROWS_WITH(io::write_dataset_files(planes, {0}, folder.file("d.png"), files, io::DatasetFileOptions{}),
                      Catch::Contains("d.depth.png: depth 70") && Catch::Contains("depth scale of at least 0.00106"));
    CHECK_FALSE(std::filesystem::exists(folder.file("d.depth.png")));
    CHECK_FALSE(std::filesystem::exists(folder.file("d.mask.png")));
    io::DatasetFileOptions coarse;
    coarse.depth_scale = 0.01;
    io::write_dataset_files(planes, {0}, folder.file("d.png"), files, coarse);
    CHECK(read_values(folder.file("d.depth.png"), 1) == std::vector<std::uint16_t>{0, 100, 200, 7000});

    files = io::DatasetFiles{};
    files.id = true;
    CHECK_THROWS_WITH(io::check_dataset_files(files, {}, 70000, 1), Catch::Contains("70000 triangles"));
    CHECK_NOTHROW(io::check_dataset_files(files, {}, 65534, 1));
    files.depth16 = true;
    io::DatasetFileOptions zero;
    zero.depth_scale = 0.0;
    CHECK_THROWS_WITH(io::check_dataset_files(files, zero, 10, 1), Catch::Contains("depth-scale"));
    CHECK_THROWS_WITH(io::parse_dataset_files("depth,colour"), Catch::Contains("unknown 'colour'"));
    CHECK(io::to_string(io::parse_dataset_files("all")) == "depth,mask,id,normal,object,distance");
}
