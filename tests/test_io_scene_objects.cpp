// Scene files version 2: "objects" (a matrix or translation/rotation/scale,
// material overrides, normals), the scene's "normals", and every bad input
// with the message that names the file, the JSON pointer and what was expected.
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "phongrast/io/error.hpp"
#include "phongrast/io/scene_file.hpp"

using Catch::Matchers::Contains;
using phongrast::io::parse_scene_json;
using phongrast::io::SceneFile;

namespace {

/// A scene with the given "objects" (JSON text) and the required camera and image.
std::string scene_with_objects(const std::string& objects, const std::string& extra = "") {
    return R"({ "objects": )" + objects + R"(,
  "camera": { "eye": [0, 0, 10], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1] },
  "image": { "height": 8, "width": 8 })" + extra + "}";
}

SceneFile parsed(const std::string& objects, const std::string& extra = "") {
    return parse_scene_json(scene_with_objects(objects, extra), "scene.json", "/data");
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

void check_near(const glm::dvec3& a, const glm::dvec3& b) {
    INFO("(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")");
    CHECK(std::abs(a.x - b.x) < 1e-12);
    CHECK(std::abs(a.y - b.y) < 1e-12);
    CHECK(std::abs(a.z - b.z) < 1e-12);
}

}  // namespace

TEST_CASE("objects: each places a mesh relative to the scene file, in order") {
    const SceneFile file = parsed(R"([{ "mesh": "table.obj" }, { "mesh": "sub/cup.glb" }, { "mesh": "/abs/cup.glb" }])");
    REQUIRE(file.objects.size() == 3);
    CHECK(file.mesh_path.empty());
    CHECK(file.objects[0].mesh_path == "/data/table.obj");
    CHECK(file.objects[1].mesh_path == "/data/sub/cup.glb");
    CHECK(file.objects[2].mesh_path == "/abs/cup.glb");
    CHECK(file.objects[0].transform == glm::dmat4(1.0));  // no transform: the identity
    CHECK(file.objects[1].name == "objects[1] (sub/cup.glb)");
    CHECK_FALSE(file.objects[0].normals);
    CHECK(file.objects[0].material.empty());
    CHECK(file.warnings.empty());
}

TEST_CASE("objects: a transform is a list of rows applied to column vectors") {
    const SceneFile file = parsed(R"([{ "mesh": "a.obj", "transform": [[1, 0, 0, -0.2], [0, 2, 0, 0.75], [0, 0, 1, 3], [0, 0, 0, 1]] }])");
    const glm::dmat4& m = file.objects[0].transform;
    CHECK(m[3][0] == -0.2);  // glm is column-major: column 3 is the translation
    CHECK(m[3][1] == 0.75);
    CHECK(m[1][1] == 2.0);
    CHECK(apply(m, {1, 1, 1}) == glm::dvec3(0.8, 2.75, 4.0));
}

TEST_CASE("objects: translation, rotation and scale compose as T * R * S") {
    // 90 degrees about +y: (x, y, z) -> (z, y, -x).
    const double h = std::sqrt(0.5);
    const SceneFile file = parsed(R"([{ "mesh": "a.obj", "translation": [1, 2, 3], "rotation": [0, )" +
                                  std::to_string(h) + ", 0, " + std::to_string(h) + R"(], "scale": [2, 3, 4] }])");
    const glm::dmat4& m = file.objects[0].transform;
    // S: (1, 1, 1) -> (2, 3, 4); R: -> (4, 3, -2); T: -> (5, 5, 1).
    check_near(apply(m, {1, 1, 1}), {5, 5, 1});
    check_near(apply(m, {0, 0, 0}), {1, 2, 3});
    check_near(apply(m, {1, 0, 0}), {1, 2, 1});  // x scaled by 2, turned to -z
    // The same matrix from the library's composition, and each part alone.
    const glm::dmat4 composed = phongrast::io::compose_transform({1, 2, 3}, {0, h, 0, h}, {2, 3, 4});
    check_near(apply(composed, {0.5, -2, 7}), apply(m, {0.5, -2, 7}));

    const SceneFile parts = parsed(R"([{ "mesh": "a.obj", "translation": [1, 2, 3] },
                                       { "mesh": "a.obj", "scale": 2 },
                                       { "mesh": "a.obj", "rotation": [0, 0, 1, 0] }])");
    check_near(apply(parts.objects[0].transform, {1, 1, 1}), {2, 3, 4});
    check_near(apply(parts.objects[1].transform, {1, 1, 1}), {2, 2, 2});
    check_near(apply(parts.objects[2].transform, {1, 2, 3}), {-1, -2, 3});  // 180 degrees about z
}

