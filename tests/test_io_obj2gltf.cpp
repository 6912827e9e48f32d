// The same textured model as OBJ + MTL and as a GLB converted by an outside
// tool (the npm package obj2gltf): the loader must give the same per-corner
// positions, texture coordinates (glTF's v flipped back) and file normals
// from both, up to float rounding, and the same texture; rendered textured
// with the file's normals, the two give the same picture.
//
// Needs /work/shared/assets/spot.obj and spot_texture.png (PHONGRAST_SHARED_ASSETS_DIR,
// or the folder in $PHONGRAST_SHARED_ASSETS) and obj2gltf: $PHONGRAST_OBJ2GLTF,
// else `obj2gltf` on the PATH, else the copy this test installs once with npm
// (when npm is on the PATH and its registry answers) into the build folder's
// test-tools/ (PHONGRAST_TEST_TOOLS_DIR). Without them the test says
// "skipped: why".
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include <unistd.h>

#include "io_test_files.hpp"
#include "phongrast/render.hpp"
#include "support/image_compare.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"

namespace {

// The version installed when none is given: the one this test was written against.
constexpr const char* kObj2gltfPackage = "obj2gltf@3.2.0";

/// obj2gltf from npm into PHONGRAST_TEST_TOOLS_DIR, once per build folder:
/// installed into a folder of its own and renamed into place, so that two
/// test processes at once cannot leave a half-installed copy. Returns the
/// command, or empty (with `why` set) when npm is missing or fails.
std::string installed_obj2gltf(std::string& why) {
    namespace fs = std::filesystem;
    const fs::path tools = PHONGRAST_TEST_TOOLS_DIR;
    const fs::path command = tools / "obj2gltf" / "node_modules" / ".bin" / "obj2gltf";
    if (fs::exists(command)) return command.string();
    if (std::system("command -v npm > /dev/null 2>&1") != 0) {
        why = "obj2gltf not found and npm is not on the PATH to install it";
        return {};
    }
    fs::create_directories(tools);
    const fs::path staging = tools / ("obj2gltf.installing." + std::to_string(::getpid()));
    const fs::path log = tools / "obj2gltf-npm-install.log";
    const std::string install = "npm install --no-audit --no-fund --loglevel=error --prefix '" + staging.string() +
                                "' " + kObj2gltfPackage + " > '" + log.string() + "' 2>&1";
    const bool installed = std::system(install.c_str()) == 0;
    std::error_code ignored;
    if (installed) fs::rename(staging, tools / "obj2gltf", ignored);  // fails harmlessly if another test won
    fs::remove_all(staging, ignored);
    if (fs::exists(command)) return command.string();
    why = std::string("obj2gltf not found and `npm install ") + kObj2gltfPackage + "` failed (see " + log.string() +
          ")";
    return {};
}

std::string obj2gltf_command(std::string& why) {
    if (const char* given = std::getenv("PHONGRAST_OBJ2GLTF"); given != nullptr && *given != '\0') return given;
    if (std::system("command -v obj2gltf > /dev/null 2>&1") == 0) return "obj2gltf";
    return installed_obj2gltf(why);
}

/// A textured Phong picture of `mesh` with the file's normals, spot seen from the front left.
phongrast::Image picture_of(const phongrast::Mesh& mesh) {
    phongrast::Scene scene;
    scene.mesh = mesh;
    scene.normals = phongrast::NormalSource::file;
    // The scene's coefficients win over the MTL's Kd (which the GLB lacks).
    scene.material_fields.ka = glm::vec3(0.2f);
    scene.material_fields.kd = glm::vec3(0.8f);
    scene.material_fields.ks = glm::vec3(0.3f);
    scene.material_fields.n = 20.0f;
    scene.camera = phongrast::Camera::look_at({-1.2, 0.8, 2.6}, {0.0, 0.1, 0.0}, {0.0, 1.0, 0.0}, 1.0, 1.0, 1.0);
    scene.image.rows = scene.image.columns = 128;
    scene.lights = {phongrast::PointLight{{2.0, 3.0, 4.0}, glm::vec3(0.9f)}};
    scene.shader = phongrast::Shader::phong;
    return phongrast::render(scene).image;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("spot as OBJ + MTL and as obj2gltf's GLB: the same corners, texture coordinates, normals and texture") {
    const char* assets_override = std::getenv("PHONGRAST_SHARED_ASSETS");  // e.g. when run from a worktree
    const std::filesystem::path assets = assets_override != nullptr ? assets_override : PHONGRAST_SHARED_ASSETS_DIR;
    if (!std::filesystem::exists(assets / "spot.obj") || !std::filesystem::exists(assets / "spot_texture.png")) {
        WARN("skipped: " << (assets / "spot.obj").string() << " or spot_texture.png not found");
        return;
    }
    std::string why;
    const std::string converter = obj2gltf_command(why);
    if (converter.empty()) {
        WARN("skipped: " << why << " (or set PHONGRAST_OBJ2GLTF to an obj2gltf command)");
        return;
    }
    TemporaryFolder folder;
    std::filesystem::copy_file(assets / "spot_texture.png", folder.file("spot_texture.png"));
    folder.write("spot.mtl", "newmtl spot\nKd 1 1 1\nmap_Kd spot_texture.png\n");
    // spot.obj has `vt` but no `vn`: give every face its own normal (hard
    // edges everywhere), so each position carries several normals.
    const phongrast::io::ObjFile plain = phongrast::io::read_obj((assets / "spot.obj").string());
    char buffer[160];
    // The `vn` lines before the faces (obj2gltf does not follow forward references).
    std::string text = "mtllib spot.mtl\nusemtl spot\n";
    for (const phongrast::Triangle& t : plain.mesh.triangles) {
        const glm::dvec3 n = glm::cross(plain.mesh.positions[t[1]] - plain.mesh.positions[t[0]],
                                        plain.mesh.positions[t[2]] - plain.mesh.positions[t[0]]);
        const glm::vec3 unit(glm::normalize(n));
        std::snprintf(buffer, sizeof buffer, "vn %.9g %.9g %.9g\n", double(unit.x), double(unit.y), double(unit.z));
        text += buffer;
    }
    std::istringstream lines(read_text(assets / "spot.obj"));
    std::size_t face = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("f ", 0) != 0) {
            text += line + "\n";
            continue;
        }
        ++face;
        std::istringstream corners(line.substr(2));
        text += "f";
        for (std::string corner; corners >> corner;) text += " " + corner + "/" + std::to_string(face);
        text += "\n";
    }
    REQUIRE(face == plain.mesh.triangles.size());  // spot's faces are triangles
    const std::string obj_path = folder.write("spot.obj", text);
    const std::string glb_path = folder.file("spot.glb");
    const std::string command = "'" + converter + "' -i '" + obj_path + "' -o '" + glb_path + "' > '" +
                                folder.file("obj2gltf.log") + "' 2>&1";
    INFO(command << "\n" << read_text(folder.file("obj2gltf.log")));
    REQUIRE(std::system(command.c_str()) == 0);

