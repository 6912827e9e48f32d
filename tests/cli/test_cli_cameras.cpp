// The camera flags of `phongrast render` (docs/scene-format.md, "Camera"):
// --K, --world-to-camera, --camera-to-world, --projection and --camera, read
// back from the EXR the program writes and compared with the library's render
// of the same camera built through the C++ API.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/camera_record.hpp"
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

TEST_CASE("render --K with --world-to-camera (12 or 16 numbers) draws the library's OpenCV render") {
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

TEST_CASE("render --camera-to-world is the inverse pose") {
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

TEST_CASE("render --K alone keeps the look-at camera's pose, and with the look-at's own K it draws the look-at picture") {
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

TEST_CASE("render --projection orthographic draws the library's orthographic render") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Run run = run_cli(folder, "render scene.json -q --projection orthographic --sensor 3,4 -o o.exr");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const Camera camera = Camera::orthographic({0.5, 0.3, 5}, {0, 0, 0}, {0, 1, 0}, 3.0, 4.0);
    CHECK(exr_pixels(folder, "o.exr") == render(scene_with(folder, camera)).image.pixels);
}

TEST_CASE("render --camera reads a camera file: a bare camera object or one under \"camera\"") {
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
        {"--camera-out nowhere/cam.json", "--camera-out folder 'nowhere' does not exist"},
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

namespace {

/// An OBJ of a UV sphere of radius `radius` around `centre` (closed, convex).
std::string sphere_obj(const glm::dvec3& centre, double radius) {
    std::string text;
    const int stacks = 10, slices = 14;
    const double pi = std::acos(-1.0);
    for (int i = 0; i <= stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const double theta = pi * i / stacks, phi = 2.0 * pi * j / slices;
            const glm::dvec3 p = centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                              std::sin(theta) * std::sin(phi));
            text += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
        }
    }
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const int a = i * slices + j + 1, b = i * slices + (j + 1) % slices + 1;
            const int c = a + slices, d = b + slices;
            text += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
            text += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(b) + "\n";
        }
    }
    return text;
}

/// Checks a --camera-out file against the image it describes, without the
/// renderer's projection: each vertex projected by the file's K [R | t]
/// (numbers read from the JSON, arithmetic here) lands on or next to a pixel
/// the silhouette (alpha) covers, and the projected bounding box is the
/// silhouette's to a pixel.
void check_camera_file(const TemporaryFolder& folder, const std::string& camera_file, const std::string& image_file,
                       const std::vector<glm::dvec3>& vertices) {
    const nlohmann::json document = nlohmann::json::parse(read_text(folder.file(camera_file)));
    const nlohmann::json& record = document.at("images").at(0);
    CHECK(record.at("file_path") == image_file);
    const int rows = record.at("height"), columns = record.at("width");
    const auto K = record.at("K").get<std::vector<std::vector<double>>>();
    const auto w2c = record.at("world_to_camera").get<std::vector<std::vector<double>>>();
    const auto gl = record.at("camera_to_world_opengl").get<std::vector<std::vector<double>>>();
    // camera_to_world_opengl = inverse(world_to_camera) with the y and z axes negated: R^T columns.
    for (int i = 0; i < 3; ++i) {
        CHECK(gl[i][0] == Approx(w2c[0][i]).margin(1e-12));
        CHECK(gl[i][1] == Approx(-w2c[1][i]).margin(1e-12));
        CHECK(gl[i][2] == Approx(-w2c[2][i]).margin(1e-12));
    }
    CHECK(record.at("near").get<double>() > 0.0);

    Image image;
    AovPlanes planes;
    io::read_exr_with_aovs(folder.file(image_file), image, planes);
    REQUIRE(image.rows == rows);
    REQUIRE(image.columns == columns);
    REQUIRE(planes.alpha.size() == static_cast<std::size_t>(rows) * columns);
    const auto covered = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < rows && j < columns && planes.alpha[static_cast<std::size_t>(i) * columns + j] > 0.0f;
    };
    int silhouette_top = rows, silhouette_bottom = -1, silhouette_left = columns, silhouette_right = -1;
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            if (!covered(i, j)) continue;
            silhouette_top = std::min(silhouette_top, i);
            silhouette_bottom = std::max(silhouette_bottom, i);
            silhouette_left = std::min(silhouette_left, j);
            silhouette_right = std::max(silhouette_right, j);
        }
    }
    REQUIRE(silhouette_bottom >= 0);
    double top = 1e300, bottom = -1e300, left = 1e300, right = -1e300;
    int near_silhouette = 0;
    for (const glm::dvec3& p : vertices) {
        double q[3];
        for (int i = 0; i < 3; ++i) q[i] = w2c[i][0] * p.x + w2c[i][1] * p.y + w2c[i][2] * p.z + w2c[i][3];
        REQUIRE(q[2] > 0.0);
        // OpenCV pixel coordinates, + 0.5 for the contract's (pixel (i, j) covers [j, j+1) x [i, i+1)).
        const double column = (K[0][0] * q[0] + K[0][1] * q[1]) / q[2] + K[0][2] + 0.5;
        const double row = K[1][1] * q[1] / q[2] + K[1][2] + 0.5;
        top = std::min(top, row);
        bottom = std::max(bottom, row);
        left = std::min(left, column);
        right = std::max(right, column);
        const int i = static_cast<int>(std::floor(row)), j = static_cast<int>(std::floor(column));
        bool found = false;
        for (int di = -1; di <= 1; ++di) {
            for (int dj = -1; dj <= 1; ++dj) found = found || covered(i + di, j + dj);
        }
        near_silhouette += found;
    }
    CHECK(near_silhouette == static_cast<int>(vertices.size()));
    // The silhouette's pixel centres lie within the projected box, which reaches at most a pixel beyond them.
    CHECK(std::abs(std::floor(top) - silhouette_top) <= 1.0);
    CHECK(std::abs(std::floor(bottom) - silhouette_bottom) <= 1.0);
    CHECK(std::abs(std::floor(left) - silhouette_left) <= 1.0);
    CHECK(std::abs(std::floor(right) - silhouette_right) <= 1.0);
}