TEST_CASE("objects: a negative scale is a mirror (negative determinant), not an error") {
    const SceneFile file = parsed(R"([{ "mesh": "a.obj", "scale": [-1, 1, 1] }])");
    CHECK(glm::determinant(glm::dmat3(file.objects[0].transform)) == -1.0);
}

TEST_CASE("objects: material overrides and normals, per object and for the scene") {
    const SceneFile file = parsed(R"([{ "mesh": "a.obj", "material": { "ks": 0.5, "n": 40 }, "normals": "file" },
                                      { "mesh": "a.obj", "normals": "computed" }, { "mesh": "a.obj" }])",
                                  R"(, "material": { "ka": 0.3 }, "normals": "file")");
    CHECK(file.scene.normals == phongrast::NormalSource::file);
    REQUIRE(file.objects.size() == 3);
    CHECK(*file.objects[0].material.ks == glm::vec3(0.5f));
    CHECK(*file.objects[0].material.n == 40.0f);
    CHECK_FALSE(file.objects[0].material.ka);
    CHECK(*file.objects[0].normals == phongrast::NormalSource::file);
    CHECK(*file.objects[1].normals == phongrast::NormalSource::computed);
    CHECK_FALSE(file.objects[2].normals);
    CHECK(*file.material.ka == glm::vec3(0.3f));
}

TEST_CASE("a version-1 scene reads as before: normals computed, no objects") {
    const SceneFile file = parse_scene_json(R"({ "mesh": "m.obj",
      "camera": { "eye": [0, 0, 10], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1] },
      "image": { "height": 8, "width": 8 } })", "scene.json", "");
    CHECK(file.objects.empty());
    CHECK(file.mesh_path == "m.obj");
    CHECK(file.scene.normals == phongrast::NormalSource::computed);
}

TEST_CASE("objects: unknown fields are warnings naming the object and the field (the contract)") {
    const SceneFile file = parsed(R"([{ "mesh": "a.obj" }, { "mesh": "a.obj", "colour": "red", "material": { "shine": 1 } }])");
    REQUIRE(file.warnings.size() == 2);
    CHECK_THAT(file.warnings[0], Contains("scene.json: ignoring unknown field /objects/1/colour"));
    CHECK_THAT(file.warnings[1], Contains("/objects/1/material/shine"));
}

