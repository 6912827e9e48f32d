// Contract version 2 from glTF: each primitive's material (baseColorFactor as
// the colour factor, baseColorTexture with its sampler's wraps and texCoord
// set), TEXCOORD_n as (u, 1 - v), NORMAL through the node matrices' inverse
// transpose (a mirror keeps corners and normals together), images from a
// buffer view, a data: URI or a file, and the contract's triangle order.
#include <catch2/catch.hpp>

#include <cstring>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "png_test_writer.hpp"

using Catch::Matchers::Contains;
using nlohmann::json;
using phongrast::kNoIndex;
using phongrast::Triangle;
using phongrast::io::read_mesh;

namespace {

constexpr Triangle no_corners{kNoIndex, kNoIndex, kNoIndex};

/// The binary buffer of a test glTF file, with its buffer views and accessors.
struct GltfBuilder {
    std::string bin;
    json views = json::array();
    json accessors = json::array();

    int view(const std::string& bytes) {
        while (bin.size() % 4 != 0) bin.push_back('\0');
        views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}});
        bin += bytes;
        return static_cast<int>(views.size()) - 1;
    }
    template <class T>
    int accessor(const std::vector<T>& values, int component_type, const char* type, std::size_t count) {
        std::string bytes(values.size() * sizeof(T), '\0');
        std::memcpy(bytes.data(), values.data(), bytes.size());
        accessors.push_back({{"bufferView", view(bytes)}, {"componentType", component_type}, {"type", type}, {"count", count}});
        return static_cast<int>(accessors.size()) - 1;
    }
    int floats(const std::vector<float>& values, const char* type, int components) {
        return accessor(values, 5126, type, values.size() / static_cast<std::size_t>(components));
    }
    int indices(const std::vector<std::uint16_t>& values) { return accessor(values, 5123, "SCALAR", values.size()); }

    std::string glb(json document) const {
        document["asset"] = {{"version", "2.0"}};
        document["buffers"] = json::array({{{"byteLength", bin.size()}}});
        document["bufferViews"] = views;
        document["accessors"] = accessors;
        std::string text = document.dump();
        while (text.size() % 4 != 0) text.push_back(' ');
        std::string padded = bin;
        while (padded.size() % 4 != 0) padded.push_back('\0');
        std::string out = "glTF";
        const auto u32 = [&out](std::size_t value) {
            const auto v = static_cast<std::uint32_t>(value);
            out.append(reinterpret_cast<const char*>(&v), 4);
        };
        u32(2);
        u32(12 + 8 + text.size() + 8 + padded.size());
        u32(text.size());
        out += "JSON";
        out += text;
        u32(padded.size());
        out += std::string("BIN\0", 4);
        out += padded;
        return out;
    }
};

std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t bits = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
        if (i + 1 < bytes.size()) bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) bits |= static_cast<unsigned char>(bytes[i + 2]);
        out.push_back(alphabet[(bits >> 18) & 63]);
        out.push_back(alphabet[(bits >> 12) & 63]);
        out.push_back(i + 1 < bytes.size() ? alphabet[(bits >> 6) & 63] : '=');
        out.push_back(i + 2 < bytes.size() ? alphabet[bits & 63] : '=');
    }
    return out;
}

/// A 1 x 2 RGB PNG of the two colours (0-255).
std::string two_texels(std::uint16_t r0, std::uint16_t g0, std::uint16_t b0, std::uint16_t r1, std::uint16_t g1, std::uint16_t b1) {
    return png_test::encode(1, 2, 8, 2, {r0, g0, b0, r1, g1, b1});
}

/// A unit quad (two triangles 0 1 2, 0 2 3) with NORMAL, TEXCOORD_0 and TEXCOORD_1.
json quad_attributes(GltfBuilder& builder, bool with_normals) {
    json attributes = {
        {"POSITION", builder.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3)},
        {"TEXCOORD_0", builder.floats({0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}, "VEC2", 2)},
        {"TEXCOORD_1", builder.floats({0, 0.25f, 1, 0.25f, 1, 1, 0, 1}, "VEC2", 2)}};
    if (with_normals) attributes["NORMAL"] = builder.floats({0, 0, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC3", 3);
    return attributes;
}

}  // namespace

