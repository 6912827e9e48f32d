// phongrast::io::read_mesh: PLY, STL and glTF/GLB read to the same mesh (and
// picture) as OBJ, content-based format detection, and each format's features.
#include <catch2/catch.hpp>

#include <cstring>

#include "io_test_files.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using phongrast::Mesh;
using phongrast::io::read_mesh;
using Catch::Matchers::Contains;

namespace {

/// A coloured torus whose coordinates are floats (glTF and STL store float)
/// and whose colours have four decimals (OBJ writes four).
Mesh float_torus() {
    Mesh mesh = test_meshes::torus(24, 12, 1.0, 0.35);
    for (glm::dvec3& p : mesh.positions) {
        for (int k = 0; k < 3; ++k) p[k] = static_cast<double>(static_cast<float>(p[k]));
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        mesh.colors.emplace_back(float(i % 8) / 8.0f, float(i % 5) / 4.0f, 0.5f);
    }
    return mesh;
}

phongrast::Image picture(const Mesh& mesh) {
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = 1;
    return phongrast::render(phongrast::io::frame_mesh(mesh, 48, 64), options).image;
}

std::size_t lit_pixels(const phongrast::Image& image) {
    std::size_t count = 0;
    for (const glm::vec3& p : image.pixels) count += p != glm::vec3(1.0f) ? 1 : 0;
    return count;
}

}  // namespace

TEST_CASE("the same mesh as OBJ, PLY (ASCII, both binaries), GLB and STL gives the same mesh and picture") {
    TemporaryFolder folder;
    const Mesh mesh = float_torus();
    const phongrast::Image expected = picture(mesh);
    REQUIRE(lit_pixels(expected) > 500);  // a real picture, not an empty frame

    phongrast::io::write_obj(mesh, folder.file("t.obj"));
    phongrast::io::write_ply(mesh, folder.file("t-ascii.ply"), phongrast::io::PlyEncoding::ascii);
    phongrast::io::write_ply(mesh, folder.file("t-le.ply"), phongrast::io::PlyEncoding::binary_little_endian);
    phongrast::io::write_ply(mesh, folder.file("t-be.ply"), phongrast::io::PlyEncoding::binary_big_endian);
    phongrast::io::write_glb(mesh, folder.file("t.glb"));
    for (const char* name : {"t.obj", "t-ascii.ply", "t-le.ply", "t-be.ply", "t.glb"}) {
        INFO(name);
        const Mesh read = read_mesh(folder.file(name)).mesh;
        CHECK(read.positions == mesh.positions);
        CHECK(read.colors == mesh.colors);
        CHECK(read.triangles == mesh.triangles);
        CHECK(test_render_modes::same_bits(picture(read), expected));
    }

    // STL has no colours and repeats corners: welded, it renders the white torus.
    Mesh white = mesh;
    white.colors.clear();
    const phongrast::Image expected_white = picture(white);
    phongrast::io::write_stl(mesh, folder.file("t-binary.stl"), true);
    phongrast::io::write_stl(mesh, folder.file("t-ascii.stl"), false);
    for (const char* name : {"t-binary.stl", "t-ascii.stl"}) {
        INFO(name);
        const Mesh read = read_mesh(folder.file(name)).mesh;
        CHECK(read.positions.size() == mesh.positions.size());  // welded back to one vertex per position
        CHECK(read.triangles.size() == mesh.triangles.size());
        CHECK(test_render_modes::same_bits(picture(read), expected_white));
    }
}

TEST_CASE("the format comes from the content when the extension lies") {
    TemporaryFolder folder;
    const Mesh mesh = float_torus();
    phongrast::io::write_ply(mesh, folder.file("ply.obj"));
    phongrast::io::write_glb(mesh, folder.file("glb.stl"));
    phongrast::io::write_stl(mesh, folder.file("stl.ply"), true);
    phongrast::io::write_stl(mesh, folder.file("ascii-stl.obj"), false);
    CHECK(read_mesh(folder.file("ply.obj")).mesh.positions == mesh.positions);
    CHECK(read_mesh(folder.file("glb.stl")).mesh.positions == mesh.positions);
    CHECK(read_mesh(folder.file("stl.ply")).mesh.triangles.size() == mesh.triangles.size());
    CHECK(read_mesh(folder.file("ascii-stl.obj")).mesh.triangles.size() == mesh.triangles.size());
    CHECK_THROWS_WITH(read_mesh(folder.write("mesh.xyz", "1 2 3\n")),
                      Contains("mesh.xyz: unknown mesh format (extension '.xyz')"));
}

