// phongrast::io::parse_scene_json: the contract's fields, defaults, and every bad-input error.
#include <catch2/catch.hpp>

#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/scene_file.hpp"

using phongrast::io::parse_scene_json;
using Catch::Matchers::Contains;

namespace {

const char* const contract_example = R"({
  "mesh": "dog.obj",
  "camera": {
    "eye": [0, 0, 15000], "lookat": [0, 0, 0], "up": [0, 1, 0],
    "focal": 70, "sensor": [15, 20]
  },
  "image": { "height": 512, "width": 640, "background": [1, 1, 1] },
  "material": { "ka": 0.1, "kd": [0.8, 0.7, 0.6], "ks": 1.0, "n": 1 },
  "ambient": [0.2, 0.2, 0.2],
  "lights": [
    { "position": [0, 10000, 0], "intensity": [1, 1, 1] },
    { "position": [1000, 1000, 0], "intensity": [1, 0, 0] }
  ],
  "shader": "gouraud",
  "lighting": "diffusion+specular"
})";

/// The contract example with one substring replaced.
std::string example_with(const std::string& from, const std::string& to) {
    std::string text = contract_example;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("the contract's example scene is read field by field") {
    const phongrast::io::SceneFile file = parse_scene_json(contract_example, "scene.json", "/data");
    const phongrast::Scene& s = file.scene;
    CHECK(file.mesh_path == "/data/dog.obj");
    CHECK(s.camera.eye == glm::dvec3(0, 0, 15000));
    CHECK(s.camera.focal == 70.0);
    CHECK(s.camera.sensor_height == 15.0);
    CHECK(s.camera.sensor_width == 20.0);
    CHECK(s.image.rows == 512);
    CHECK(s.image.columns == 640);
    REQUIRE(file.material.kd);
    CHECK(*file.material.kd == glm::vec3(0.8f, 0.7f, 0.6f));
    CHECK(*file.material.ka == glm::vec3(0.1f));
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[1].intensity == glm::vec3(1, 0, 0));
    CHECK(s.shader == phongrast::Shader::gouraud);
    CHECK(s.lighting == phongrast::Lighting{false, true, true});
    CHECK(file.warnings.empty());
}

TEST_CASE("extra fields are warnings naming them, not errors") {
    const phongrast::io::SceneFile file =
        parse_scene_json(example_with("\"shader\"", "\"colour\": 3, \"shader\""), "scene.json", "");
    REQUIRE(file.warnings.size() == 1);
    CHECK_THAT(file.warnings[0], Contains("scene.json") && Contains("/colour"));
}

TEST_CASE("material: scene fields, then the MTL, then stated defaults") {
    phongrast::io::MaterialFields fields;
    fields.kd = glm::vec3(0.5f);
    phongrast::PhongMaterial mtl;
    mtl.ks = glm::vec3(0.25f);
    mtl.n = 8;
    std::vector<std::string> defaults;
    phongrast::PhongMaterial m = phongrast::io::resolve_material(fields, mtl, &defaults);
    CHECK(m.kd == glm::vec3(0.5f));
    CHECK(m.ks == glm::vec3(0.25f));
    CHECK(m.n == 8.0f);
    CHECK(defaults.empty());
    m = phongrast::io::resolve_material(fields, std::nullopt, &defaults);
    CHECK(defaults == std::vector<std::string>{"ka", "ks", "n"});
    CHECK(m.ka == phongrast::io::default_material().ka);
}

TEST_CASE("scene_to_json writes a scene file that reads back to the same scene") {
    const phongrast::io::SceneFile file = parse_scene_json(contract_example, "a.json", "");
    phongrast::Scene scene = file.scene;
    scene.material = phongrast::io::resolve_material(file.material, std::nullopt, nullptr);
    const phongrast::io::SceneFile again =
        parse_scene_json(phongrast::io::scene_to_json(scene, "dog.obj"), "b.json", "");
    CHECK(again.warnings.empty());
    CHECK(again.mesh_path == "dog.obj");
    CHECK(again.scene.camera.eye == scene.camera.eye);
    CHECK(again.scene.image.columns == scene.image.columns);
    CHECK(*again.material.kd == scene.material.kd);
    CHECK(again.scene.lights.size() == scene.lights.size());
    CHECK(again.scene.lighting == scene.lighting);
}

TEST_CASE("bad scene input: the message names the file, the field and what was expected") {
    struct Case {
        std::string text;
        const char* expected;
    };
    const Case cases[] = {
        {"{\n  \"mesh\": \"a.obj\",\n  \"camera\": {,\n}", "scene.json:3:14: malformed JSON"},
        {example_with("\"focal\": 70, ", ""), "/camera/focal: missing required field"},
        {example_with("\"height\": 512", "\"height\": \"512\""), "/image/height: expected a number, got a string"},
        {example_with("\"height\": 512", "\"height\": -5"), "/image/height: expected a whole number of pixels"},
        {example_with("\"eye\": [0, 0, 15000]", "\"eye\": [0, 0, 0]"), "camera.lookat: must differ from camera.eye"},
        {example_with("\"up\": [0, 1, 0]", "\"up\": [0, 0, 2]"), "camera.up: must not be parallel"},
        // JSON has no NaN/Infinity; an overflowing literal is the way to write a non-finite number.
        {example_with("\"focal\": 70", "\"focal\": 1e999"), "scene.json:5:14: expected a finite number, got 1e999"},
        {example_with("[1000, 1000, 0]", "[1000, -1e999, 0]"), "scene.json:12:26: expected a finite number, got -1e999"},
        {example_with("\"gouraud\"", "\"toon\""), "/shader: shader: unknown 'toon'; expected flat, gouraud or phong"},
        {example_with("\"diffusion+specular\"", "\"glossy\""), "/lighting: lighting: unknown term 'glossy'"},
        {example_with("\"n\": 1", "\"n\": -1"), "/material/n: expected a non-negative number"},
        {example_with("\"eye\": [0, 0, 15000]", "\"eye\": [0, 15000]"), "/camera/eye: expected an array of 3 numbers"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK_THROWS_WITH(parse_scene_json(c.text, "scene.json", ""), Contains("scene.json") && Contains(c.expected));
    }
    CHECK_THROWS_AS(parse_scene_json("[]", "s.json", ""), phongrast::io::FileError);
}