TEST_CASE("glTF: materials per primitive, texCoord set with v flipped, samplers, NORMAL, node order and mirrors") {
    TemporaryFolder folder;
    GltfBuilder builder;
    const int indices = builder.indices({0, 1, 2, 0, 2, 3});
    const json textured = {{"attributes", quad_attributes(builder, false)}, {"indices", indices}, {"material", 0}};
    const json tinted = {{"attributes", quad_attributes(builder, true)}, {"indices", indices}, {"material", 1}};
    const json plain = {{"attributes", {{"POSITION", textured["attributes"]["POSITION"]}}}, {"indices", indices}};
    const int image_view = builder.view(two_texels(255, 0, 0, 0, 0, 255));
    json document = {
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 3}}}}},
        // Depth first: node 0, its children 1 then 2, then node 3.
        {"nodes", {{{"mesh", 0}, {"children", {1, 2}}}, {{"mesh", 1}, {"scale", {-1, 2, 1}}}, {{"mesh", 2}}, {{"mesh", 2}}}},
        {"meshes", {{{"primitives", {textured, tinted}}}, {{"primitives", {tinted}}}, {{"primitives", {plain}}}}},
        {"materials",
         {{{"name", "painted"},
           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}},
          {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 0.5}}}}}}},
        {"textures", {{{"source", 0}, {"sampler", 0}}}},
        {"samplers", {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}}}},
        {"images", {{{"bufferView", image_view}, {"mimeType", "image/png"}}}}};
    const std::string path = folder.write("scene.glb", builder.glb(document));
    const phongrast::io::MeshFile file = read_mesh(path);
    const phongrast::Mesh& mesh = file.mesh;
    for (const std::string& warning : file.warnings) UNSCOPED_INFO(warning);
    CHECK(file.warnings.empty());

    // Node 0: textured (2), tinted (2); node 1: tinted mirrored (2); node 2: plain (2); node 3: plain (2).
    REQUIRE(mesh.triangles.size() == 10);
    REQUIRE(mesh.materials.size() == 2);
    CHECK(mesh.face_materials ==
          std::vector<std::uint32_t>{0, 0, 1, 1, 1, 1, kNoIndex, kNoIndex, kNoIndex, kNoIndex});
    const phongrast::FaceMaterial& painted = mesh.materials[0];
    CHECK(painted.name == "painted");
    CHECK(painted.coefficients.empty());  // glTF gives no coefficients
    CHECK(painted.color_factor == glm::vec3(1.0f));
    REQUIRE(painted.texture);
    CHECK(painted.texture->wrap_s == phongrast::TextureWrap::clamp_to_edge);
    CHECK(painted.texture->wrap_t == phongrast::TextureWrap::mirrored_repeat);
    REQUIRE(painted.texture->image);
    CHECK(painted.texture->image->at(0, 0) == glm::vec3(1, 0, 0));
    CHECK(painted.texture->image->at(0, 1) == glm::vec3(0, 0, 1));
    const phongrast::FaceMaterial& tint = mesh.materials[1];
    CHECK(tint.name == "/materials/1");
    CHECK(tint.color_factor == glm::vec3(0.5f, 0.25f, 1.0f));
    CHECK_FALSE(tint.texture);
    // Without COLOR_0 vertices are white: the factor is the material's, not baked into colours.
    for (const glm::vec3& c : mesh.colors) CHECK(c == glm::vec3(1.0f));

    // The texture reads TEXCOORD_1, (u, v) -> (u, 1 - v).
    const Triangle first = mesh.texcoord_triangles[0];
    CHECK(mesh.texcoords[first[0]] == glm::vec2(0.0f, 0.75f));
    CHECK(mesh.texcoords[first[1]] == glm::vec2(1.0f, 0.75f));
    CHECK(mesh.texcoords[first[2]] == glm::vec2(1.0f, 0.0f));
    // Untextured primitives carry TEXCOORD_0 (for the uv output); plain ones none.
    CHECK(mesh.texcoords[mesh.texcoord_triangles[2][0]] == glm::vec2(0.5f, 0.5f));
    CHECK(mesh.texcoord_triangles[6] == no_corners);

    // NORMAL: none on the textured primitive; the tinted one's as given at node 0.
    REQUIRE(mesh.file_normal_triangles.size() == 10);
    CHECK(mesh.file_normal_triangles[0] == no_corners);
    CHECK(mesh.file_normal_triangles[9] == no_corners);
    const Triangle tinted_normals = mesh.file_normal_triangles[2];
    CHECK(mesh.file_normals[tinted_normals[0]] == glm::vec3(0, 0, 1));
    CHECK(glm::length(mesh.file_normals[tinted_normals[1]] - glm::vec3(glm::normalize(glm::dvec3(1, 1, 0)))) < 1e-6f);

    // Node 1 mirrors (scale -1, 2, 1): corners 1 and 2 trade places, and each
    // corner keeps its own normal and texture coordinate; normals go through
    // the inverse transpose, diag(-1, 0.5, 1), and stay outward.
    const Triangle mirrored = mesh.triangles[4];
    const Triangle unmirrored = mesh.triangles[2];
    CHECK(mirrored[0] - 4 == unmirrored[0]);  // node 1's vertices follow node 0's two primitives (4 + 4)
    CHECK(mirrored[1] - 4 == unmirrored[2]);
    CHECK(mirrored[2] - 4 == unmirrored[1]);
    CHECK(mesh.positions[mirrored[1]] == glm::dvec3(-1, 2, 0));  // quad corner 2 at (1, 1, 0), transformed
    const Triangle mirrored_normals = mesh.file_normal_triangles[4];
    CHECK(mesh.file_normals[mirrored_normals[0]] == glm::vec3(0, 0, 1));
    const glm::vec3 expected = glm::vec3(glm::normalize(glm::dvec3(-1, 0.5, 0)));  // corner 1's (1, 1, 0)
    CHECK(glm::length(mesh.file_normals[mirrored_normals[2]] - expected) < 1e-6f);
    const Triangle mirrored_uv = mesh.texcoord_triangles[4];
    CHECK(mirrored_uv[1] - mirrored_uv[0] == 2);  // corner 2 of the quad in the slot of corner 1
    CHECK(mirrored_uv[2] - mirrored_uv[0] == 1);

    // The embedded image is shared by every load of the same file.
    const phongrast::io::MeshFile again = read_mesh(path);
    CHECK(again.mesh.materials[0].texture->image.get() == painted.texture->image.get());
}

