// Contract version 2 from OBJ/MTL and PLY: a material per face (the last
// `usemtl` before it), the MTL's Ka/Kd/Ks/Ns/map_Kd (relative to the MTL,
// `-clamp on`), `vt`/`vn` per corner (hard edges), PLY nx ny nz, and the
// bad input around them (errors naming file and line, warnings).
#include <catch2/catch.hpp>

#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "png_test_writer.hpp"

using Catch::Matchers::Contains;
using phongrast::kNoIndex;
using phongrast::Triangle;
using phongrast::io::read_mesh;
using phongrast::io::read_obj;

namespace {

constexpr Triangle no_corners{kNoIndex, kNoIndex, kNoIndex};

std::string all_warnings(const phongrast::io::MeshFile& file) {
    std::string text;
    for (const std::string& warning : file.warnings) text += warning + "\n";
    return text;
}

/// A 2 x 2 RGB PNG: red, green / blue, white.
std::string write_checker(const TemporaryFolder& folder, const std::string& name) {
    return folder.write(name, png_test::encode(2, 2, 8, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255}));
}

const char* const quad_positions = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("each face takes the material of the last usemtl before it, faces before any have none") {
    TemporaryFolder folder;
    folder.write("two.mtl",
                 "# two materials, each stating some fields\n"
                 "newmtl red\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nNs 42\n"
                 "newmtl dull\nKd 0.25\n");
    const auto obj = read_obj(folder.write("groups.obj", std::string("mtllib two.mtl\n") + quad_positions +
                                                             "f 1 2 3\n"          // before any usemtl
                                                             "usemtl red\nf 1 2 3 4\n"  // two triangles
                                                             "usemtl dull\nf 1 3 4\n"
                                                             "usemtl red\nf 2 3 4\n"));
    const phongrast::Mesh& mesh = obj.mesh;
    REQUIRE(mesh.triangles.size() == 5);
    REQUIRE(mesh.materials.size() == 2);  // each used material once, in order of first use
    CHECK(mesh.face_materials == std::vector<std::uint32_t>{kNoIndex, 0, 0, 1, 0});
    const phongrast::FaceMaterial& red = mesh.materials[0];
    CHECK(red.name == "red");
    CHECK(*red.coefficients.ka == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(*red.coefficients.kd == glm::vec3(0.4f, 0.5f, 0.6f));  // Kd is kd, never the colour
    CHECK(*red.coefficients.ks == glm::vec3(0.7f, 0.8f, 0.9f));
    CHECK(*red.coefficients.n == 42.0f);
    CHECK(red.color_factor == glm::vec3(1.0f));
    CHECK_FALSE(red.texture);
    // Only the fields the MTL states: the rest come from the scene or the defaults.
    const phongrast::FaceMaterial& dull = mesh.materials[1];
    CHECK(*dull.coefficients.kd == glm::vec3(0.25f));  // one number: r = g = b
    CHECK_FALSE(dull.coefficients.ka);
    CHECK_FALSE(dull.coefficients.ks);
    CHECK_FALSE(dull.coefficients.n);
    CHECK(mesh.colors == std::vector<glm::vec3>(4, glm::vec3(1.0f)));
    // The version-1 view (MeshFile::material): the first face's material.
    REQUIRE(obj.material);
    CHECK(obj.material_name == "red");
    CHECK(obj.material->kd == glm::vec3(0.4f, 0.5f, 0.6f));
    CHECK(obj.warnings.empty());
}

TEST_CASE("a missing MTL or an unknown material: a warning, and those faces have no material") {
    TemporaryFolder folder;
    folder.write("known.mtl", "newmtl known\nKd 1 0 0\n");
    const auto obj = read_obj(folder.write("partly.obj", std::string("mtllib absent.mtl known.mtl\n") + quad_positions +
                                                             "usemtl nowhere\nf 1 2 3\nusemtl known\nf 1 3 4\n"
                                                             "usemtl nowhere\nf 2 3 4\n"));
    CHECK(obj.mesh.face_materials == std::vector<std::uint32_t>{kNoIndex, 0, kNoIndex});
    const std::string warnings = all_warnings(obj);
    CHECK_THAT(warnings, Contains("partly.obj:1: MTL file") && Contains("absent.mtl not found"));
    CHECK_THAT(warnings, Contains("partly.obj:6: usemtl nowhere: no such material"));
    CHECK(obj.warnings.size() == 2);  // the unknown name warns once

    const auto lost = read_obj(folder.write("lost.obj", std::string("mtllib gone.mtl\n") + quad_positions +
                                                            "usemtl any\nf 1 2 3\n"));
    CHECK(lost.mesh.materials.empty());
    CHECK(lost.mesh.face_materials.empty());
    CHECK_FALSE(lost.material);
    CHECK(lost.warnings.size() == 2);
}

TEST_CASE("map_Kd: the texture relative to the MTL file, -clamp on, other options warned and skipped") {
    TemporaryFolder folder;
    std::filesystem::create_directories(folder.file("materials/maps"));
    write_checker(folder, "materials/maps/checker.png");
    folder.write("materials/lib.mtl",
                 "newmtl tiled\nKd 0.9 0.9 0.9\nmap_Kd -s 2 2 1 -bm 0.5 maps/checker.png\n"
                 "newmtl clamped\nmap_Kd -clamp on maps/checker.png\n"
                 "newmtl broken\nmap_Kd maps/no such file.png\n");
    const auto obj = read_obj(folder.write("textured.obj", std::string("mtllib materials/lib.mtl\n") + quad_positions +
                                                               "vt 0 0\nvt 1 0\nvt 1 1\n"
                                                               "usemtl tiled\nf 1/1 2/2 3/3\n"
                                                               "usemtl clamped\nf 1/1 3/3 4/2\n"
                                                               "usemtl broken\nf 2/1 3/2 4/3\n"));
    const phongrast::Mesh& mesh = obj.mesh;
    REQUIRE(mesh.materials.size() == 3);
    const phongrast::FaceMaterial& tiled = mesh.materials[0];
    REQUIRE(tiled.texture);
    REQUIRE(tiled.texture->image);
    CHECK(tiled.texture->wrap_s == phongrast::TextureWrap::repeat);
    CHECK(tiled.texture->wrap_t == phongrast::TextureWrap::repeat);
    CHECK(tiled.texture->image->at(0, 0) == glm::vec3(1, 0, 0));
    CHECK(tiled.texture->image->at(1, 1) == glm::vec3(1, 1, 1));
    CHECK(*tiled.coefficients.kd == glm::vec3(0.9f));
    const phongrast::FaceMaterial& clamped = mesh.materials[1];
    REQUIRE(clamped.texture);
    CHECK(clamped.texture->wrap_s == phongrast::TextureWrap::clamp_to_edge);
    CHECK(clamped.texture->wrap_t == phongrast::TextureWrap::clamp_to_edge);
    CHECK(clamped.texture->image.get() == tiled.texture->image.get());  // one image for both
    CHECK_FALSE(clamped.coefficients.kd);  // map_Kd without Kd states no kd
    // An unreadable texture keeps its map, with no image (drawn with T = 1), and a warning.
    REQUIRE(mesh.materials[2].texture);
    CHECK_FALSE(mesh.materials[2].texture->image);
    const std::string warnings = all_warnings(obj);
    CHECK_THAT(warnings, Contains("lib.mtl:3: map_Kd option '-s 2 2 1' ignored"));
    CHECK_THAT(warnings, Contains("lib.mtl:3: map_Kd option '-bm 0.5' ignored"));
    CHECK_THAT(warnings, Contains("material broken: texture") && Contains("no such file.png") &&
                             Contains("no such file") && Contains("T = 1"));
    CHECK(obj.warnings.size() == 3);
}

TEST_CASE("a textured face without texture coordinates: one warning") {
    TemporaryFolder folder;
    write_checker(folder, "checker.png");
    folder.write("t.mtl", "newmtl t\nmap_Kd checker.png\n");
    const auto obj = read_obj(folder.write("bare.obj", std::string("mtllib t.mtl\n") + quad_positions +
                                                           "vt 0 0\nusemtl t\nf 1 2 3\nf 1 3 4\nf 1/1 2/1 4/1\n"));
    REQUIRE(obj.warnings.size() == 1);
    CHECK_THAT(obj.warnings[0], Contains("bare.obj: 2 triangles with a textured material (t) have no texture coordinates"));
}

TEST_CASE("vt and vn per corner: one position carries different normals on different faces (a hard edge)") {
    TemporaryFolder folder;
    // Two faces of a cube's edge share vertices 1 and 2 but not their normals.
    const auto obj = read_obj(folder.write("edge.obj",
                                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 -1\n"
                                           "vt 0.25 0.75\nvt 1 0\nvt 0.5 0.5 0\n"
                                           "vn 0 0 1\nvn 0 -1 0\n"
                                           "f 1/1/1 2/2/1 3/3/1\n"
                                           "f 2//2 1//2 4//2\n"
                                           "f -4/-3 -2/-1 -1/-2\n"));  // relative vt, no vn
    const phongrast::Mesh& mesh = obj.mesh;
    REQUIRE(mesh.texcoords.size() == 3);
    CHECK(mesh.texcoords[0] == glm::vec2(0.25f, 0.75f));  // (s, t) = (u, v)
    CHECK(mesh.texcoords[2] == glm::vec2(0.5f, 0.5f));
    REQUIRE(mesh.file_normals.size() == 2);
    CHECK(mesh.file_normals[1] == glm::vec3(0, -1, 0));
    CHECK(mesh.texcoord_triangles == std::vector<Triangle>{{0, 1, 2}, no_corners, {0, 2, 1}});
    CHECK(mesh.file_normal_triangles == std::vector<Triangle>{{0, 0, 0}, {1, 1, 1}, no_corners});
    // Vertex 1 (index 0) has normal 0 on the first face and normal 1 on the second.
    CHECK(mesh.triangles[0][0] == 0);
    CHECK(mesh.triangles[1][1] == 0);
}

TEST_CASE("a plain OBJ has no per-corner lists, materials or file normals") {
    TemporaryFolder folder;
    const auto obj = read_obj(folder.write("plain.obj", std::string(quad_positions) + "f 1 2 3 4\n"));
    CHECK(obj.mesh.texcoords.empty());
    CHECK(obj.mesh.texcoord_triangles.empty());
    CHECK(obj.mesh.file_normals.empty());
    CHECK(obj.mesh.file_normal_triangles.empty());
    CHECK(obj.mesh.materials.empty());
    CHECK(obj.mesh.face_materials.empty());
}

TEST_CASE("a non-finite vn is kept as zero: the contract's 'take the computed normal'") {
    TemporaryFolder folder;
    const auto obj = read_obj(folder.write("nan.obj", std::string(quad_positions) + "vn nan 0 1\nvn 0 0 1e300\nf 1//1 2//2 3//1\n"));
    CHECK(obj.mesh.file_normals == std::vector<glm::vec3>{glm::vec3(0.0f), glm::vec3(0.0f)});
}

TEST_CASE("bad vt, vn and MTL input: the error names the file and the line") {
    TemporaryFolder folder;
    const std::string head = std::string(quad_positions) + "vt 0 0\nvn 0 0 1\n";  // lines 1-6
    const auto fails_with = [&](const std::string& name, const std::string& text, const std::string& message) {
        INFO(name);
        CHECK_THROWS_WITH(read_obj(folder.write(name, text)), Contains(name + message));
    };
    fails_with("vt_range.obj", head + "f 1/2 2/1 3/1\n",
               ":7: face texture coordinate index 2 is out of range: the file has 1 texture coordinates ('vt' lines)");
    fails_with("vn_range.obj", head + "f 1//1 2//1 3//5\n", ":7: face normal index 5 is out of range: the file has 1 normals");
    fails_with("vn_zero.obj", head + "f 1//1 2//0 3//1\n", ":7: face normal index 0: OBJ indices start at 1");
    fails_with("vt_zero.obj", head + "f 1/0 2/1 3/1\n", ":7: face texture coordinate index 0");
    fails_with("vt_back.obj", head + "f 1/-2 2/1 3/1\n",
               ":7: face texture coordinate index -2 is out of range: only 1 texture coordinates ('vt' lines) precede this line");
    fails_with("vt_word.obj", head + "f 1/a 2/1 3/1\n", ":7: face vertex '1/a': expected an integer texture coordinate index");
    fails_with("slashes.obj", head + "f 1/1/1/1 2 3\n", ":7: face vertex '1/1/1/1': expected v, v/vt, v//vn or v/vt/vn");
    fails_with("vt_nan.obj", head + "vt nan 0\nf 1 2 3\n", ":7: texture coordinate u: expected a finite number, got 'nan'");
    fails_with("vt_text.obj", head + "vt 0 x\nf 1 2 3\n", ":7: texture coordinate v: expected a number, got 'x'");
    fails_with("vn_short.obj", head + "vn 0 1\nf 1 2 3\n", ":7: expected 'vn x y z', got 2 numbers");
    folder.write("bad.mtl", "newmtl bad\nKd 0.5 0.5\n");
    CHECK_THROWS_WITH(read_obj(folder.write("bad_mtl.obj", std::string("mtllib bad.mtl\n") + head + "usemtl bad\nf 1 2 3\n")),
                      Contains("bad.mtl:2: Kd: expected 1 or 3 finite numbers, got '0.5 0.5'"));
    folder.write("ns.mtl", "newmtl ns\nNs -3\n");
    CHECK_THROWS_WITH(read_obj(folder.write("ns.obj", std::string("mtllib ns.mtl\n") + head + "f 1 2 3\n")),
                      Contains("ns.mtl:2: Ns: expected a non-negative finite number, got '-3'"));
}

TEST_CASE("an out-of-range vt in a late chunk of a large file: the sequential reader's line") {
    TemporaryFolder folder;
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    const std::size_t faces = 200000;  // about 5 MB: several chunks parsed in parallel
    for (std::size_t i = 0; i < faces; ++i) text += "f 1/1/1 2/1/1 3/-1/-1\n";
    text += "f 1/1/1 2/2/1 3/1/1\n";
    const auto obj = read_obj(folder.write("long.obj", text.substr(0, text.size() - 20)));
    CHECK(obj.mesh.texcoord_triangles.size() == faces);
    CHECK(obj.mesh.texcoord_triangles.back() == Triangle{0, 0, 0});
    CHECK(obj.mesh.file_normal_triangles[faces / 2] == Triangle{0, 0, 0});
    CHECK_THROWS_WITH(read_obj(folder.write("late.obj", text)),
                      Contains("late.obj:" + std::to_string(faces + 6) + ": face texture coordinate index 2 is out of range"));
}

TEST_CASE("PLY nx ny nz are the file's normals, per vertex") {
    TemporaryFolder folder;
    const auto ply = read_mesh(folder.write("normals.ply",
                                            "ply\nformat ascii 1.0\nelement vertex 4\n"
                                            "property float x\nproperty float y\nproperty float z\n"
                                            "property float nx\nproperty float ny\nproperty float nz\n"
                                            "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                                            "0 0 0 0 0 1\n1 0 0 0 0.5 0.5\n1 1 0 nan 0 1\n0 1 0 1 0 0\n"
                                            "3 0 1 2\n4 0 2 3 1\n"));
    const phongrast::Mesh& mesh = ply.mesh;
    REQUIRE(mesh.file_normals.size() == 4);
    CHECK(mesh.file_normals[1] == glm::vec3(0, 0.5f, 0.5f));  // as stored: the renderer normalises
    CHECK(mesh.file_normals[2] == glm::vec3(0.0f));           // non-finite: the computed normal
    CHECK(mesh.file_normal_triangles == mesh.triangles);
    CHECK(mesh.colors.empty());
    CHECK(mesh.positions[3] == glm::dvec3(0, 1, 0));
}