TEST_CASE("PLY: uchar colours, polygons fanned, unknown elements and properties read past") {
    TemporaryFolder folder;
    const std::string path = folder.write("quad.ply",
                                          "ply\r\nformat ascii 1.0\ncomment made by hand\n"
                                          "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                          "property float nx\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                                          "element face 1\nproperty list uchar int vertex_indices\nproperty uchar flags\n"
                                          "element edge 1\nproperty list uchar uint ends\nend_header\n"
                                          "0 0 0 1 255 0 0\n1 0 0 1 0 255 0\n1 1 0 1 0 0 51\n0 1 0 1 255 255 255\n"
                                          "4 0 1 2 3 7\n2 0 1\n");
    const Mesh mesh = read_mesh(path).mesh;
    REQUIRE(mesh.triangles.size() == 2);
    CHECK(mesh.triangles[0] == phongrast::Triangle{0, 1, 2});
    CHECK(mesh.triangles[1] == phongrast::Triangle{0, 2, 3});
    CHECK(mesh.colors[0] == glm::vec3(1, 0, 0));
    CHECK(mesh.colors[2] == glm::vec3(0, 0, 0.2f));
    CHECK(mesh.positions[2] == glm::dvec3(1, 1, 0));
}

TEST_CASE("STL: corners at the same position are welded, in order of first appearance") {
    TemporaryFolder folder;
    const Mesh mesh = read_mesh(folder.write("two.stl",
                                             "solid two\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n"
                                             "  vertex 1 1 0\n endloop\nendfacet\nfacet normal 0 0 1\n outer loop\n"
                                             "  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\nendsolid two\n"))
                          .mesh;
    REQUIRE(mesh.positions.size() == 4);
    CHECK(mesh.positions[3] == glm::dvec3(0, 1, 0));
    CHECK(mesh.triangles == std::vector<phongrast::Triangle>{{0, 1, 2}, {0, 2, 3}});
    CHECK(mesh.colors.empty());
}

TEST_CASE("glTF: node transforms, base colour factors, external buffers, texture warnings") {
    TemporaryFolder folder;
    // One triangle (positions, then uint16 indices), used by two nodes.
    std::string bin;
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, 2};
    bin.append(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    folder.write("tri.bin", bin);
    const std::string path = folder.write("two.gltf", R"({
      "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"translation": [10, 0, 0], "children": [1], "mesh": 0},
                {"scale": [2, 2, -2], "translation": [0, 5, 0], "mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.5, 1, 1],
                                              "baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0}], "images": [{"uri": "missing.png"}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "buffers": [{"uri": "tri.bin", "byteLength": 42}]})");
    const phongrast::io::MeshFile file = read_mesh(path);
    const Mesh& mesh = file.mesh;
    REQUIRE(mesh.positions.size() == 6);
    CHECK(mesh.positions[1] == glm::dvec3(11, 0, 0));
    CHECK(mesh.positions[4] == glm::dvec3(12, 5, 0));  // child: parent's translation after its own
    // The factor is the material's colour factor (contract version 2), vertices stay white.
    CHECK(mesh.colors[4] == glm::vec3(1.0f));
    REQUIRE(mesh.materials.size() == 1);
    CHECK(mesh.materials[0].color_factor == glm::vec3(0.25f, 0.5f, 1.0f));
    CHECK(mesh.face_materials == std::vector<std::uint32_t>{0, 0});
    CHECK(mesh.triangles[0] == phongrast::Triangle{0, 1, 2});
    CHECK(mesh.triangles[1] == phongrast::Triangle{3, 5, 4});  // the mirroring scale turns the winding back
    // The texture's file is missing, and the primitive has no TEXCOORD_0 either.
    REQUIRE(file.warnings.size() == 2);
    CHECK_THAT(file.warnings[0], Contains("missing.png: no such file"));
    CHECK_THAT(file.warnings[1], Contains("2 triangles with a textured material") && Contains("no texture coordinates"));
    // The files beside it that a cache must watch: the buffer, then the (missing) image.
    CHECK(file.side_files == std::vector<std::string>{folder.file("tri.bin"), folder.file("missing.png")});
}
