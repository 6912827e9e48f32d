// The version-2 checks of a scene (objects, transforms, per-corner and
// per-face indices, texture coordinates, materials), apart from
// validation.cpp's checks of the version-1 fields, which then run on the
// assembled scene. Each failure names the member: "objects[2].transform: singular".
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "finite.hpp"
#include "scene_assembly.hpp"
#include "validation.hpp"

namespace phongrast::detail {
namespace {

[[noreturn]] void fail(const std::string& member, const std::string& what) {
    throw std::invalid_argument(member + ": " + what);
}

void check_fields(const MaterialFields& fields, const std::string& member) {
    if (fields.ka && !all_finite(*fields.ka)) fail(member + ".ka", "expected finite numbers");
    if (fields.kd && !all_finite(*fields.kd)) fail(member + ".kd", "expected finite numbers");
    if (fields.ks && !all_finite(*fields.ks)) fail(member + ".ks", "expected finite numbers");
    if (fields.n && (!(*fields.n >= 0.0f) || !std::isfinite(*fields.n))) {
        fail(member + ".n", "expected a non-negative finite number");
    }
}

void check_transform(const glm::dmat4& m, const std::string& member) {
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            if (!std::isfinite(m[column][row])) fail(member, "expected finite numbers");
        }
    }
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) {
        fail(member, "expected the last row to be 0 0 0 1");
    }
    const glm::dmat3 linear(m);
    const double det = glm::determinant(linear);
    if (det == 0.0 || !std::isfinite(det)) fail(member, "singular (determinant " + std::to_string(det) + ")");
    const glm::dmat3 inverse = glm::inverse(linear);
    for (int column = 0; column < 3; ++column) {
        if (!all_finite(inverse[column])) fail(member, "singular (its inverse is not finite)");
    }
}

/// Per-triangle index triples into an array of `values` entries: empty or
/// one per triangle, each index below `values` or kNoIndex.
void check_corner_indices(const std::vector<Triangle>& triples, std::size_t triangles, std::size_t values,
                          const std::string& member) {
    if (triples.empty()) return;
    if (triples.size() != triangles) {
        fail(member, std::to_string(triples.size()) + " entries for " + std::to_string(triangles) +
                         " triangles (expected one per triangle, or none)");
    }
    for (std::size_t t = 0; t < triples.size(); ++t) {
        for (std::uint32_t index : triples[t]) {
            if (index != kNoIndex && index >= values) {
                fail(member + "[" + std::to_string(t) + "]",
                     "index " + std::to_string(index) + ", expected below " + std::to_string(values));
            }
        }
    }
}

/// What validation learns of the texture images (validate_scene_objects()'s `checked`).
struct TextureScan {
    const CheckedTextures* before = nullptr;  ///< images whose texels need no scan
    CheckedTextures now;                      ///< this scene's images
};

/// `scan_texels` false: the texels were found finite before (CheckedTextures).
void check_texture(const TextureImage& image, const std::string& member, bool scan_texels) {
    if (image.rows < 1 || image.columns < 1 ||
        image.texels.size() != static_cast<std::size_t>(image.rows) * static_cast<std::size_t>(image.columns)) {
        fail(member, "image '" + image.name + "' of " + std::to_string(image.rows) + " x " +
                         std::to_string(image.columns) + " texels holds " + std::to_string(image.texels.size()) +
                         " (expected rows x columns, at least 1 x 1)");
    }
    for (std::size_t i = 0; scan_texels && i < image.texels.size(); ++i) {
        if (!all_finite(image.texels[i])) {
            fail(member, "image '" + image.name + "': texel " + std::to_string(i) + " is not finite");
        }
    }
}

void check_mesh(const Mesh& mesh, const std::string& member, TextureScan* scan) {
    try {
        const double any = std::numeric_limits<double>::infinity();
        validate_mesh(mesh, glm::dvec3(any), [](const glm::vec3&) { return 0.0; });
    } catch (const std::invalid_argument& error) {
        // validate_mesh() says "mesh: ..."; name the object's mesh instead.
        std::string text = error.what();
        if (text.rfind("mesh", 0) == 0) text.erase(0, 4);
        throw std::invalid_argument(member + text);
    }
    check_corner_indices(mesh.texcoord_triangles, mesh.triangles.size(), mesh.texcoords.size(),
                         member + ".texcoord_triangles");
    check_corner_indices(mesh.file_normal_triangles, mesh.triangles.size(), mesh.file_normals.size(),
                         member + ".file_normal_triangles");
    for (std::size_t i = 0; i < mesh.texcoords.size(); ++i) {
        if (!std::isfinite(mesh.texcoords[i].x) || !std::isfinite(mesh.texcoords[i].y)) {
            fail(member + ".texcoords[" + std::to_string(i) + "]", "expected finite numbers");
        }
    }
    if (!mesh.face_materials.empty() && mesh.face_materials.size() != mesh.triangles.size()) {
        fail(member + ".face_materials", std::to_string(mesh.face_materials.size()) + " entries for " +
                                             std::to_string(mesh.triangles.size()) +
                                             " triangles (expected one per triangle, or none)");
    }
    for (std::size_t t = 0; t < mesh.face_materials.size(); ++t) {
        const std::uint32_t index = mesh.face_materials[t];
        if (index != kNoIndex && index >= mesh.materials.size()) {
            fail(member + ".face_materials[" + std::to_string(t) + "]",
                 "index " + std::to_string(index) + ", expected below " + std::to_string(mesh.materials.size()));
        }
    }
    for (std::size_t i = 0; i < mesh.materials.size(); ++i) {
        const FaceMaterial& material = mesh.materials[i];
        const std::string name = member + ".materials[" + std::to_string(i) + "]" +
                                 (material.name.empty() ? std::string() : " (" + material.name + ")");
        check_fields(material.coefficients, name);
        if (!all_finite(material.color_factor)) fail(name + ".color_factor", "expected finite numbers");
        if (!material.texture || !material.texture->image) continue;
        const std::shared_ptr<const TextureImage>& image = material.texture->image;
        const bool known = scan != nullptr && scan->before != nullptr && scan->before->contains(*image);
        check_texture(*image, name + ".texture", !known);
        if (scan != nullptr && !scan->now.contains(*image)) {
            scan->now.entries.push_back({image, image->texels.data(), image->texels.size(), image->rows, image->columns});
        }
    }
}

}  // namespace

void validate_scene_objects(const Scene& scene, CheckedTextures* checked) {
    TextureScan scan;
    scan.before = checked;
    TextureScan* const texture_scan = checked != nullptr ? &scan : nullptr;
    check_fields(scene.material_fields, "material");
    if (scene.objects.empty()) {
        check_mesh(scene.mesh, "mesh", texture_scan);
        if (checked != nullptr) *checked = std::move(scan.now);
        return;
    }
    if (!scene.mesh.positions.empty() || !scene.mesh.triangles.empty()) {
        fail("mesh", "a scene with objects must leave mesh empty (one of mesh and objects)");
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const std::string member = "objects[" + std::to_string(i) + "]";
        if (!object.mesh) fail(member + ".mesh", "null (expected a mesh)");
        check_transform(object.transform, member + ".transform");
        check_fields(object.material, member + ".material");
        check_mesh(*object.mesh, member + ".mesh", texture_scan);
    }
    if (checked != nullptr) *checked = std::move(scan.now);
}

}  // namespace phongrast::detail
