// The batch manifest: the three kinds of job, settings, output names, and every
// bad line stopping the batch with a message naming the line and the field.
#include <catch2/catch.hpp>

#include "batch_manifest.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/option_names.hpp"

using namespace phongrast::cli;

namespace {

Manifest parse(const std::string& text, const JobSettings& defaults = {}) {
    return parse_manifest(text, "m.jsonl", "/data", defaults);
}

/// The message of the error that parsing `text` raises ("" if none).
std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const phongrast::io::FileError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a manifest holds scene files, inline scenes and turntables, paths relative to its folder") {
    const Manifest manifest = parse(
        "{\"scene\": \"figures/knot.json\"}\n"
        "\n"
        "{\"scene\": {\"mesh\": \"knot.obj\"}, \"shader\": \"gouraud\"}\n"
        "{\"mesh\": \"meshes/chair.obj\", \"views\": 12, \"elevation\": 20, \"size\": \"64x32\", \"samples\": 2}\n");
    REQUIRE(manifest.jobs.size() == 3);
    CHECK(manifest.jobs[0].kind == JobKind::scene_file);
    CHECK(manifest.jobs[0].path == "/data/figures/knot.json");
    CHECK(manifest.jobs[0].outputs == std::vector<std::string>{"knot.png"});
    CHECK(manifest.jobs[1].kind == JobKind::inline_scene);
    CHECK(manifest.jobs[1].line == 3);  // the blank line counts
    CHECK(manifest.jobs[1].folder == "/data");
    CHECK(manifest.jobs[1].settings.shader == "gouraud");
    CHECK(manifest.jobs[1].outputs == std::vector<std::string>{"line-3.png"});
    const BatchJob& turntable = manifest.jobs[2];
    CHECK(turntable.kind == JobKind::mesh);
    CHECK(turntable.path == "/data/meshes/chair.obj");
    CHECK(turntable.views == 12);
    CHECK(turntable.layout == ViewLayout::turntable);
    CHECK(turntable.elevations == std::vector<double>{20.0});
    CHECK(turntable.settings.size == "64x32");
    CHECK(turntable.settings.samples == 2);
    REQUIRE(turntable.outputs.size() == 12);
    CHECK(turntable.outputs.front() == "chair-00.png");
    CHECK(turntable.outputs.back() == "chair-11.png");
}

TEST_CASE("view layouts: elevation rings multiply the views, a sphere or hemisphere has as many as it says") {
    const Manifest manifest = parse(
        "{\"mesh\": \"a.obj\", \"views\": 8, \"elevations\": [-15, 0, 30.5]}\n"
        "{\"mesh\": \"b.obj\", \"layout\": \"sphere\", \"views\": 50}\n"
        "{\"mesh\": \"c.obj\", \"layout\": \"hemisphere\", \"views\": 7}\n"
        "{\"mesh\": \"d.obj\", \"layout\": \"turntable\"}\n");
    REQUIRE(manifest.jobs.size() == 4);
    CHECK(manifest.jobs[0].layout == ViewLayout::turntable);
    CHECK(manifest.jobs[0].views == 24);
    CHECK(manifest.jobs[0].elevations == std::vector<double>{-15.0, 0.0, 30.5});
    CHECK(manifest.jobs[0].outputs.size() == 24);
    CHECK(manifest.jobs[0].outputs.back() == "a-23.png");
    CHECK(manifest.jobs[1].layout == ViewLayout::sphere);
    CHECK(manifest.jobs[1].views == 50);
    CHECK(manifest.jobs[1].outputs.back() == "b-49.png");
    CHECK(manifest.jobs[2].layout == ViewLayout::hemisphere);
    CHECK(manifest.jobs[2].views == 7);
    CHECK(manifest.jobs[3].views == 1);
    CHECK(manifest.jobs[3].elevations == std::vector<double>{0.0});
    CHECK(manifest.jobs[3].outputs == std::vector<std::string>{"d.png"});
}

