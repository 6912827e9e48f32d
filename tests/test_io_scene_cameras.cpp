// Scene files' cameras of contract version 2 (docs/scene-format.md, "Camera"):
// OpenCV K with world_to_camera or camera_to_world, and orthographic.
#include <catch2/catch.hpp>

#include <cmath>

#include "phongrast/camera.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/scene_file.hpp"

using phongrast::io::parse_scene_json;
using Catch::Matchers::Contains;

namespace {

/// A scene whose camera object is `camera` (the text between the braces).
std::string scene_with_camera(const std::string& camera) {
    return R"({ "mesh": "a.obj", "camera": { )" + camera + R"( }, "image": { "height": 48, "width": 64 } })";
}

// A rotation by 90 degrees about y: R = [[0,0,-1],[0,1,0],[1,0,0]]; camera_to_world is its transpose with the eye.
const char* const K_text = R"("K": [[500, 2, 31.5], [0, 400, 23.5], [0, 0, 1]])";
const char* const world_to_camera_text =
    R"("world_to_camera": [[0, 0, -1, 1], [0, 1, 0, 2], [1, 0, 0, 10], [0, 0, 0, 1]])";

}  // namespace

TEST_CASE("an OpenCV camera is read from K and world_to_camera") {
    const phongrast::io::SceneFile file =
        parse_scene_json(scene_with_camera(std::string(K_text) + ", " + world_to_camera_text), "s.json", "");
    const phongrast::Camera& c = file.scene.camera;
    CHECK(c.model == phongrast::CameraModel::opencv);
    CHECK(c.opencv.fx == 500.0);
    CHECK(c.opencv.fy == 400.0);
    CHECK(c.opencv.cx == 31.5);
    CHECK(c.opencv.cy == 23.5);
    CHECK(c.opencv.skew == 2.0);
    CHECK(c.opencv.world_to_camera[0][2] == -1.0);
    CHECK(c.opencv.world_to_camera[2][3] == 10.0);
    CHECK(file.warnings.empty());
}

TEST_CASE("camera_to_world is the same camera as its inverse world_to_camera") {
    // R^T t = (10, 2, -1), so the eye -R^T t is (-10, -2, 1); camera_to_world = [R^T | eye].
    const phongrast::io::SceneFile from_inverse = parse_scene_json(
        scene_with_camera(std::string(K_text) +
                          R"(, "camera_to_world": [[0, 0, 1, -10], [0, 1, 0, -2], [-1, 0, 0, 1], [0, 0, 0, 1]])"),
        "s.json", "");
    const phongrast::io::SceneFile direct =
        parse_scene_json(scene_with_camera(std::string(K_text) + ", " + world_to_camera_text), "s.json", "");
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            CHECK(from_inverse.scene.camera.opencv.world_to_camera[i][j] ==
                  Approx(direct.scene.camera.opencv.world_to_camera[i][j]).margin(1e-15));
        }
    }
    CHECK(direct.scene.camera.opencv.eye() == glm::dvec3(-10, -2, 1));
}

TEST_CASE("an orthographic camera is read, focal is not required") {
    const phongrast::io::SceneFile file = parse_scene_json(
        scene_with_camera(R"("projection": "orthographic", "eye": [0, 0, 5], "lookat": [0, 0, 0], "sensor": [3, 4])"),
        "s.json", "");
    CHECK(file.scene.camera.model == phongrast::CameraModel::orthographic);
    CHECK(file.scene.camera.sensor_width == 4.0);
    CHECK(file.warnings.empty());
    // A focal is ignored with a warning.
    const phongrast::io::SceneFile with_focal = parse_scene_json(
        scene_with_camera(R"("projection": "orthographic", "eye": [0, 0, 5], "lookat": [0, 0, 0], "focal": 2, "sensor": [3, 4])"),
        "s.json", "");
    REQUIRE(with_focal.warnings.size() == 1);
    CHECK_THAT(with_focal.warnings[0], Contains("/camera/focal"));
}

TEST_CASE("scene_to_json writes OpenCV and orthographic cameras that read back the same") {
    for (const std::string& camera :
         {std::string(K_text) + ", " + world_to_camera_text,
          std::string(R"("projection": "orthographic", "eye": [0, 1, 5], "lookat": [0, 0, 0], "sensor": [3, 4])")}) {
        const phongrast::io::SceneFile file = parse_scene_json(scene_with_camera(camera), "a.json", "");
        const phongrast::io::SceneFile again =
            parse_scene_json(phongrast::io::scene_to_json(file.scene, "a.obj"), "b.json", "");
        CHECK(again.warnings.empty());
        const phongrast::Camera& a = file.scene.camera;
        const phongrast::Camera& b = again.scene.camera;
        CHECK(a.model == b.model);
        CHECK(a.eye == b.eye);
        CHECK(a.sensor_height == b.sensor_height);
        CHECK(a.opencv.K() == b.opencv.K());
        CHECK(a.opencv.world_to_camera == b.opencv.world_to_camera);
    }
}

