// Bad PLY, STL and glTF input: every message names the file, the place (line,
// element, byte offset or accessor) and what was expected.
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>

#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/mesh_file.hpp"

using phongrast::io::read_mesh;
using Catch::Matchers::Contains;

namespace {

struct Case {
    const char* name;
    std::string bytes;
    const char* expected;
};

void check_cases(const std::vector<Case>& cases) {
    TemporaryFolder folder;
    for (const Case& c : cases) {
        INFO(c.name);
        CHECK_THROWS_WITH(read_mesh(folder.write(c.name, c.bytes)), Contains(c.expected));
    }
}

const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
const std::string ply_faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

std::string binary_ply(std::uint32_t vertices, const std::string& body) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\n" + ply_faces + body;
}

template <class T>
std::string bytes_of(std::initializer_list<T> values) {
    std::string out;
    for (const T v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);
    return out;
}

std::string binary_stl(std::uint32_t declared, const std::vector<float>& corners) {
    std::string out(80, ' ');
    out += bytes_of<std::uint32_t>({declared});
    for (std::size_t t = 0; t * 9 < corners.size(); ++t) {
        out += bytes_of<float>({0, 0, 1});
        for (std::size_t k = 0; k < 9; ++k) out += bytes_of<float>({corners[9 * t + k]});
        out += bytes_of<std::uint16_t>({0});
    }
    return out;
}

/// A GLB holding `json` and one triangle's positions (36 bytes) and uint32 indices (12 bytes).
std::string glb(std::string json, const std::vector<float>& positions, const std::vector<std::uint32_t>& indices) {
    std::string bin;
    for (float p : positions) bin += bytes_of<float>({p});
    for (std::uint32_t i : indices) bin += bytes_of<std::uint32_t>({i});
    json.append((4 - json.size() % 4) % 4, ' ');
    std::string out = "glTF" + bytes_of<std::uint32_t>({2, std::uint32_t(28 + json.size() + bin.size())});
    out += bytes_of<std::uint32_t>({std::uint32_t(json.size()), 0x4E4F534A}) + json;
    return out + bytes_of<std::uint32_t>({std::uint32_t(bin.size()), 0x004E4942}) + bin;
}

std::string gltf_json(const std::string& position_type, const std::string& extra = "") {
    const std::string nodes = extra.find("\"nodes\"") == std::string::npos ? R"("nodes": [{"mesh": 0}], )" : "";
    return R"({"asset": {"version": "2.0"}, )" + nodes + extra +
           R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": ")" + position_type + R"("},
                    {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
      "buffers": [{"byteLength": 48}]})";
}

const std::vector<float> triangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

}  // namespace

TEST_CASE("bad PLY input") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    check_cases({
        {"type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty flt x\n",
         "type.ply:4: unknown property type 'flt'; expected char, uchar"},
        {"format.ply", "ply\nformat binary 1.0\n", "format.ply:2: unknown format 'binary'"},
        {"header.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "header.ply:3: the file ends inside the header"},
        {"word.ply", ply_head + ply_faces + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
         "word.ply: vertex 1 (line 11): expected a number, got 'zero'"},
        {"nan.ply", ply_head + ply_faces + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", "nan.ply: vertex 1 (line 11): z is not a finite number"},
        {"range.ply", ply_head + ply_faces + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
         "range.ply: face 0 (line 13): vertex index 7 is out of range: the file has 3 vertices"},
        {"float-index.ply", ply_head + "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1e30\n",
         "float-index.ply: face 0 (line 13): vertex index 1e+30 is out of range"},
        {"short.ply", ply_head + ply_faces + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "short.ply: face 0 (line 13): 2 vertices; expected at least 3"},
        {"ends.ply", ply_head + ply_faces + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "ends.ply: face 0 (line 14): the file ends; expected a number"},
        {"count.ply", binary_ply(1000000, bytes_of<float>({0, 0, 0})),
         "count.ply: element 'vertex' (byte 175): the header declares 1000000 elements of at least 12 bytes, but only 12 bytes remain"},
        {"truncated.ply", binary_ply(3, bytes_of<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}) + "\3" + bytes_of<std::int32_t>({0, 1})),
         "truncated.ply: face 0 (byte 214): the file ends at byte 214; expected 4 more bytes"},
        {"binary-nan.ply", binary_ply(3, bytes_of<float>({0, 0, 0, nan, 0, 0, 0, 1, 0}) + "\3" + bytes_of<std::int32_t>({0, 1, 2})),
         "binary-nan.ply: vertex 1 (byte 181): x is not a finite number"},
        {"noface.ply", ply_head + "end_header\n0 0 0\n1 0 0\n0 1 0\n", "noface.ply: no faces"},
    });
}

