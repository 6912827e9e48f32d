// Runs the phongrast executable and reads back what it wrote: PNG and EXR
// pixels against the library's own render of the same scene, the sheet and
// its figures, --repeat/--stats-json, and `generate`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "cli_run.hpp"
#include "io_test_files.hpp"
// Internal: the reordering thresholds this test straddles.
#include "mesh_order.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/render.hpp"
#include "shuffled_mesh.hpp"
#include "support/meshes.hpp"

using namespace phongrast;

namespace {

const std::string data_folder = PHONGRAST_CLI_DATA;

/// The library's render of a scene file, as the program should produce it in exact mode.
RenderResult render_with_library(const std::string& scene_path) {
    return render(load_scene_with_library(scene_path), RenderOptions::exact());
}

}  // namespace

TEST_CASE("the PNG of a tiny scene has the expected 8-bit pixels") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + data_folder + "/triangle.json' -o tiny.png");
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK_THAT(run.out, Catch::Matchers::Contains("1 triangles in, 1 drawn"));
    const Image png = io::read_image(folder.file("tiny.png"));
    REQUIRE(png.rows == 8);
    REQUIRE(png.columns == 8);
    // Ambient only: ka 1 x Ia 0.5 x red = (0.5, 0, 0) -> 128/255, no gamma curve.
    CHECK(png.at(4, 4) == glm::vec3(128.0f / 255.0f, 0.0f, 0.0f));
    CHECK(png.at(0, 0) == glm::vec3(0.0f, 0.0f, 1.0f));  // background
    // Every pixel is the library's render, clamped and rounded to 8 bits.
    const RenderResult expected = render_with_library(data_folder + "/triangle.json");
    int covered = 0;
    for (std::size_t i = 0; i < png.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float value = std::min(1.0f, std::max(0.0f, expected.image.pixels[i][c]));
            CHECK(png.pixels[i][c] == Approx(std::round(value * 255.0f) / 255.0f).margin(1e-6));
        }
        if (png.pixels[i].x > 0.0f) ++covered;
    }
    CHECK(covered == static_cast<int>(expected.stats.samples_shaded));
    CHECK(covered > 4);
}

TEST_CASE("EXR output is the library's linear floats exactly") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + data_folder + "/triangle.json' --lighting full -o tiny.exr");
    INFO(run.err);
    REQUIRE(run.status == 0);
    io::SceneFile file = io::read_scene_file(data_folder + "/triangle.json");
    file.scene.mesh = io::read_obj(file.mesh_path).mesh;
    file.scene.material = io::resolve_material(file.material, std::nullopt, nullptr);
    file.scene.lighting = Lighting::full();
    const RenderResult expected = render(file.scene, RenderOptions::exact());
    CHECK(io::read_image(folder.file("tiny.exr")).pixels == expected.image.pixels);
}

TEST_CASE("options mode seed and threads 1 give the library's seed render") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + data_folder + "/triangle.json' --mode seed --threads 1 -o seed.exr");
    REQUIRE(run.status == 0);
    io::SceneFile file = io::read_scene_file(data_folder + "/triangle.json");
    file.scene.mesh = io::read_obj(file.mesh_path).mesh;
    file.scene.material = io::resolve_material(file.material, std::nullopt, nullptr);
    CHECK(io::read_image(folder.file("seed.exr")).pixels == render(file.scene, RenderOptions::seed()).image.pixels);
}

TEST_CASE("options visibility and overdraw reach the library, overdraw never changes the picture") {
    TemporaryFolder folder;
    io::SceneFile file = io::read_scene_file(data_folder + "/triangle.json");
    file.scene.mesh = io::read_obj(file.mesh_path).mesh;
    file.scene.material = io::resolve_material(file.material, std::nullopt, nullptr);
    const std::vector<glm::vec3> expected = render(file.scene, RenderOptions::exact()).image.pixels;
    for (const char* overdraw : {"all", "visible", "auto"}) {
        const std::string name = std::string(overdraw) + ".exr";
        const Run run = run_cli(folder, "render '" + data_folder + "/triangle.json' --overdraw " + overdraw +
                                            " --stats-json " + overdraw + ".json -o " + name);
        INFO(run.err);
        REQUIRE(run.status == 0);
        CHECK(io::read_image(folder.file(name)).pixels == expected);
        const nlohmann::json stats = nlohmann::json::parse(read_text(folder.file(std::string(overdraw) + ".json")));
        CHECK(stats["scene"]["overdraw"] == overdraw);
        CHECK(stats["stats"]["samples_covered"].get<std::uint64_t>() >= stats["stats"]["samples_shaded"].get<std::uint64_t>());
    }
    const Run depth = run_cli(folder, "render '" + data_folder + "/triangle.json' --visibility depth-buffer -o depth.exr");
    REQUIRE(depth.status == 0);
    RenderOptions depth_buffer = RenderOptions::exact();
    depth_buffer.visibility = Visibility::depth_buffer;
    CHECK(io::read_image(folder.file("depth.exr")).pixels == render(file.scene, depth_buffer).image.pixels);
    const Run bad = run_cli(folder, "render '" + data_folder + "/triangle.json' --overdraw some -o bad.png");
    CHECK(bad.status != 0);
    CHECK_THAT(bad.err, Catch::Matchers::Contains("--overdraw"));
    CHECK_FALSE(std::ifstream(folder.file("bad.png")).good());
}