TEST_CASE("bad cameras: the message names the file and the JSON pointer") {
    struct Case {
        std::string camera;
        const char* expected;
    };
    const std::string K = K_text, pose = world_to_camera_text;
    const Case cases[] = {
        {K, "/camera/world_to_camera: missing required field"},
        {pose, "/camera/K: missing"},
        {K + ", " + pose + R"(, "camera_to_world": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]])",
         "/camera/camera_to_world: give one of"},
        {R"("K": [[0, 0, 31.5], [0, 400, 23.5], [0, 0, 1]], )" + pose, "/camera/K/0/0: expected fx, a positive number"},
        {R"("K": [[500, 0, 31.5], [0, -4, 23.5], [0, 0, 1]], )" + pose, "/camera/K/1/1: expected fy"},
        {R"("K": [[500, 0, 31.5], [0, 400, 23.5], [0, 1, 1]], )" + pose, "/camera/K/2: expected [0, 0, 1]"},
        {R"("K": [[500, 0, 31.5], [0, 400, 23.5]], )" + pose, "/camera/K: expected [[fx, s, cx]"},
        {R"("K": [[500, 0, 31.5], [0, 400], [0, 0, 1]], )" + pose, "/camera/K/1: expected a row of 3 numbers"},
        {K + R"(, "world_to_camera": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
         "/camera/world_to_camera: the 3x3 part is not a rotation"},
        {K + R"(, "world_to_camera": [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
         "/camera/world_to_camera: the 3x3 part has determinant -1"},
        {K + R"(, "world_to_camera": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])",
         "/camera/world_to_camera/3: expected the last row [0, 0, 0, 1]"},
        {K + R"(, "world_to_camera": [[1, 0, 0, 1e999], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])",
         "expected a finite number, got 1e999"},
        {K + R"(, "camera_to_world": [[1, 0, 0], [0, 1, 0], [0, 0, 1]])", "/camera/camera_to_world/0: expected a row of 4 numbers"},
        {R"("projection": "fisheye", "eye": [0, 0, 5], "lookat": [0, 0, 0], "sensor": [3, 4])",
         "/camera/projection: expected \"perspective\" or \"orthographic\""},
        {R"("projection": "orthographic", )" + K + ", " + pose, "/camera/projection: an OpenCV camera (K) is a perspective"},
        {R"("projection": "orthographic", "eye": [0, 0, 5], "lookat": [0, 0, 0])", "/camera/sensor: missing required field"},
    };
    for (const Case& c : cases) {
        INFO(c.camera);
        CHECK_THROWS_WITH(parse_scene_json(scene_with_camera(c.camera), "scene.json", ""),
                          Contains("scene.json") && Contains(c.expected));
    }
}

TEST_CASE("a 3x4 pose ([R | t] without the last row) is accepted") {
    const phongrast::io::SceneFile file = parse_scene_json(
        scene_with_camera(std::string(K_text) + R"(, "world_to_camera": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 3]])"),
        "s.json", "");
    CHECK(file.scene.camera.opencv.world_to_camera[2][3] == 3.0);
}

TEST_CASE("parse_camera_object reads one camera as a scene file's, messages under the given JSON pointer") {
    using phongrast::io::parse_camera_object;
    using phongrast::io::UnusedCameraFields;
    const std::string camera = "{" + std::string(K_text) + ", " + world_to_camera_text + "}";
    const phongrast::Camera from_scene = parse_scene_json(scene_with_camera(std::string(K_text) + ", " + world_to_camera_text),
                                                          "s.json", "").scene.camera;
    const phongrast::Camera alone = parse_camera_object(camera, "jobs.jsonl:3", "/cameras/2", UnusedCameraFields::refuse, nullptr);
    CHECK(alone.model == phongrast::CameraModel::opencv);
    CHECK(alone.opencv.world_to_camera == from_scene.opencv.world_to_camera);
    CHECK(alone.opencv.K() == from_scene.opencv.K());
    // The scene reader's messages, under the pointer given.
    CHECK_THROWS_WITH(parse_camera_object(R"({"K": [[0, 0, 31.5], [0, 400, 23.5], [0, 0, 1]], )" +
                                              std::string(world_to_camera_text) + "}",
                                          "jobs.jsonl:3", "/cameras/2", UnusedCameraFields::refuse, nullptr),
                      "jobs.jsonl:3: /cameras/2/K/0/0: expected fx, a positive number, got 0");
    CHECK_THROWS_WITH(parse_camera_object("[1]", "c.json", "", UnusedCameraFields::warn, nullptr),
                      "c.json: /: expected an object, got an array of 1");
    CHECK_THROWS_WITH(parse_camera_object(R"({"eye": [1, 2, 3], "lookat": [1, 2, 3], "focal": 1, "sensor": [1, 1]})",
                                          "c.json", "/cam", UnusedCameraFields::warn, nullptr),
                      "c.json: /cam/lookat: must differ from camera.eye");
    CHECK_THROWS_AS(parse_camera_object(camera, "c.json", "cameras", UnusedCameraFields::warn, nullptr),
                    std::invalid_argument);  // not a JSON pointer: a caller's mistake
    // Unused fields: warnings, as in a scene file, or errors when refused.
    const std::string extra = R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1], "fov": 40})";
    std::vector<std::string> warnings;
    CHECK(parse_camera_object(extra, "c.json", "/cameras/0", UnusedCameraFields::warn, &warnings).focal == 1.0);
    CHECK(warnings == std::vector<std::string>{"c.json: ignoring unknown field /cameras/0/fov"});
    CHECK_THROWS_WITH(parse_camera_object(extra, "c.json", "/cameras/0", UnusedCameraFields::refuse, nullptr),
                      Contains("c.json: /cameras/0/fov: unknown field"));
    const std::string both = "{\"eye\": [0, 0, 5], " + std::string(K_text) + ", " + world_to_camera_text + "}";
    warnings.clear();
    CHECK(parse_camera_object(both, "c.json", "", UnusedCameraFields::warn, &warnings).model == phongrast::CameraModel::opencv);
    CHECK(warnings.size() == 1);
    CHECK_THROWS_WITH(parse_camera_object(both, "c.json", "", UnusedCameraFields::refuse, nullptr),
                      Contains("c.json: /eye: an OpenCV camera (K) is placed by its matrices"));
}
