// SceneAssembly: a Renderer's assembled scene, kept while nothing assembly
// reads has changed. Meshes are compared by content against a copy, not by
// address: a `mesh` scene is held by value and may be edited in place
// between frames (so may a shared object mesh, through another pointer), and
// a stale assembly would draw the old mesh. Comparing is a few memcmp's over
// the arrays, far cheaper than assembling (normals, vertex splitting,
// validation) and its allocations.
#include <cstring>
#include <type_traits>
#include <unordered_map>

#include "same_array.hpp"
#include "scene_assembly.hpp"

namespace phongrast::detail {
namespace {

/// The same bits (so -0 and +0 differ, and a NaN equals itself: assembly's result is a function of the bits).
template <typename T>
bool same_bits(const T& a, const T& b) {
    static_assert(std::is_trivially_copyable_v<T>);
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <typename T>
bool same_optional(const std::optional<T>& a, const std::optional<T>& b) {
    return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}

bool same_fields(const MaterialFields& a, const MaterialFields& b) {
    return same_optional(a.ka, b.ka) && same_optional(a.kd, b.kd) && same_optional(a.ks, b.ks) &&
           same_optional(a.n, b.n);
}

bool same_material(const PhongMaterial& a, const PhongMaterial& b) {
    return same_bits(a.ka, b.ka) && same_bits(a.kd, b.kd) && same_bits(a.ks, b.ks) && same_bits(a.n, b.n);
}

/// A texture by its image's address (texels are read at render time, not copied) and wrap modes.
bool same_texture(const std::optional<TextureMap>& a, const std::optional<TextureMap>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->image == b->image && a->wrap_s == b->wrap_s && a->wrap_t == b->wrap_t);
}

bool same_face_material(const FaceMaterial& a, const FaceMaterial& b) {
    return a.name == b.name && same_fields(a.coefficients, b.coefficients) &&
           same_bits(a.color_factor, b.color_factor) && same_texture(a.texture, b.texture);
}

/// Every field of Mesh that assembly or its validation reads.
bool same_content(const Mesh& a, const Mesh& b) {
    if (!same_array(a.positions, b.positions) || !same_array(a.colors, b.colors) ||
        !same_array(a.triangles, b.triangles) || !same_array(a.normals, b.normals) ||
        !same_array(a.texcoords, b.texcoords) || !same_array(a.texcoord_triangles, b.texcoord_triangles) ||
        !same_array(a.file_normals, b.file_normals) ||
        !same_array(a.file_normal_triangles, b.file_normal_triangles) ||
        !same_array(a.face_materials, b.face_materials) || a.materials.size() != b.materials.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        if (!same_face_material(a.materials[i], b.materials[i])) return false;
    }
    return true;
}

bool same_normal_source(const std::optional<NormalSource>& a, const std::optional<NormalSource>& b) {
    return a.has_value() == b.has_value() && (!a || *a == *b);
}

}  // namespace

namespace {

bool still_as_checked(const CheckedTextures::Entry& entry, const TextureImage& image) {
    return entry.image.get() == &image && entry.texels == image.texels.data() && entry.count == image.texels.size() &&
           entry.rows == image.rows && entry.columns == image.columns;
}

}  // namespace

bool CheckedTextures::contains(const TextureImage& image) const {
    for (const Entry& entry : entries) {
        if (still_as_checked(entry, image)) return true;
    }
    return false;
}

bool CheckedTextures::unchanged() const {
    for (const Entry& entry : entries) {
        if (!still_as_checked(entry, *entry.image)) return false;
    }
    return true;
}

const AssembledScene& SceneAssembly::assemble(const Scene& scene) {
    if (valid_ && same_as_before(scene)) {
        copy_view_fields(scene, assembled.scene);
        return assembled;
    }
    valid_ = false;
    assemble_scene(scene, assembled, normals_scratch, &checked_textures_);
    ++assemblies;
    remember(scene);
    return assembled;
}

bool SceneAssembly::same_as_before(const Scene& scene) const {
    if (scene.objects.empty() != mesh_scene_) return false;
    // A texture whose texel array was replaced or resized is checked again (by a new assembly).
    if (!checked_textures_.unchanged()) return false;
    if (!same_material(scene.material, key_material_) || !same_fields(scene.material_fields, key_material_fields_) ||
        scene.normals != key_normals_) {
        return false;
    }
    if (mesh_scene_) return same_content(scene.mesh, snapshots_[0]);
    // Objects: `mesh` must stay empty (validation), each object as before.
    if (!scene.mesh.positions.empty() || !scene.mesh.triangles.empty() || scene.objects.size() != objects_.size()) {
        return false;
    }
    for (std::size_t i = 0; i < objects_.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const ObjectKey& key = objects_[i];
        if (!object.mesh || !same_bits(object.transform, key.transform) || !same_fields(object.material, key.material) ||
            !same_normal_source(object.normals, key.normals)) {
            return false;
        }
        // A mesh placed again (same pointer as its first placement) was compared there.
        const bool compared = key.first_use < i && object.mesh == scene.objects[key.first_use].mesh;
        if (!compared && !same_content(*object.mesh, snapshots_[key.snapshot])) return false;
    }
    return true;
}

void SceneAssembly::remember(const Scene& scene) {
    mesh_scene_ = scene.objects.empty();
    objects_.clear();
    std::size_t used = 0;
    const auto snapshot = [&](const Mesh& mesh) {
        if (snapshots_.size() <= used) snapshots_.emplace_back();
        snapshots_[used] = mesh;  // copy-assigned: reuses the arrays' memory
        return used++;
    };
    if (mesh_scene_) {
        snapshot(scene.mesh);
    } else {
        std::unordered_map<const Mesh*, std::size_t> first_use;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& object = scene.objects[i];
            ObjectKey key;
            const auto [at, added] = first_use.emplace(object.mesh.get(), i);
            key.first_use = at->second;
            key.snapshot = added ? snapshot(*object.mesh) : objects_[at->second].snapshot;
            key.transform = object.transform;
            key.material = object.material;
            key.normals = object.normals;
            objects_.push_back(key);
        }
    }
    snapshots_.resize(used);
    key_material_ = scene.material;
    key_material_fields_ = scene.material_fields;
    key_normals_ = scene.normals;
    valid_ = true;
}

}  // namespace phongrast::detail
