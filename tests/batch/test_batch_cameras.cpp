// `phongrast batch` with a mesh job's own "cameras" (look-at, OpenCV,
// orthographic), end to end: each view is byte for byte `phongrast render`
// of the mesh with that camera given by flags, and the job's camera file and
// transforms.json hold the cameras exactly as the manifest gave them.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "batch_test_support.hpp"
#include "phongrast/io/image_file.hpp"

using namespace batch_test;
using nlohmann::json;

namespace {

/// Numbers for a command-line flag, comma separated, each read back exactly.
std::string flag_numbers(const std::vector<double>& numbers) {
    std::string text;
    for (const double number : numbers) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", number);
        text += (text.empty() ? "" : ",") + std::string(buffer);
    }
    return text;
}

/// Pixels of the PNG at `path` that differ from its top-left pixel (the background).
int object_pixels(const std::string& path) {
    const phongrast::Image image = phongrast::io::read_image(path);
    int count = 0;
    for (const glm::vec3& pixel : image.pixels) count += pixel != image.pixels.front() ? 1 : 0;
    return count;
}

}  // namespace

TEST_CASE("a job's own cameras: each view is `render` with that camera, the camera files hold them exactly") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 60, 8);
    // An OpenCV camera 12 units from the knot's centre, turned 30 degrees about y, looking at it:
    // rows of R are x right, y down (world -y), z forward; t = -R eye = (0, 0, 12).
    const double pi = std::acos(-1.0);
    const double c = std::cos(pi / 6.0), s = std::sin(pi / 6.0);
    const json K = {{41.7, 0.0, 30.25}, {0.0, 40.3, 24.75}, {0.0, 0.0, 1.0}};
    const json pose = {{c, 0.0, -s, 0.0}, {0.0, -1.0, 0.0, 0.0}, {-s, 0.0, -c, 12.0}, {0.0, 0.0, 0.0, 1.0}};
    const json opencv = {{"K", K}, {"world_to_camera", pose}};
    const json look_at = {{"eye", {0, 3, 12}}, {"lookat", {0, 0, 0}}, {"up", {0, 1, 0}}, {"focal", 8}, {"sensor", {6, 8}}};
    const json orthographic = {{"projection", "orthographic"}, {"eye", {9, 1, 0}}, {"lookat", {0, 0, 0}},
                               {"sensor", {9, 12}}};
    const json views = {{"mesh", "knot.obj"},  {"size", "64x48"},  {"cameras", {look_at, opencv}},
                        {"output", "v/{view}.png"}, {"camera_out", "v/cameras.json"}, {"transforms_out", "v/transforms.json"}};
    const json flat = {{"mesh", "knot.obj"}, {"size", "64x48"}, {"cameras", {orthographic}}, {"camera_out", "o.json"}};
    folder.write("jobs.jsonl", views.dump() + "\n" + flat.dump() + "\n");
    const Run batch = run_phongrast(folder, "batch jobs.jsonl -o out");
    INFO(batch.err);
    REQUIRE(batch.status == 0);

    // Each view equals `render` with the same camera as flags.
    std::vector<double> K_flag = {41.7, 40.3, 30.25, 24.75};
    std::vector<double> pose_flag;
    for (const json& row : pose) {
        for (const json& number : row) pose_flag.push_back(number.get<double>());
    }
    REQUIRE(run_phongrast(folder, "render knot.obj --size 64x48 --K " + flag_numbers(K_flag) + " --world-to-camera " +
                                      flag_numbers(pose_flag) + " -q -o opencv.png").status == 0);
    REQUIRE(run_phongrast(folder, "render knot.obj --size 64x48 --eye 0,3,12 --lookat 0,0,0 --up 0,1,0 --focal 8 "
                                  "--sensor 6,8 -q -o look_at.png").status == 0);
    REQUIRE(run_phongrast(folder, "render knot.obj --size 64x48 --projection orthographic --eye 9,1,0 --lookat 0,0,0 "
                                  "--sensor 9,12 -q -o orthographic.png").status == 0);
    const auto out = files_under(folder.file("out"));
    const auto alone = files_under(folder.file(""));
    CHECK(out.at("v/0.png") == alone.at("look_at.png"));
    CHECK(out.at("v/1.png") == alone.at("opencv.png"));
    CHECK(out.at("knot.png") == alone.at("orthographic.png"));  // one camera: the single view's name
    // The knot is in every picture (a blank image would match a blank one).
    for (const char* view : {"v/0.png", "v/1.png", "knot.png"}) {
        INFO(view);
        CHECK(object_pixels(folder.file("out/") + view) > 200);
    }

    // The camera file: the OpenCV camera's K and pose exactly, the look-at camera as given.
    const json cameras = json::parse(read_text(folder.file("out/v/cameras.json")));
    REQUIRE(cameras["images"].size() == 2);
    CHECK(cameras["camera"] == look_at);
    CHECK(cameras["images"][0]["file_path"] == "0.png");
    CHECK(cameras["images"][0]["look_at"] == look_at);
    CHECK(cameras["images"][0]["projection"] == "perspective");
    CHECK(cameras["images"][1]["file_path"] == "1.png");
    CHECK(cameras["images"][1]["K"] == K);
    CHECK(cameras["images"][1]["world_to_camera"] == pose);
    CHECK(cameras["images"][1]["look_at"].is_null());
    CHECK(cameras["images"][1]["width"] == 64);
    CHECK(cameras["images"][1]["height"] == 48);

    // transforms.json: the OpenCV view carries its own intrinsics (cx + 0.5) and its pose's inverse.
    const json transforms = json::parse(read_text(folder.file("out/v/transforms.json")));
    REQUIRE(transforms["frames"].size() == 2);
    const json& frame = transforms["frames"][1];
    CHECK(frame["file_path"] == "1.png");
    CHECK(frame["fl_x"] == 41.7);
    CHECK(frame["fl_y"] == 40.3);
    CHECK(frame["cx"] == 30.75);
    CHECK(frame["cy"] == 25.25);
    // The eye, -R^T t, is the camera-to-world's last column.
    const json& matrix = frame["transform_matrix"];
    CHECK(matrix[0][3].get<double>() == Approx(12.0 * s).margin(1e-12));
    CHECK(matrix[1][3].get<double>() == Approx(0.0).margin(1e-12));
    CHECK(matrix[2][3].get<double>() == Approx(12.0 * c).margin(1e-12));

    // The orthographic camera: no K, its look-at form as given (up defaults to +y).
    const json flat_cameras = json::parse(read_text(folder.file("out/o.json")));
    REQUIRE(flat_cameras["images"].size() == 1);
    CHECK(flat_cameras["images"][0]["projection"] == "orthographic");
    CHECK(flat_cameras["images"][0]["K"].is_null());
    json expected = orthographic;
    expected["up"] = {0, 1, 0};
    CHECK(flat_cameras["images"][0]["look_at"] == expected);
}

TEST_CASE("a bad camera stops the batch before anything is written, naming the line and the field") {
    TemporaryFolder folder;
    folder.write("jobs.jsonl",
                 "{\"mesh\": \"knot.obj\"}\n"
                 "{\"mesh\": \"knot.obj\", \"size\": \"64x48\", \"cameras\": [{\"K\": [[40, 0, 31.5], [0, 40, 23.5], "
                 "[0, 0, 1]], \"world_to_camera\": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]}, "
                 "{\"K\": [[40, 0, 31.5], [0, 40, 23.5], [0, 0, 1]], \"world_to_camera\": [[1, 0, 0, 0], [0, 1, 0, "
                 "NaN], [0, 0, 1, 5], [0, 0, 0, 1]]}]}\n");
    const Run run = run_phongrast(folder, "batch jobs.jsonl -o out");
    CHECK(run.status == 2);
    CHECK(run.err == "phongrast: error: jobs.jsonl:2: /cameras/1/world_to_camera/1/3: expected a finite number, got "
                     "NaN (JSON has no NaN or Infinity; check the numbers the line was made from)\n");
    CHECK_FALSE(std::filesystem::exists(folder.file("out")));
}