TEST_CASE("bad view layouts name the field") {
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"layout\": \"cube\"}"),
               Catch::StartsWith("m.jsonl:1: /layout: expected \"turntable\", \"sphere\" or \"hemisphere\", got \"cube\""));
    CHECK_THAT(error_of("{\"scene\": \"s.json\", \"layout\": \"sphere\"}"), Catch::StartsWith("m.jsonl:1: /layout: only a \"mesh\""));
    CHECK_THAT(error_of("{\"scene\": \"s.json\", \"elevations\": [1]}"), Catch::StartsWith("m.jsonl:1: /elevations: only a \"mesh\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"layout\": \"sphere\", \"elevation\": 10}"),
               Catch::Contains("/elevation: a sphere layout chooses its own elevations"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"layout\": \"hemisphere\", \"elevations\": [10]}"),
               Catch::Contains("/elevations: a hemisphere layout chooses its own elevations"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevation\": 10, \"elevations\": [10]}"),
               Catch::Contains("/elevations: both \"elevation\" and \"elevations\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevations\": []}"), Catch::Contains("/elevations: expected a non-empty array"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevations\": 10}"), Catch::Contains("/elevations: expected a non-empty array"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevations\": [0, 90]}"),
               Catch::Contains("/elevations/1: expected degrees between -90 and 90 (exclusive), got 90"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevations\": [0, \"up\"]}"),
               Catch::Contains("/elevations/1: expected degrees between -90 and 90 (exclusive), got the string \"up\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"views\": 60000, \"elevations\": [0, 10]}"),
               Catch::Contains("/elevations: 60000 views x 2 rings = 120000 images; at most 100000 per job"));
}

TEST_CASE("command-line settings fill what a line leaves out, and a line's own win") {
    JobSettings defaults;
    defaults.size = "32x32";
    defaults.shader = "flat";
    defaults.samples = 3;
    const Manifest manifest = parse("{\"mesh\": \"a.obj\"}\n{\"mesh\": \"b.obj\", \"size\": \"8x8\", \"samples\": 1}\n",
                                    defaults);
    CHECK(manifest.jobs[0].settings.size == "32x32");
    CHECK(manifest.jobs[0].settings.shader == "flat");
    CHECK(manifest.jobs[0].settings.samples == 3);
    CHECK(manifest.jobs[1].settings.size == "8x8");
    CHECK(manifest.jobs[1].settings.shader == "flat");
    CHECK(manifest.jobs[1].settings.samples == 1);
}

TEST_CASE("output patterns: {name}, {line}, {view} padded to the last view, {view:N}, subfolders, EXR") {
    CHECK(expand_output_pattern("{name}-{view}.png", "cup", 4, 7, 100) == "cup-07.png");
    CHECK(expand_output_pattern("{name}-{view}.png", "cup", 4, 7, 8) == "cup-7.png");
    CHECK(expand_output_pattern("a/{line}/{view:4}.exr", "cup", 12, 7, 8) == "a/12/0007.exr");
    CHECK_THROWS_WITH(expand_output_pattern("{colour}.png", "cup", 1, 0, 1),
                      Catch::Contains("unknown placeholder {colour}"));
    CHECK_THROWS_WITH(expand_output_pattern("{name.png", "cup", 1, 0, 1), Catch::Contains("'{' without '}'"));
    const Manifest manifest = parse("{\"mesh\": \"cup.obj\", \"views\": 2, \"output\": \"turn/./{name}_{view}.exr\"}");
    CHECK(manifest.jobs[0].outputs == std::vector<std::string>{"turn/cup_0.exr", "turn/cup_1.exr"});
}