TEST_CASE("options repeat K and stats-json report K timed runs and the render statistics") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "render '" + data_folder + "/triangle.json' --repeat 3 --stats-json stats.json -o r.png");
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK_THAT(run.out, Catch::Matchers::Contains("render time over 3 runs after 1 warm-up: median"));
    const nlohmann::json stats = nlohmann::json::parse(read_text(folder.file("stats.json")));
    REQUIRE(stats["render_seconds"]["runs"].size() == 3);
    CHECK(stats["render_seconds"]["warm_up"] == true);
    const double median = stats["render_seconds"]["median"];
    CHECK(median >= stats["render_seconds"]["min"].get<double>());
    CHECK(median <= stats["render_seconds"]["max"].get<double>());
    CHECK(stats["stats"]["triangles_in"] == 1);
    CHECK(stats["stats"]["triangles_drawn"] == 1);
    CHECK(stats["scene"]["width"] == 8);
    CHECK(stats["load_seconds"].get<double>() >= 0.0);
    CHECK(stats["load_seconds"].get<double>() < 60.0);
    // The warm-up is the Renderer's first frame: timed, and reported apart from the runs.
    REQUIRE(stats["render_seconds"].contains("first"));
    CHECK(stats["render_seconds"]["first"].get<double>() > 0.0);
    CHECK(stats["render_seconds"]["first"].get<double>() < 60.0);

    // Without --repeat the one run is the first frame: no warm-up to report.
    const Run once = run_cli(folder, "render '" + data_folder + "/triangle.json' --stats-json once.json -o once.png");
    REQUIRE(once.status == 0);
    const nlohmann::json once_stats = nlohmann::json::parse(read_text(folder.file("once.json")));
    CHECK(once_stats["render_seconds"]["warm_up"] == false);
    CHECK_FALSE(once_stats["render_seconds"].contains("first"));
    CHECK(once_stats["render_seconds"]["runs"].size() == 1);
}

TEST_CASE("one frame (render()) and repeated frames (a Renderer, which reorders this mesh) write the same floats") {
    // 128,000 triangles in a shuffled order: a Renderer renders a reordered copy
    // (from 16,384 triangles), the single frame the file's order (render(): from 2^18).
    Mesh sphere = support::icosphere(80, 0.05);
    std::mt19937 random(7);
    test_meshes_order::shuffle_faces_and_vertices(sphere, random);
    REQUIRE(detail::local_order_misses(sphere) > detail::kReorderMinMissesPerTriangle);
    REQUIRE(sphere.triangles.size() >= detail::reorder_min_triangles(false));
    REQUIRE(sphere.triangles.size() < detail::reorder_min_triangles(true));
    TemporaryFolder folder;
    io::write_obj(sphere, folder.file("sphere.obj"));
    for (const char* shader : {"gouraud", "phong"}) {
        INFO(shader);
        const std::string mesh = "render '" + folder.file("sphere.obj") + "' --size 96x64 --shader " + shader;
        const Run once = run_cli(folder, mesh + " -o once.exr");
        const Run repeated = run_cli(folder, mesh + " --repeat 1 -o repeated.exr");
        INFO(once.err << repeated.err);
        REQUIRE(once.status == 0);
        REQUIRE(repeated.status == 0);
        const Image image = io::read_image(folder.file("once.exr"));
        CHECK(std::count(image.pixels.begin(), image.pixels.end(), image.pixels[0]) < 96 * 64 - 1000);  // the sphere shows
        CHECK(image.pixels == io::read_image(folder.file("repeated.exr")).pixels);
    }
}

TEST_CASE("a scene naming a PLY mesh, and a GLB given alone, render as their OBJ twin does") {
    TemporaryFolder folder;
    const Run obj = run_cli(folder, "render '" + data_folder + "/triangle.json' -o obj.png");
    const Run ply = run_cli(folder, "render '" + data_folder + "/triangle_ply.json' -o ply.png");
    REQUIRE(obj.status == 0);
    REQUIRE(ply.status == 0);
    CHECK(io::read_image(folder.file("ply.png")).pixels == io::read_image(folder.file("obj.png")).pixels);
    const Run obj_alone = run_cli(folder, "render '" + data_folder + "/triangle.obj' --size 32x24 -o obj_alone.png");
    const Run glb_alone = run_cli(folder, "render '" + data_folder + "/triangle.glb' --size 32x24 -o glb_alone.png");
    REQUIRE(obj_alone.status == 0);
    REQUIRE(glb_alone.status == 0);
    const Image framed = io::read_image(folder.file("glb_alone.png"));
    CHECK(framed.pixels == io::read_image(folder.file("obj_alone.png")).pixels);
    CHECK(std::count(framed.pixels.begin(), framed.pixels.end(), glm::vec3(1.0f)) < 32 * 24);  // the triangle shows
}