    const phongrast::io::MeshFile obj = phongrast::io::read_mesh(obj_path);
    const phongrast::io::MeshFile glb = phongrast::io::read_mesh(glb_path);
    CHECK(obj.warnings.empty());
    CHECK(glb.warnings.empty());
    const phongrast::Mesh& a = obj.mesh;
    const phongrast::Mesh& b = glb.mesh;
    REQUIRE(a.triangles.size() == b.triangles.size());
    REQUIRE(a.texcoord_triangles.size() == a.triangles.size());
    REQUIRE(b.texcoord_triangles.size() == b.triangles.size());
    REQUIRE(a.file_normal_triangles.size() == a.triangles.size());
    REQUIRE(b.file_normal_triangles.size() == b.triangles.size());
    double position_error = 0, texcoord_error = 0, normal_error = 0;
    for (std::size_t t = 0; t < a.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            position_error = std::max(position_error, glm::length(a.positions[a.triangles[t][k]] - b.positions[b.triangles[t][k]]));
            REQUIRE(a.texcoord_triangles[t][k] != phongrast::kNoIndex);
            REQUIRE(b.texcoord_triangles[t][k] != phongrast::kNoIndex);
            texcoord_error = std::max(texcoord_error, double(glm::length(a.texcoords[a.texcoord_triangles[t][k]] -
                                                                         b.texcoords[b.texcoord_triangles[t][k]])));
            const glm::vec3 na = glm::normalize(a.file_normals[a.file_normal_triangles[t][k]]);
            const glm::vec3 nb = glm::normalize(b.file_normals[b.file_normal_triangles[t][k]]);
            normal_error = std::max(normal_error, double(glm::length(na - nb)));
        }
    }
    INFO("largest differences: position " << position_error << ", texture coordinate " << texcoord_error
                                          << ", normal " << normal_error);
    CHECK(position_error < 1e-6);  // spot fits in [-1, 1]^3: float rounding is below 6e-8
    CHECK(texcoord_error < 1e-6);  // t = 1 - (1 - v) in float
    CHECK(normal_error < 1e-6);
    // The same texture: the GLB's embedded copy and the file beside the MTL.
    REQUIRE(a.materials.size() == 1);
    REQUIRE(b.materials.size() == 1);
    REQUIRE(a.materials[0].texture);
    REQUIRE(b.materials[0].texture);
    REQUIRE(a.materials[0].texture->image);
    REQUIRE(b.materials[0].texture->image);
    CHECK(a.materials[0].texture->image->texels == b.materials[0].texture->image->texels);
    CHECK(b.materials[0].color_factor == glm::vec3(1.0f));
    CHECK(b.materials[0].texture->wrap_s == phongrast::TextureWrap::repeat);

    // The same picture: textured, lit with the file's normals. Positions
    // agree to float rounding, so at most a few silhouette pixels may differ.
    const phongrast::Image from_obj = picture_of(a), from_glb = picture_of(b);
    const phongrast::support::ImageAgreement agreement =
        phongrast::support::agreement(from_obj, from_glb, phongrast::ImageSpec{}.background);
    INFO(phongrast::support::summary(agreement));
    CHECK(agreement.covered_in_both > agreement.pixels / 8);
    CHECK(agreement.above_1 <= 3);
    CHECK(agreement.only_in_first + agreement.only_in_second <= 3);
}