TEST_CASE("a bad manifest line names the line and the field") {
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\"}\n{\"mesh\": \"b.obj\",}\n"),
               Catch::Matches("m\\.jsonl:2:[0-9]+: malformed JSON: .*"));
    CHECK_THAT(error_of("[1, 2]"), Catch::StartsWith("m.jsonl:1: expected a JSON object"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"sampels\": 4}"), Catch::StartsWith("m.jsonl:1: /sampels: unknown field"));
    CHECK_THAT(error_of("{\"views\": 4}"), Catch::StartsWith("m.jsonl:1: expected \"scene\""));
    CHECK_THAT(error_of("{\"scene\": \"s.json\", \"mesh\": \"a.obj\"}"), Catch::Contains("both \"scene\" and \"mesh\""));
    CHECK_THAT(error_of("{\"scene\": 3}"), Catch::StartsWith("m.jsonl:1: /scene: expected a non-empty string, got 3"));
    CHECK_THAT(error_of("{\"scene\": \"s.json\", \"views\": 3}"), Catch::StartsWith("m.jsonl:1: /views: only a \"mesh\""));
    CHECK_THAT(error_of("\n\n{\"mesh\": \"a.obj\", \"views\": 0}"),
               Catch::StartsWith("m.jsonl:3: /views: expected a whole number from 1 to"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"views\": \"4\"}"), Catch::Contains("/views: expected a whole number"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"views\": 2.5}"), Catch::Contains("/views: expected a whole number"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"elevation\": 90}"), Catch::Contains("/elevation: expected degrees"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"shader\": \"toon\"}"), Catch::Contains("/shader: shader: unknown 'toon'"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"lighting\": \"glow\"}"), Catch::Contains("/lighting: lighting: unknown term"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"size\": \"12by8\"}"), Catch::Contains("/size: expected \"WxH\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"samples\": 17}"), Catch::Contains("/samples: expected a whole number from 1 to 16"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"mode\": \"fast\"}"), Catch::Contains("/mode: expected \"exact\" or \"seed\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"texture_filter\": \"cubic\"}"),
               Catch::Contains("/texture_filter: expected \"bilinear\", \"nearest\" or \"trilinear\", got \"cubic\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"visibility\": \"zbuffer\"}"),
               Catch::Contains("/visibility: expected \"painter\" or \"depth-buffer\""));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"output\": \"a.jpg\"}"), Catch::Contains("/output: a.jpg: unknown image format"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"output\": \"/tmp/a.png\"}"), Catch::Contains("/output: '/tmp/a.png' must stay inside"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"output\": \"x/../../a.png\"}"), Catch::Contains("must stay inside"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"output\": \"{what}.png\"}"), Catch::Contains("/output: unknown placeholder"));
}

TEST_CASE("the library's named options are manifest fields, with every spelling the command line takes") {
    const Manifest manifest = parse_manifest(
        "{\"mesh\": \"a.obj\", \"visibility\": \"depth_buffer\", \"texture_filter\": \"nearest\", \"overdraw\": \"all\"}\n"
        "{\"mesh\": \"b.obj\"}\n",
        "m.jsonl", "/data", JobSettings{});
    REQUIRE(manifest.jobs.size() == 2);
    using namespace phongrast;
    const RenderOptions options = options_from_names(manifest.jobs[0].settings.options);
    CHECK(options.visibility == Visibility::depth_buffer);
    CHECK(options.texture_filter == TextureFilter::nearest);
    CHECK(options.overdraw == Overdraw::shade_all);
    const RenderOptions defaults = options_from_names(manifest.jobs[1].settings.options);
    CHECK(defaults.visibility == Visibility::painter);
    CHECK(defaults.texture_filter == TextureFilter::bilinear);
}

TEST_CASE("two jobs (or two views of one) writing the same image are an error naming both lines") {
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\"}\n{\"mesh\": \"other/a.obj\"}"),
               Catch::StartsWith("m.jsonl:2: /output: 'a.png' is also written by line 1"));
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\", \"views\": 3, \"output\": \"a.png\"}"),
               Catch::Contains("also written by line 1 (add {view} to the pattern)"));
    CHECK_NOTHROW(parse("{\"mesh\": \"a.obj\"}\n{\"mesh\": \"a.obj\", \"shader\": \"flat\", \"output\": \"a-flat.png\"}"));
}