TEST_CASE("glTF images from a file beside it (URI-encoded) and from a data: URI, a missing one warns") {
    TemporaryFolder folder;
    folder.write("tex file.png", two_texels(10, 20, 30, 40, 50, 60));
    GltfBuilder builder;
    const int indices = builder.indices({0, 1, 2, 0, 2, 3});
    const json attributes = quad_attributes(builder, false);
    json primitives = json::array();
    for (int m = 0; m < 3; ++m) primitives.push_back({{"attributes", attributes}, {"indices", indices}, {"material", m}});
    json document = {
        {"meshes", {{{"primitives", primitives}}}},
        {"materials",
         {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
          {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}},
          {{"name", "lost"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}}}},
        {"textures", {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}}},
        {"images",
         {{{"uri", "tex%20file.png"}},
          {{"uri", "data:image/png;base64," + base64(two_texels(255, 255, 255, 0, 0, 0))}},
          {{"uri", "missing.png"}}}},
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"byteLength", builder.bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(builder.bin)}}}},
        {"bufferViews", builder.views},
        {"accessors", builder.accessors}};
    const phongrast::io::MeshFile file = read_mesh(folder.write("images.gltf", document.dump()));
    const phongrast::Mesh& mesh = file.mesh;
    REQUIRE(mesh.materials.size() == 3);
    REQUIRE(mesh.materials[0].texture->image);
    CHECK(mesh.materials[0].texture->image->at(0, 1) == glm::vec3(40, 50, 60) / 255.0f);
    CHECK(mesh.materials[0].texture->wrap_s == phongrast::TextureWrap::repeat);  // no sampler: repeat
    REQUIRE(mesh.materials[1].texture->image);
    CHECK(mesh.materials[1].texture->image->at(0, 0) == glm::vec3(1.0f));
    REQUIRE(mesh.materials[2].texture);
    CHECK_FALSE(mesh.materials[2].texture->image);
    // With no texCoord the textures read TEXCOORD_0.
    CHECK(mesh.texcoords[mesh.texcoord_triangles[0][0]] == glm::vec2(0.5f, 0.5f));
    REQUIRE(file.warnings.size() == 1);
    CHECK_THAT(file.warnings[0], Contains("images.gltf: material lost: texture /textures/2 cannot be read") &&
                                     Contains("missing.png: no such file") && Contains("T = 1"));
    // The image files beside it (data: URIs are inside the file): what a cache of this mesh watches.
    CHECK(file.side_files == std::vector<std::string>{folder.file("tex file.png"), folder.file("missing.png")});
}

TEST_CASE("bad glTF texture input: the error names the file and the field") {
    TemporaryFolder folder;
    GltfBuilder builder;
    const int indices = builder.indices({0, 1, 2});
    json attributes = {{"POSITION", builder.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3)},
                       {"TEXCOORD_0", builder.floats({0, 0, std::nanf(""), 0, 1, 1}, "VEC2", 2)}};
    json document = {{"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", indices}, {"material", 0}}}}}}},
                     {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
                     {"textures", {{{"sampler", 0}}}},
                     {"samplers", {{{"wrapS", 1234}}}}};
    CHECK_THROWS_WITH(read_mesh(folder.write("wrap.glb", builder.glb(document))),
                      Contains("wrap.glb: /samplers/0/wrapS: expected 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648"));
    document["samplers"] = json::array({json::object()});
    CHECK_THROWS_WITH(read_mesh(folder.write("nan.glb", builder.glb(document))),
                      Contains("nan.glb: /accessors/2: texture coordinate 1 is not finite"));
}