TEST_CASE("bad STL input") {
    const float inf = std::numeric_limits<float>::infinity();
    check_cases({
        {"truncated.stl", binary_stl(10, triangle), "truncated.stl: byte 80: the binary STL declares 10 triangles (584 bytes), but the file has 134 bytes"},
        {"short.stl", std::string(40, ' '), "short.stl: 40 bytes; a binary STL needs at least 84"},
        {"inf.stl", binary_stl(1, {0, 0, 0, 1, inf, 0, 0, 1, 0}), "inf.stl: triangle 0 (byte 112): coordinate is not a finite number"},
        {"word.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 q 0\n", "word.stl:5: vertex y: expected a number, got 'q'"},
        {"nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\n", "nan.stl:5: vertex y: expected a finite number"},
        {"two.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n", "two.stl:6: a facet with 2 vertices; expected 3"},
        {"open.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "open.stl:5: the file ends inside a facet"},
        {"empty.stl", "solid x\nendsolid x\n", "empty.stl: no triangles"},
    });
}

/// 20 nodes, each the parent of the next twice: 2^20 instances of the mesh.
std::string doubling_nodes() {
    std::string nodes = R"("nodes": [)";
    for (int i = 0; i < 20; ++i) {
        nodes += R"({"mesh": 0, "children": [)" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
    }
    return nodes + R"({"mesh": 0}], "scenes": [{"nodes": [0]}], )";
}

TEST_CASE("bad glTF input") {
    std::string truncated = glb(gltf_json("VEC3"), triangle, {0, 1, 2});
    truncated.resize(truncated.size() - 10);
    check_cases({
        {"truncated.glb", truncated, "truncated.glb: byte 8: the header declares"},
        {"range.glb", glb(gltf_json("VEC3"), triangle, {0, 1, 9}),
         "range.glb: /accessors/1: index 2 is 9, out of range: POSITION has 3 elements"},
        {"nan.glb", glb(gltf_json("VEC3"), {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0}, {0, 1, 2}),
         "nan.glb: /accessors/0: element 2 is not finite"},
        {"type.glb", glb(gltf_json("VEC2"), triangle, {0, 1, 2}), "type.glb: /accessors/0: type VEC2 of 5126; expected VEC3 of 5126"},
        // Found by fuzz_gltf: no "type" gave zero-byte elements and a division by zero.
        {"no-type.glb", glb(gltf_json(""), triangle, {0, 1, 2}), "no-type.glb: /accessors/0: type  of 5126; expected VEC3 of 5126"},
        {"extension.glb", glb(gltf_json("VEC3", R"("extensionsRequired": ["KHR_draco_mesh_compression"], )"), triangle, {0, 1, 2}),
         "extension.glb: /extensionsRequired: requires \"KHR_draco_mesh_compression\""},
        {"count.glb", glb(gltf_json("VEC3"), triangle, {0, 1}),  // the index view promises 12 bytes, 8 present
         "count.glb: /buffers/0/byteLength: 48 bytes declared, only 44 present"},
        {"doubling.glb", glb(gltf_json("VEC3", doubling_nodes()), triangle, {0, 1, 2}),
         "more than 100000 node instances in the scene"},
        {"json.gltf", R"({"asset": {"version": "2.0"}, "nodes": [)", "json.gltf: malformed glTF JSON at byte"},
        {"version.gltf", R"({"asset": {"version": "1.0"}})", "version.gltf: /asset/version: '1.0'; expected 2.0"},
        {"node.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [3]}]})", "node.gltf: /nodes/3: no such node"},
        {"mesh.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": "zero"}]})", "mesh.gltf: /nodes/0/mesh: expected a non-negative integer"},
    });
}