namespace {

// Cameras in the scene file's schema, as manifest lines write them.
const char* const look_at_camera = R"({"eye": [0, 3, 12], "lookat": [0, 0, 0], "up": [0, 1, 0], "focal": 4, "sensor": [6, 8]})";
const char* const opencv_camera =
    R"({"K": [[40, 0, 31.5], [0, 41.25, 23.5], [0, 0, 1]], "world_to_camera": [[1, 0, 0, 0.25], [0, -1, 0, 0.5], [0, 0, -1, 10], [0, 0, 0, 1]]})";
const char* const orthographic_camera =
    R"({"projection": "orthographic", "eye": [5, 0, 0], "lookat": [0, 0, 0], "sensor": [4, 4]})";

/// A mesh job of size 64x48 with `cameras` (the array's text) and `extra` fields.
std::string camera_line(const std::string& cameras, const std::string& extra = "") {
    return "{\"mesh\": \"a.obj\", \"size\": \"64x48\", \"cameras\": " + cameras + extra + "}";
}

}  // namespace

TEST_CASE("a mesh job's cameras: one view per camera, each exactly as given, numbered as generated views") {
    const std::string cameras = std::string("[") + look_at_camera + ", " + opencv_camera + ", " + orthographic_camera + "]";
    const Manifest manifest = parse(camera_line(cameras) + "\n" + camera_line(std::string("[") + look_at_camera + "]"));
    REQUIRE(manifest.jobs.size() == 2);
    const BatchJob& job = manifest.jobs[0];
    CHECK(job.kind == JobKind::mesh);
    CHECK(job.views == 3);
    REQUIRE(job.cameras.size() == 3);
    CHECK(job.outputs == std::vector<std::string>{"a-0.png", "a-1.png", "a-2.png"});
    using phongrast::CameraModel;
    const phongrast::Camera& look_at = job.cameras[0];
    CHECK(look_at.model == CameraModel::look_at);
    CHECK(look_at.eye == glm::dvec3(0.0, 3.0, 12.0));
    CHECK(look_at.focal == 4.0);
    CHECK(look_at.sensor_height == 6.0);
    CHECK(look_at.sensor_width == 8.0);
    const phongrast::Camera& opencv = job.cameras[1];
    CHECK(opencv.model == CameraModel::opencv);
    CHECK(opencv.opencv.fx == 40.0);
    CHECK(opencv.opencv.fy == 41.25);
    CHECK(opencv.opencv.cx == 31.5);
    CHECK(opencv.opencv.cy == 23.5);
    CHECK(opencv.opencv.world_to_camera[0][3] == 0.25);
    CHECK(opencv.opencv.world_to_camera[1][1] == -1.0);
    CHECK(opencv.opencv.world_to_camera[2][3] == 10.0);
    CHECK(job.cameras[2].model == CameraModel::orthographic);
    CHECK(job.cameras[2].eye == glm::dvec3(5.0, 0.0, 0.0));
    // The scene file's own reader gives the same cameras.
    for (std::size_t i = 0; i < 3; ++i) {
        const char* text = i == 0 ? look_at_camera : i == 1 ? opencv_camera : orthographic_camera;
        const phongrast::Camera scene = phongrast::io::parse_camera_json(text, "camera.json", nullptr);
        CHECK(scene.model == job.cameras[i].model);
        CHECK(scene.eye == job.cameras[i].eye);
        CHECK(scene.opencv.world_to_camera == job.cameras[i].opencv.world_to_camera);
        CHECK(scene.opencv.fx == job.cameras[i].opencv.fx);
    }
    // One camera: one view, named as a single view is.
    CHECK(manifest.jobs[1].views == 1);
    CHECK(manifest.jobs[1].outputs == std::vector<std::string>{"a.png"});
}