std::vector<glm::dvec3> obj_vertices(const std::string& text) {
    std::vector<glm::dvec3> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) != 0) continue;
        std::istringstream fields(line.substr(2));
        glm::dvec3 p;
        fields >> p.x >> p.y >> p.z;
        out.push_back(p);
    }
    return out;
}

}  // namespace

TEST_CASE("render --camera-out: the written matrices project the mesh onto its rendered silhouette") {
    TemporaryFolder folder;
    const std::string sphere = sphere_obj({0.3, -0.2, 0.1}, 1.0);
    folder.write("sphere.obj", sphere);
    const std::vector<glm::dvec3> vertices = obj_vertices(sphere);
    SECTION("an automatically framed look-at camera") {
        const Run run = run_cli(folder, "render sphere.obj -q --size 96x72 --aov alpha -o s.exr --camera-out cam.json");
        INFO(run.err);
        REQUIRE(run.status == 0);
        check_camera_file(folder, "cam.json", "s.exr", vertices);
        // Its "camera" reads back through --camera: the same picture.
        const Run again = run_cli(folder, "render sphere.obj -q --size 96x72 --aov alpha -o t.exr --camera cam.json");
        REQUIRE(again.status == 0);
        CHECK(exr_pixels(folder, "t.exr") == exr_pixels(folder, "s.exr"));
    }
    SECTION("an OpenCV camera with skew") {
        Matrix3x4 p = pose();
        const Run run = run_cli(folder, "render sphere.obj -q --size 80x64 --aov alpha -o o.exr --camera-out sub/../cam.json"
                                        " --K 60,58,38,30,6 --world-to-camera " + pose_text(p, false));
        INFO(run.err);
        REQUIRE(run.status == 2);  // sub/ does not exist: refused before rendering
        CHECK_FALSE(std::filesystem::exists(folder.file("o.exr")));
        std::filesystem::create_directory(folder.file("sub"));
        const Run ok = run_cli(folder, "render sphere.obj -q --size 80x64 --aov alpha -o o.exr --camera-out sub/cam.json"
                                       " --K 60,58,38,30,6 --world-to-camera " + pose_text(p, false));
        INFO(ok.err);
        REQUIRE(ok.status == 0);
        const nlohmann::json record = nlohmann::json::parse(read_text(folder.file("sub/cam.json"))).at("images").at(0);
        CHECK(record.at("file_path") == "../o.exr");  // relative to the camera file's folder
        CHECK(record.at("look_at").is_null());
        std::filesystem::copy_file(folder.file("sub/cam.json"), folder.file("cam2.json"));
        // check_camera_file reads the image by the name given here (the record's path is relative to sub/).
        const nlohmann::json document = nlohmann::json::parse(read_text(folder.file("cam2.json")));
        CHECK(document.at("images").at(0).at("K").at(0).at(1) == 6.0);
        nlohmann::json fixed = document;
        fixed["images"][0]["file_path"] = "o.exr";
        folder.write("cam2.json", fixed.dump());
        check_camera_file(folder, "cam2.json", "o.exr", vertices);
    }
    SECTION("the shared spot mesh, if present") {
        const std::string spot = std::string(PHONGRAST_SHARED_ASSETS_DIR) + "/spot.obj";
        if (!std::filesystem::exists(spot)) {
            WARN("skipped: " + spot + " is missing");
            return;
        }
        const Run run = run_cli(folder, "render '" + spot + "' -q --size 120x90 --aov alpha -o spot.exr --camera-out cam.json");
        INFO(run.err);
        REQUIRE(run.status == 0);
        check_camera_file(folder, "cam.json", "spot.exr", obj_vertices(read_text(spot)));
    }
}

