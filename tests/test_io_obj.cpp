// phongrast::io::read_obj / write_obj: the contract's OBJ reading and every bad-input error.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>

#include <glm/geometric.hpp>

#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/obj_file.hpp"

using phongrast::io::FileError;
using phongrast::io::read_obj;
using Catch::Matchers::Contains;

TEST_CASE("vertex colours, a fan-triangulated quad and negative indices") {
    TemporaryFolder folder;
    const std::string path = folder.write("quad.obj",
                                          "# a coloured quad, then a triangle with relative indices\n"
                                          "v 0 0 0 1 0 0\n"
                                          "v 1 0 0 0 1 0\n"
                                          "v 1 1 0 0 0 1\n"
                                          "v 0 1 0 0.5 0.5 0.5\n"
                                          "vt 0 0\nvn 0 0 1\nvn 0 0 1\n"
                                          "f 1 2 3 4\n"
                                          "f -4/1/1 -3//2 -1\n");
    const phongrast::io::ObjFile obj = read_obj(path);
    REQUIRE(obj.mesh.positions.size() == 4);
    REQUIRE(obj.mesh.colors.size() == 4);
    CHECK(obj.mesh.colors[1] == glm::vec3(0, 1, 0));
    CHECK(obj.mesh.colors[3] == glm::vec3(0.5f));
    REQUIRE(obj.mesh.triangles.size() == 3);
    // The contract's fan: v0 v1 v2, v0 v2 v3.
    CHECK(obj.mesh.triangles[0] == phongrast::Triangle{0, 1, 2});
    CHECK(obj.mesh.triangles[1] == phongrast::Triangle{0, 2, 3});
    CHECK(obj.mesh.triangles[2] == phongrast::Triangle{0, 1, 3});
    CHECK_FALSE(obj.material);
}