TEST_CASE("without -o, a default output name that is already a file is replaced with a warning, not silently") {
    TemporaryFolder folder;
    // Two inputs with one name (triangle.obj, triangle.glb) both default to triangle.png.
    const Run first = run_cli(folder, "render '" + data_folder + "/triangle.obj' --size 16x16");
    REQUIRE(first.status == 0);
    CHECK(first.err.find("replacing") == std::string::npos);
    const Run second = run_cli(folder, "render '" + data_folder + "/triangle.glb' --size 16x16");
    REQUIRE(second.status == 0);
    CHECK(second.err.find("replacing triangle.png, the default output name for this input") != std::string::npos);
    // An explicit -o is the user's choice: no warning.
    const Run named = run_cli(folder, "render '" + data_folder + "/triangle.glb' --size 16x16 -o triangle.png");
    REQUIRE(named.status == 0);
    CHECK(named.err.find("replacing") == std::string::npos);
}

TEST_CASE("sheet writes the 4x2 grid and, with --figures, the eight figures") {
    TemporaryFolder folder;
    std::filesystem::create_directories(folder.file("figures"));
    const Run run = run_cli(folder, "sheet '" + data_folder + "/triangle.json' --size 64x48 --figures figures -o sheet.png");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const Image sheet = io::read_image(folder.file("sheet.png"));
    CHECK(sheet.columns > 4 * 64);
    CHECK(sheet.rows > 2 * 48);
    for (const char* shader : {"gouraud", "phong"}) {
        for (const char* lighting : {"ambient", "diffuse", "specular", "full"}) {
            const std::string path = folder.file(std::string("figures/") + shader + "-" + lighting + ".png");
            INFO(path);
            REQUIRE(std::filesystem::exists(path));
            CHECK(io::read_image(path).columns == 64);
        }
    }
    // The ambient and diffuse figures differ (the sheet really changes the lighting).
    CHECK(io::read_image(folder.file("figures/phong-ambient.png")).pixels !=
          io::read_image(folder.file("figures/phong-diffuse.png")).pixels);
}

TEST_CASE("generate writes a closed, outward-facing, coloured mesh, the one in assets/default.obj") {
    TemporaryFolder folder;
    const Run run = run_cli(folder, "generate -o knot.obj");
    REQUIRE(run.status == 0);
    const io::ObjFile obj = io::read_obj(folder.file("knot.obj"));
    CHECK(obj.mesh.triangles.size() == 2u * 240u * 20u);
    CHECK(obj.mesh.colors.size() == obj.mesh.positions.size());
    double signed_volume = 0.0;
    for (const Triangle& t : obj.mesh.triangles) {
        const glm::dvec3 &a = obj.mesh.positions[t[0]], &b = obj.mesh.positions[t[1]], &c = obj.mesh.positions[t[2]];
        signed_volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    CHECK(signed_volume > 1.0);  // counter-clockwise seen from outside
    CHECK(read_text(folder.file("knot.obj")) == read_text(data_folder + "/../../../assets/default.obj"));
}

TEST_CASE("render with smooth normals by position and a 30-degree crease draws a shared-vertex cube exactly like a cube with separate faces") {
    TemporaryFolder folder;
    std::string corners;
    for (int i = 0; i < 8; ++i) corners += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
                                           std::to_string((i >> 2) & 1) + "\n";
    const int quads[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
    std::string shared = corners;
    std::string faceted = corners;  // every face its own copies of its corners
    for (int f = 0; f < 6; ++f) {
        shared += "f " + std::to_string(quads[f][0]) + " " + std::to_string(quads[f][1]) + " " +
                  std::to_string(quads[f][2]) + " " + std::to_string(quads[f][3]) + "\n";
        for (int k = 0; k < 4; ++k) {
            const int corner = quads[f][k] - 1;
            faceted += "v " + std::to_string(corner & 1) + " " + std::to_string((corner >> 1) & 1) + " " +
                       std::to_string((corner >> 2) & 1) + "\n";
        }
        const int base = 9 + 4 * f;
        faceted += "f " + std::to_string(base) + " " + std::to_string(base + 1) + " " + std::to_string(base + 2) +
                   " " + std::to_string(base + 3) + "\n";
    }
    folder.write("cube.obj", shared);
    folder.write("faceted.obj", faceted);
    const std::string common = " --shader gouraud --size 48x48 --eye 2.5,1.8,3.1 --quiet";
    REQUIRE(run_cli(folder, "render cube.obj -o creased.exr --smooth position --crease 30" + common).status == 0);
    REQUIRE(run_cli(folder, "render faceted.obj -o faceted.exr" + common).status == 0);
    REQUIRE(run_cli(folder, "render cube.obj -o contract.exr" + common).status == 0);
    const Image creased = io::read_image(folder.file("creased.exr"));
    CHECK(creased.pixels == io::read_image(folder.file("faceted.exr")).pixels);
    CHECK(creased.pixels != io::read_image(folder.file("contract.exr")).pixels);
}
