// The batch manifest: the three kinds of job, settings, output names, and every
// bad line stopping the batch with a message naming the line and the field.
#include <catch2/catch.hpp>

#include "batch_manifest.hpp"
#include "phongrast/io/error.hpp"
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