TEST_CASE("vertices without a colour are white") {
    TemporaryFolder folder;
    const phongrast::io::ObjFile obj =
        read_obj(folder.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    REQUIRE(obj.mesh.colors.size() == 3);
    for (const glm::vec3& c : obj.mesh.colors) CHECK(c == glm::vec3(1.0f));
}

TEST_CASE("coordinates keep double precision (1e7 + 0.25)") {
    // tinyobjloader's packaged float build would read 10000000.25 as 10000000.
    TemporaryFolder folder;
    const phongrast::io::ObjFile obj = read_obj(
        folder.write("far.obj", "v 10000000.25 -10000000.125 3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    CHECK(obj.mesh.positions[0].x == 10000000.25);
    CHECK(obj.mesh.positions[0].y == -10000000.125);
}

TEST_CASE("MTL Ka/Kd/Ks/Ns become the PhongMaterial") {
    TemporaryFolder folder;
    folder.write("shiny.mtl", "newmtl shiny\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nNs 42\n");
    const phongrast::io::ObjFile obj = read_obj(
        folder.write("lit.obj", "mtllib shiny.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n"));
    REQUIRE(obj.material);
    CHECK(obj.material_name == "shiny");
    CHECK(obj.material->ka == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(obj.material->kd == glm::vec3(0.4f, 0.5f, 0.6f));
    CHECK(obj.material->ks == glm::vec3(0.7f, 0.8f, 0.9f));
    CHECK(obj.material->n == 42.0f);
}

TEST_CASE("bad OBJ input: the message names the file, the line and what was expected") {
    TemporaryFolder folder;
    struct Case {
        const char* name;
        const char* text;
        const char* expected;
    };
    const Case cases[] = {
        {"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "zero.obj:4: face vertex index 0"},
        {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "range.obj:4: face vertex index 4 is out of range"},
        {"negative.obj", "v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n", "negative.obj:2: face vertex index -2 is out of range"},
        {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "nan.obj:2: vertex x: expected a finite number"},
        {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", "inf.obj:3: vertex y: expected a finite number"},
        {"word.obj", "v 0 0 zero\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "word.obj:1: vertex z: expected a number"},
        {"colour.obj", "v 0 0 0 1e300 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "colour.obj:1: vertex r: expected a colour within float range"},
        {"two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "two.obj:4: face with 2 vertices; expected at least 3"},
        {"empty.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "empty.obj: no faces"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string path = folder.write(c.name, c.text);
        CHECK_THROWS_WITH(read_obj(path), Contains(c.expected));
    }
    CHECK_THROWS_WITH(read_obj(folder.file("missing.obj")), Contains("missing.obj: mesh not found"));
}

TEST_CASE("write_obj then read_obj gives the same mesh") {
    TemporaryFolder folder;
    phongrast::Mesh mesh;
    mesh.positions = {{0.1, 0.2, 0.3}, {10000000.25, 1, 0}, {0, 1, 1e-9}};
    mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 0.25f}};
    mesh.triangles = {{0, 1, 2}};
    const std::string path = folder.file("round.obj");
    phongrast::io::write_obj(mesh, path, "round trip");
    const phongrast::io::ObjFile obj = read_obj(path);
    CHECK(obj.mesh.positions == mesh.positions);
    CHECK(obj.mesh.colors == mesh.colors);
    CHECK(obj.mesh.triangles == mesh.triangles);
    CHECK(folder.entry_count() == 1);  // no temporary file left
}

TEST_CASE("coordinates are the file's decimals correctly rounded (values tinyobjloader's parser misreads)") {
    // tinyobjloader reads 0.3 as 0.30000000000000004, 0.7 as 0.70000000000000007,
    // 0.123456789 as 0.12345678900000001 and -7.612936 as -7.6129359999999986.
    TemporaryFolder folder;
    const phongrast::io::ObjFile obj = read_obj(folder.write(
        "exact.obj", "v 0.3 0.7 0.123456789\nv -7.612936 -0.975701923109 1.396942974\n"
                     "v +2.5 1e-400 0x1p3\nf 1 2 3\n"));
    CHECK(obj.mesh.positions[0] == glm::dvec3(0.3, 0.7, 0.123456789));
    CHECK(obj.mesh.positions[1] == glm::dvec3(-7.612936, -0.975701923109, 1.396942974));
    // What strtod accepts stays accepted: a leading '+', underflow to 0, hexadecimal.
    CHECK(obj.mesh.positions[2] == glm::dvec3(2.5, 0.0, 8.0));
}

TEST_CASE("polygons are fanned and negative indices count back from the line") {
    TemporaryFolder folder;
    const phongrast::io::ObjFile obj = read_obj(folder.write(
        "pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 2 0\nv 1 3 0\nv -1 2 0\n"
                        "vt 0 0\nvt 0.5 0\nvt 1 0.5\nvt 0.5 1\nvt 0 0.5\nvt 1 1\n"
                        "vn 1 0 0\nvn 0 1 0\nvn 0 0 1\nvn -1 0 0\nvn 0 -1 0\n"
                        "f -5/1/1 -4/2/2 -3/3/3 -2/4/4 -1/5/5\n"  // a pentagon, v/vt/vn, relative
                        "v 0 0 1\n\tf\t1//1 -1//1   2//1 # tabs, v//vn and a comment\r\n"
                        "f 1/1 2/2 6/6\n"));
    REQUIRE(obj.mesh.triangles.size() == 5);
    CHECK(obj.mesh.triangles[0] == phongrast::Triangle{0, 1, 2});
    CHECK(obj.mesh.triangles[1] == phongrast::Triangle{0, 2, 3});
    CHECK(obj.mesh.triangles[2] == phongrast::Triangle{0, 3, 4});
    CHECK(obj.mesh.triangles[3] == phongrast::Triangle{0, 5, 1});
    CHECK(obj.mesh.triangles[4] == phongrast::Triangle{0, 1, 5});
    // The vt and vn indices follow the same fan, corner by corner.
    constexpr std::uint32_t none = phongrast::kNoIndex;
    REQUIRE(obj.mesh.texcoord_triangles.size() == 5);
    CHECK(obj.mesh.texcoord_triangles[0] == phongrast::Triangle{0, 1, 2});
    CHECK(obj.mesh.texcoord_triangles[2] == phongrast::Triangle{0, 3, 4});
    CHECK(obj.mesh.texcoord_triangles[3] == phongrast::Triangle{none, none, none});
    CHECK(obj.mesh.texcoord_triangles[4] == phongrast::Triangle{0, 1, 5});
    REQUIRE(obj.mesh.file_normal_triangles.size() == 5);
    CHECK(obj.mesh.file_normal_triangles[1] == phongrast::Triangle{0, 2, 3});
    CHECK(obj.mesh.file_normal_triangles[3] == phongrast::Triangle{0, 0, 0});
    CHECK(obj.mesh.file_normal_triangles[4] == phongrast::Triangle{none, none, none});
    CHECK(obj.mesh.texcoords.size() == 6);
    CHECK(obj.mesh.file_normals.size() == 5);
}

namespace {

/// A strip of `quads` quads in relative indices, one `v` pair per quad: large
/// enough (several MB) to be parsed in parallel chunks.
std::string long_strip(std::size_t quads) {
    std::string text = "v 0 0 0\nv 0 1 0\n";
    char line[96];
    for (std::size_t i = 1; i <= quads; ++i) {
        std::snprintf(line, sizeof line, "v %zu.5 0 0 0.25 0.5 0.75\nv %zu.5 1 0\nf -4 -2 -1 -3\n", i, i);
        text += line;
    }
    return text;
}

}  // namespace

TEST_CASE("a file parsed in parallel chunks gives the sequential result and line numbers") {
    TemporaryFolder folder;
    const std::size_t quads = 120000;  // about 6 MB, several chunks
    const std::string strip = long_strip(quads);
    const phongrast::io::ObjFile obj = read_obj(folder.write("strip.obj", strip + "usemtl none\n"));
    REQUIRE(obj.mesh.positions.size() == 2 * quads + 2);
    REQUIRE(obj.mesh.triangles.size() == 2 * quads);
    for (std::size_t i = 0; i < quads; i += 997) {
        const auto a = static_cast<std::uint32_t>(2 * i);
        CHECK(obj.mesh.triangles[2 * i] == phongrast::Triangle{a, a + 2, a + 3});
        CHECK(obj.mesh.triangles[2 * i + 1] == phongrast::Triangle{a, a + 3, a + 1});
        CHECK(obj.mesh.positions[a + 2] == glm::dvec3(double(i) + 1.5, 0, 0));
        CHECK(obj.mesh.colors[a + 2] == glm::vec3(0.25f, 0.5f, 0.75f));
    }
    REQUIRE(obj.warnings.size() == 1);
    CHECK_THAT(obj.warnings[0], Contains("usemtl none: no such material"));

    // Line 3 x quads + 3 is after the strip; an index error early wins over a later bad number.
    const std::string late = strip + "v 1 2 x\n";
    CHECK_THROWS_WITH(read_obj(folder.write("late.obj", late)),
                      Contains("late.obj:" + std::to_string(3 * quads + 3) + ": vertex z: expected a number, got 'x'"));
    std::string early = strip;
    early.insert(early.find("f -4", early.size() / 2), "f 1 2 999999999\n");
    const std::size_t early_line =
        static_cast<std::size_t>(std::count(early.begin(), early.begin() + early.find("f 1 2 999"), '\n')) + 1;
    CHECK_THROWS_WITH(read_obj(folder.write("early.obj", early + "v 1 2 x\n")),
                      Contains("early.obj:" + std::to_string(early_line) + ": face vertex index 999999999 is out of range: "
                               "the file has " + std::to_string(2 * quads + 3) + " vertices"));
}