TEST_CASE("objects: every bad input names the file, the field and what was expected") {
    struct Case {
        const char* objects;
        const char* expected;
    };
    const Case cases[] = {
        {R"([{ "mesh": "a.obj", "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "scale": 2 }])",
         "scene.json: /objects/0: both \"transform\" and translation/rotation/scale; expected one form"},
        {R"([{ "mesh": "a.obj" }, { "mesh": "a.obj", "transform": [[1,0,0,0],[0,0,0,0],[0,0,1,0],[0,0,0,1]] }])",
         "scene.json: /objects/1/transform: objects[1] (a.obj): the model matrix is singular"},
        {R"([{ "mesh": "a.obj", "transform": [[1,2,3,0],[2,4,6,0],[0,0,1,0],[0,0,0,1]] }])",
         "/objects/0/transform: objects[0] (a.obj): the model matrix is singular"},
        {R"([{ "mesh": "a.obj", "transform": [[1,0,0],[0,1,0],[0,0,1]] }])",
         "scene.json: /objects/0/transform: expected a 4x4 matrix as a list of 4 rows of 4 numbers"},
        {R"([{ "mesh": "a.obj", "transform": [[1,0,0,0],[0,1,0,0],[0,0,1],[0,0,0,1]] }])",
         "scene.json: /objects/0/transform/2: expected a 4x4 matrix"},
        {R"([{ "mesh": "a.obj", "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]] }])",
         "scene.json: /objects/0/transform/3: expected a 4x4 matrix as a list of 4 rows of 4 numbers, the last row [0, 0, 0, 1]"},
        {R"([{ "mesh": "a.obj", "transform": [[1,0,0,0],[0,1,"x",0],[0,0,1,0],[0,0,0,1]] }])",
         "scene.json: /objects/0/transform/1/2: expected a number, got a string"},
        {R"([{ "mesh": "a.obj", "transform": "identity" }])", "/objects/0/transform: expected a 4x4 matrix"},
        {R"([{ "mesh": "a.obj", "scale": [1e200, 1e200, 1e200] }])",
         "scene.json: /objects/0: objects[0] (a.obj): the model matrix's determinant is not finite"},
        {R"([{ "mesh": "a.obj", "rotation": [0, 0, 0, 2] }])",
         "scene.json: /objects/0/rotation: expected a unit quaternion [x, y, z, w] (length 1 to 1e-6), got length 2"},
        {R"([{ "mesh": "a.obj", "rotation": [0, 0, 0, 1.00001] }])", "/objects/0/rotation: expected a unit quaternion"},
        {R"([{ "mesh": "a.obj", "rotation": [0, 0, 1] }])", "/objects/0/rotation: expected a unit quaternion [x, y, z, w], got an array of 3"},
        {R"([{ "mesh": "a.obj", "scale": "big" }])", "scene.json: /objects/0/scale: expected a number or [sx, sy, sz], got a string"},
        {R"([{ "mesh": "a.obj", "scale": [1, 0, 1] }])", "/objects/0/scale: objects[0] (a.obj): a zero scale makes the model matrix singular"},
        {R"([{ "mesh": "a.obj", "translation": [1, 2] }])", "/objects/0/translation: expected an array of 3 numbers"},
        {R"([{ "mesh": "a.obj", "normals": "smooth" }])", "scene.json: /objects/0/normals: normals: unknown 'smooth'; expected computed or file"},
        {R"([{ "mesh": "a.obj", "normals": 1 }])", "/objects/0/normals: expected a string, got a number"},
        {R"([{ "mesh": "a.obj", "material": { "ks": "shiny" } }])", "/objects/0/material/ks: expected a number or an array of 3 numbers"},
        {R"([{ "mesh": "a.obj", "material": { "n": -1 } }])", "/objects/0/material/n: expected a non-negative number"},
        {R"([{ "mesh": "a.obj", "material": 3 }])", "/objects/0/material: expected an object, got a number"},
        {R"([{ "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]] }])", "scene.json: /objects/0/mesh: missing required field; expected a mesh file name"},
        {R"([{ "mesh": "" }])", "/objects/0/mesh: expected a mesh file name"},
        {R"([{ "mesh": 7 }])", "/objects/0/mesh: expected a string, got a number"},
        {R"(["a.obj"])", "scene.json: /objects/0: expected an object, got a string"},
        {R"([])", "scene.json: /objects: expected a non-empty array of objects, got an array of 0"},
        {R"({ "mesh": "a.obj" })", "scene.json: /objects: expected a non-empty array of objects, got an object"},
    };
    for (const Case& c : cases) {
        INFO(c.objects);
        CHECK_THROWS_WITH(parsed(c.objects), Contains(c.expected));
    }
    CHECK_THROWS_WITH(parsed(R"([{ "mesh": "a.obj" }])", R"(, "normals": "vertex")"),
                      Contains("scene.json: /normals: normals: unknown 'vertex'"));
    CHECK_THROWS_WITH(parse_scene_json(R"({ "mesh": "m.obj", "objects": [{ "mesh": "a.obj" }],
      "camera": { "eye": [0, 0, 10], "lookat": [0, 0, 0], "focal": 1, "sensor": [1, 1] },
      "image": { "height": 8, "width": 8 } })", "scene.json", ""),
                      Contains("scene.json: /: both \"mesh\" and \"objects\"; expected exactly one of them"));
    // JSON has no NaN; a literal too large for a double is refused where it stands.
    CHECK_THROWS_WITH(parsed(R"([{ "mesh": "a.obj", "translation": [1e999, 0, 0] }])"),
                      Contains("scene.json:1:") && Contains("expected a finite number, got 1e999"));
}
