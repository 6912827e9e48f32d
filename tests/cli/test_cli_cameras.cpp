// The camera flags of `phongrast render` (docs/scene-format.md, "Camera"):
// --K, --world-to-camera, --camera-to-world, --projection and --camera, read
// back from the EXR the program writes and compared with the library's render
// of the same camera built through the C++ API.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "cli_run.hpp"
#include "io_test_files.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/render.hpp"

using namespace phongrast;
using Catch::Matchers::Contains;

namespace {

// Two triangles, one behind the other, lit: enough to see a wrong camera.
const char* const kMesh = R"(v -1 -1 0 1 0 0
v 1 -1 0 1 0 0
v 0 1 0 1 0 0
v -1.5 -0.5 -1 0 1 0
v 0.5 -1 -1 0 1 0
v 1.5 1.2 -1 0 1 0
f 1 2 3
f 4 5 6
)";

const char* const kScene = R"({
  "mesh": "two.obj",
  "camera": { "eye": [0.5, 0.3, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "focal": 2, "sensor": [1.2, 1.6] },
  "image": { "height": 48, "width": 64, "background": [0, 0, 0] },
  "material": { "ka": 0.2, "kd": 0.6, "ks": 0.5, "n": 8 },
  "lights": [ { "position": [2, 3, 6], "intensity": [1, 1, 1] } ],
  "shader": "phong"
})";

// fx, fy, cx, cy, skew and a pose [R | t] (a rotation about (1, 1, 0)/sqrt(2) by 0.2 rad, then 6 units ahead).
const Matrix3x3 kK{{{70.0, 1.5, 30.0}, {0.0, 65.0, 25.0}, {0.0, 0.0, 1.0}}};
Matrix3x4 pose() {
    const double c = std::cos(0.2), s = std::sin(0.2), k = 1.0 - c, h = std::sqrt(0.5);
    return {{{c + h * h * k, h * h * k, h * s, 0.1},
             {h * h * k, c + h * h * k, -h * s, -0.2},
             {-h * s, h * s, c, 6.0}}};
}

std::string number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// The pose's 12 (or 16) numbers, comma-separated, row by row.
std::string pose_text(const Matrix3x4& m, bool sixteen) {
    std::string text;
    for (const auto& row : m) {
        for (double v : row) text += (text.empty() ? "" : ",") + number(v);
    }
    return sixteen ? text + ",0,0,0,1" : text;
}

/// The scene file's scene with its mesh loaded, the camera replaced.
Scene scene_with(const TemporaryFolder& folder, const Camera& camera) {
    Scene scene = load_scene_with_library(folder.file("scene.json"));
    scene.camera = camera;
    return scene;
}

void write_fixtures(const TemporaryFolder& folder) {
    folder.write("two.obj", kMesh);
    folder.write("scene.json", kScene);
}

std::vector<glm::vec3> exr_pixels(const TemporaryFolder& folder, const std::string& name) {
    return io::read_image(folder.file(name)).pixels;
}

}  // namespace

TEST_CASE("--K with --world-to-camera (12 or 16 numbers) draws the library's OpenCV render") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const std::string K = "--K " + number(kK[0][0]) + "," + number(kK[1][1]) + "," + number(kK[0][2]) + "," +
                          number(kK[1][2]) + "," + number(kK[0][1]);
    const Run twelve = run_cli(folder, "render scene.json -q " + K + " --world-to-camera " + pose_text(pose(), false) + " -o a.exr");
    INFO(twelve.err);
    REQUIRE(twelve.status == 0);
    const Run sixteen = run_cli(folder, "render scene.json -q " + K + " --world-to-camera " + pose_text(pose(), true) + " -o b.exr");
    REQUIRE(sixteen.status == 0);
    const std::vector<glm::vec3> expected = render(scene_with(folder, Camera::from_opencv(kK, pose()))).image.pixels;
    CHECK(exr_pixels(folder, "a.exr") == expected);
    CHECK(exr_pixels(folder, "b.exr") == expected);
    int lit = 0;
    for (const glm::vec3& p : expected) lit += p != glm::vec3(0.0f);
    CHECK(lit > 100);  // the triangles are in view
}

TEST_CASE("--camera-to-world is the inverse pose") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Camera camera = Camera::from_opencv(kK, pose());
    const Matrix4x4 c2w = camera.opencv.camera_to_world();
    const Matrix3x4 c2w_rows{c2w[0], c2w[1], c2w[2]};
    const Run run = run_cli(folder, "render scene.json -q --K 70,65,30,25,1.5 --camera-to-world " +
                                        pose_text(c2w_rows, true) + " -o c.exr");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const Camera inverse = Camera::from_opencv_camera_to_world(kK, c2w_rows);
    CHECK(exr_pixels(folder, "c.exr") == render(scene_with(folder, inverse)).image.pixels);
}