TEST_CASE("render --camera-out of an orthographic camera has no K and says so") {
    TemporaryFolder folder;
    write_fixtures(folder);
    const Run run = run_cli(folder, "render scene.json -q --projection orthographic -o o.png --camera-out cam.json");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const nlohmann::json document = nlohmann::json::parse(read_text(folder.file("cam.json")));
    const nlohmann::json& record = document.at("images").at(0);
    CHECK(record.at("projection") == "orthographic");
    CHECK(record.at("K").is_null());
    CHECK(record.at("near") == 0.0);
    CHECK(document.at("camera").at("projection") == "orthographic");
    CHECK(record.at("world_to_camera").at(2).at(3).get<double>() ==
          Approx(std::sqrt(0.5 * 0.5 + 0.3 * 0.3 + 5.0 * 5.0)));  // the eye's distance along f to the origin
}

TEST_CASE("transforms.json: OpenGL camera-to-world and centres at +0.5, and no orthographic or skewed camera") {
    Scene scene;
    scene.image.rows = 40;
    scene.image.columns = 60;
    scene.camera = Camera::look_at({1, 2, 5}, {0, 0, 0}, {0, 1, 0}, 2.0, 1.0, 1.5);
    io::CameraRecord record = io::camera_record(scene, "/data/set/a.png", "/data/set/transforms.json");
    const nlohmann::json transforms = nlohmann::json::parse(io::transforms_json({record, record}));
    const OpenCvCamera k = opencv_form(scene.camera, 40, 60);
    CHECK(transforms["camera_model"] == "OPENCV");
    CHECK(transforms["fl_x"].get<double>() == k.fx);
    CHECK(transforms["cx"].get<double>() == k.cx + 0.5);
    CHECK(transforms["cx"].get<double>() == 30.0);  // the look-at camera's centre: N / 2
    CHECK(transforms["w"] == 60);
    CHECK(transforms["camera_angle_x"].get<double>() == Approx(2.0 * std::atan(60.0 / (2.0 * k.fx))));
    REQUIRE(transforms["frames"].size() == 2);
    CHECK(transforms["frames"][0]["file_path"] == "a.png");
    CHECK_FALSE(transforms["frames"][1].contains("fl_x"));  // the same intrinsics: not repeated
    // The last column of camera_to_world is the eye; its z axis points backward (from the look-at point).
    const auto& m = transforms["frames"][0]["transform_matrix"];
    CHECK(m[0][3].get<double>() == Approx(1.0));
    CHECK(m[1][3].get<double>() == Approx(2.0));
    CHECK(m[2][3].get<double>() == Approx(5.0));
    const glm::dvec3 backward = glm::normalize(glm::dvec3(1, 2, 5));
    CHECK(m[0][2].get<double>() == Approx(backward.x));
    CHECK(m[2][2].get<double>() == Approx(backward.z));

    record.camera = Camera::orthographic({1, 2, 5}, {0, 0, 0}, {0, 1, 0}, 1.0, 1.5);
    CHECK_THROWS_WITH(io::transforms_json({record}), Catch::Contains("orthographic camera has no focal length"));
    record.camera = Camera::from_opencv({{{50.0, 3.0, 30.0}, {0.0, 50.0, 20.0}, {0.0, 0.0, 1.0}}},
                                        {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 5}}});
    CHECK_THROWS_WITH(io::transforms_json({record}), Catch::Contains("K has skew 3"));
    CHECK_THROWS_WITH(io::transforms_json({}), Catch::Contains("no images"));
}