TEST_CASE("cameras: camera_to_world, an inline pose of 3 rows and the command line's size are accepted") {
    const std::string camera_to_world =
        R"({"K": [[40, 0, 31.5], [0, 40, 23.5], [0, 0, 1]], "camera_to_world": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 10]]})";
    JobSettings defaults;
    defaults.size = "64x48";
    const Manifest manifest = parse("{\"mesh\": \"a.obj\", \"cameras\": [" + camera_to_world + "]}", defaults);
    REQUIRE(manifest.jobs.at(0).cameras.size() == 1);
    const phongrast::Matrix3x4& pose = manifest.jobs[0].cameras[0].opencv.world_to_camera;
    CHECK(pose[0][0] == 1.0);
    CHECK(pose[1][1] == -1.0);
    CHECK(pose[2][2] == -1.0);
    CHECK(pose[2][3] == 10.0);  // t = -R c: R = diag(1, -1, -1), c = (0, 0, 10)
}

TEST_CASE("bad cameras stop the batch with a message naming the line and the field") {
    const std::string good = look_at_camera;
    const auto opencv_with = [](const std::string& K, const std::string& pose) {
        return "[" + std::string(look_at_camera) + ", {\"K\": " + K + ", \"world_to_camera\": " + pose + "}]";
    };
    const std::string K = "[[40, 0, 31.5], [0, 40, 23.5], [0, 0, 1]]";
    const std::string pose = "[[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 10], [0, 0, 0, 1]]";
    // Shape.
    CHECK_THAT(error_of("{\"mesh\": \"a.obj\"}\n" + camera_line("{}")),
               Catch::StartsWith("m.jsonl:2: /cameras: expected a non-empty array of camera objects"));
    CHECK_THAT(error_of(camera_line("[]")), Catch::StartsWith("m.jsonl:1: /cameras: expected a non-empty array"));
    CHECK_THAT(error_of(camera_line("[" + good + ", 3]")),
               Catch::StartsWith("m.jsonl:1: /cameras/1: expected a camera object (look-at: eye, lookat"));
    CHECK_THAT(error_of(camera_line("[" + good + ", [1, 2]]")), Catch::Contains("/cameras/1: expected a camera object"));
    // K with a non-positive focal length.
    CHECK_THAT(error_of(camera_line(opencv_with("[[0, 0, 31.5], [0, 40, 23.5], [0, 0, 1]]", pose))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/K/0/0: expected fx, a positive number, got 0"));
    CHECK_THAT(error_of(camera_line(opencv_with("[[40, 0, 31.5], [0, -40, 23.5], [0, 0, 1]]", pose))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/K/1/1: expected fy, a positive number, got -40"));
    // A pose with NaN or Infinity (what Python's json.dumps writes for them), or too large a number.
    CHECK(error_of(camera_line(opencv_with(K, "[[1, 0, 0, NaN], [0, -1, 0, 0], [0, 0, -1, 10], [0, 0, 0, 1]]"))) ==
          "m.jsonl:1: /cameras/1/world_to_camera/0/3: expected a finite number, got NaN (JSON has no NaN or Infinity; "
          "check the numbers the line was made from)");
    CHECK_THAT(error_of(camera_line(opencv_with(K, "[[1, 0, 0, 0], [0, -1, 0, -Infinity], [0, 0, -1, 10], [0, 0, 0, 1]]"))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/world_to_camera/1/3: expected a finite number, got -Infinity"));
    CHECK_THAT(error_of(camera_line(opencv_with(K, "[[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 1e999], [0, 0, 0, 1]]"))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/world_to_camera/2/3: expected a finite number, got 1e999"));
    // A pose that is not a rotation (scaled, then mirrored).
    CHECK_THAT(error_of(camera_line(opencv_with(K, "[[2, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 10], [0, 0, 0, 1]]"))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/world_to_camera: the 3x3 part is not a rotation"));
    CHECK_THAT(error_of(camera_line(opencv_with(K, "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 10], [0, 0, 0, 1]]"))),
               Catch::StartsWith("m.jsonl:1: /cameras/1/world_to_camera: the 3x3 part has determinant -1"));
    CHECK_THAT(error_of(camera_line(R"([{"K": )" + K + "}]")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/world_to_camera: missing required field"));
    // Unknown fields, and fields the camera would ignore: a manifest refuses them.
    CHECK_THAT(error_of(camera_line(R"([{"eye": [0, 0, 5], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1], "fov": 40}])")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/fov: unknown field; a camera has eye, lookat"));
    CHECK_THAT(error_of(camera_line(R"([{"eye": [0, 0, 5], "K": )" + K + ", \"world_to_camera\": " + pose + "}]")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/eye: an OpenCV camera (K) is placed by its matrices"));
    CHECK_THAT(error_of(camera_line(R"([{"projection": "orthographic", "eye": [0, 0, 5], "lookat": [0, 0, 0], "focal": 2, "sensor": [1, 1]}])")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/focal: an orthographic camera has no focal length"));
    // The camera's geometry, named by its field.
    CHECK_THAT(error_of(camera_line(R"([{"eye": [0, 0, 5], "lookat": [0, 0, 5], "focal": 1, "sensor": [1, 1]}])")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/lookat: must differ from camera.eye"));
    CHECK_THAT(error_of(camera_line(R"([{"eye": [0, 5, 0], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1]}])")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/up: must not be parallel to the view direction"));
    CHECK_THAT(error_of(camera_line(R"([{"eye": [0, 0, 5], "lookat": [0, 0, 0], "focal": -1, "sensor": [1, 1]}])")),
               Catch::StartsWith("m.jsonl:1: /cameras/0/focal: expected a positive number, got -1"));
}

TEST_CASE("cameras exclude generated views, belong to mesh jobs, and an OpenCV K needs the job's size") {
    const std::string cameras = std::string("[") + look_at_camera + "]";
    for (const char* field : {"\"views\": 2", "\"layout\": \"sphere\"", "\"elevation\": 10", "\"elevations\": [10]"}) {
        INFO(field);
        CHECK_THAT(error_of(camera_line(cameras, std::string(", ") + field)),
                   Catch::Matches("m\\.jsonl:1: /(views|layout|elevation|elevations): \"cameras\" gives every view's "
                                  "camera; expected either \"cameras\" or views/layout/elevation\\(s\\), not both"));
    }
    CHECK_THAT(error_of("{\"scene\": \"s.json\", \"cameras\": " + cameras + "}"),
               Catch::StartsWith("m.jsonl:1: /cameras: only a \"mesh\" job has cameras"));
    // K is in pixels: without a size there is nothing to check it against.
    CHECK_THAT(error_of(std::string("{\"mesh\": \"a.obj\", \"cameras\": [") + opencv_camera + "]}"),
               Catch::StartsWith("m.jsonl:1: /cameras/0/K: an OpenCV camera's K is in pixels: give the image size"));
    CHECK_NOTHROW(parse(std::string("{\"mesh\": \"a.obj\", \"cameras\": [") + look_at_camera + "]}"));  // world units only
    // A principal point off the image: a K made for another size.
    const std::string big_K =
        R"([{"K": [[1000, 0, 959.5], [0, 1000, 539.5], [0, 0, 1]], "world_to_camera": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 10]]}])";
    CHECK(error_of(camera_line(big_K)) ==
          "m.jsonl:1: /cameras/0/K: the principal point (cx, cy) = (959.5, 539.5) lies outside the 64x48 image "
          "(\"size\"); K is in pixels of that image: was it made for another size?");
    CHECK_NOTHROW(parse("{\"mesh\": \"a.obj\", \"size\": \"1920x1080\", \"cameras\": " + big_K + "}"));
    // The edges of the image in OpenCV's pixel coordinates (centres at whole numbers) are on it.
    const std::string edge_K =
        R"([{"K": [[10, 0, -0.5], [0, 10, 47.5], [0, 0, 1]], "world_to_camera": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 10]]}])";
    CHECK_NOTHROW(parse(camera_line(edge_K)));
}
