// Materials as contract version 2 states them (docs/scene-format.md,
// "Materials"): each face has the coefficients ka, kd, ks, n and an optional
// texture, and for each field the first of these that gives it wins: the
// object's material, the scene's material, the face's own material from the
// mesh file, then the base material (the contract's defaults for scene files).
#ifndef PHONGRAST_MATERIAL_HPP
#define PHONGRAST_MATERIAL_HPP

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "phongrast/lighting.hpp"
#include "phongrast/texture.hpp"

namespace phongrast {

/// Some of a material's coefficients: the ones that are set override,
/// field by field, whatever comes after them in the contract's precedence.
struct MaterialFields {
    std::optional<glm::vec3> ka, kd, ks;
    std::optional<float> n;

    bool empty() const { return !ka && !kd && !ks && !n; }
    /// `base` with every field this one sets replaced.
    PhongMaterial over(const PhongMaterial& base) const {
        PhongMaterial result = base;
        if (ka) result.ka = *ka;
        if (kd) result.kd = *kd;
        if (ks) result.ks = *ks;
        if (n) result.n = *n;
        return result;
    }
    /// This one's fields, and `fallback`'s where this one has none.
    MaterialFields or_else(const MaterialFields& fallback) const {
        MaterialFields result = *this;
        if (!result.ka) result.ka = fallback.ka;
        if (!result.kd) result.kd = fallback.kd;
        if (!result.ks) result.ks = fallback.ks;
        if (!result.n) result.n = fallback.n;
        return result;
    }
};

/// The material a mesh file gives some of its faces: an OBJ `usemtl` with its
/// MTL entry (Ka, Kd, Ks, Ns, map_Kd), or a glTF primitive's material
/// (baseColorFactor, baseColorTexture; glTF gives no coefficients).
struct FaceMaterial {
    std::string name;             ///< for messages
    MaterialFields coefficients;  ///< MTL Ka -> ka, Kd -> kd, Ks -> ks, Ns -> n (Kd is never the colour)
    /// glTF baseColorFactor (rgb): multiplies the surface colour c.
    glm::vec3 color_factor{1.0f};
    /// map_Kd / baseColorTexture. A texture whose image could not be read has
    /// a null `image` and draws with T = 1 (the loader warned).
    std::optional<TextureMap> texture;
};

}  // namespace phongrast

#endif  // PHONGRAST_MATERIAL_HPP