TEST_CASE("--K alone keeps the look-at camera's pose; with the look-at's own K it draws the look-at picture") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Scene look_at = load_scene_with_library(folder.file("scene.json"));
    const OpenCvCamera same = opencv_form(look_at.camera, 48, 64);
    // fx = 2 * 64 / 1.6 = 80, fy = 2 * 48 / 1.2 = 80, (cx, cy) = (31.5, 23.5).
    CHECK(same.fx == Approx(80.0));
    CHECK(same.cy == 23.5);
    const Run run = run_cli(folder, "render scene.json -q --K 80,80,31.5,23.5 -o k.exr");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const std::vector<glm::vec3> got = exr_pixels(folder, "k.exr");
    const std::vector<glm::vec3> reference = render(look_at).image.pixels;
    // Camera coordinates come from R p + t instead of r.(p - eye): the same pixels up to float rounding.
    REQUIRE(got.size() == reference.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        CHECK((got[i] == glm::vec3(0.0f)) == (reference[i] == glm::vec3(0.0f)));
        CHECK(glm::length(got[i] - reference[i]) < 1e-5f);
    }
}

TEST_CASE("--projection orthographic draws the library's orthographic render") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Run run = run_cli(folder, "render scene.json -q --projection orthographic --sensor 3,4 -o o.exr");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const Camera camera = Camera::orthographic({0.5, 0.3, 5}, {0, 0, 0}, {0, 1, 0}, 3.0, 4.0);
    CHECK(exr_pixels(folder, "o.exr") == render(scene_with(folder, camera)).image.pixels);
}

TEST_CASE("--camera reads a camera file: a bare camera object or one under \"camera\"") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Scene scene = scene_with(folder, Camera::from_opencv(kK, pose()));
    const std::string camera_object = io::scene_to_json(scene, "two.obj");  // a whole scene: its "camera" is read
    folder.write("scene_as_camera.json", camera_object);
    const Run whole = run_cli(folder, "render scene.json -q --camera scene_as_camera.json -o w.exr");
    INFO(whole.err);
    REQUIRE(whole.status == 0);
    const std::vector<glm::vec3> expected = render(scene).image.pixels;
    CHECK(exr_pixels(folder, "w.exr") == expected);

    folder.write("ortho.json", R"({ "projection": "orthographic", "eye": [0.5, 0.3, 5], "lookat": [0, 0, 0], "sensor": [3, 4] })");
    const Run bare = run_cli(folder, "render scene.json -q --camera ortho.json -o o.exr");
    INFO(bare.err);
    REQUIRE(bare.status == 0);
    const Camera ortho = Camera::orthographic({0.5, 0.3, 5}, {0, 0, 0}, {0, 1, 0}, 3.0, 4.0);
    CHECK(exr_pixels(folder, "o.exr") == render(scene_with(folder, ortho)).image.pixels);
}

TEST_CASE("bad camera flags: exit 2, a message naming the flag, no output file") {
    TemporaryFolder folder;
    write_fixtures(folder);
    Matrix3x4 stretched = pose();
    for (double& v : stretched[0]) v *= 1.01;
    stretched[0][3] = 0.1;
    struct Case {
        std::string flags;
        const char* expected;
    };
    const Case cases[] = {
        {"--K 70,65,30,25 --world-to-camera " + pose_text(stretched, false),
         "--world-to-camera: the 3x3 part is not a rotation"},
        {"--K 0,65,30,25", "--K: fx must be a positive finite number"},
        {"--K 70,65,30", "--K"},
        {"--K 70,65,30,25 --world-to-camera 1,0,0,0,0,1,0,0,0,0,1,0,0,0,0", "--world-to-camera: expected 12 or 16 numbers"},
        {"--K 70,65,30,25 --world-to-camera 1,0,0,0,0,1,0,0,0,0,1,0,0,0,1,1", "--world-to-camera: expected the last row 0,0,0,1"},
        {"--K 70,65,30,25 --eye 0,0,3", "an OpenCV camera is placed by its matrices"},
        {"--K 70,65,30,25 --projection orthographic", "--projection orthographic: an OpenCV camera (K) is a perspective"},
        {"--world-to-camera " + pose_text(pose(), false) + " --camera-to-world " + pose_text(pose(), false),
         "give one of the two"},
        {"--camera missing.json", "missing.json: camera file not found"},
        {"--projection orthographic --K 70,65,30,25", "perspective camera"},
    };
    for (const Case& c : cases) {
        INFO(c.flags);
        const Run run = run_cli(folder, "render scene.json " + c.flags + " -o bad.png");
        CHECK(run.status == 2);
        CHECK_THAT(run.err, Contains(c.expected));
        CHECK_FALSE(std::filesystem::exists(folder.file("bad.png")));
    }
    // A bad camera file names the file and the JSON pointer.
    folder.write("bad_camera.json", R"({ "K": [[70, 0, 30], [0, 65, 25], [0, 0, 1]], "world_to_camera": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5]] })");
    const Run run = run_cli(folder, "render scene.json --camera bad_camera.json -o bad.png");
    CHECK(run.status == 2);
    CHECK_THAT(run.err, Contains("bad_camera.json: /world_to_camera: the 3x3 part is not a rotation"));
    CHECK_FALSE(std::filesystem::exists(folder.file("bad.png")));
}
