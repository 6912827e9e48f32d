// Effect detection: the render simulates only what the scene calls for.
#include <cstring>
#include <string>

#include "effects.hpp"

namespace phongrast {
namespace detail {
namespace {

bool non_zero(const glm::vec3& v) { return v.x != 0.0f || v.y != 0.0f || v.z != 0.0f; }

}  // namespace

EffectSet find_effects(const Scene& scene) { return find_effects(scene, scene.mesh.colors); }

EffectSet find_effects(const Scene& scene, const std::vector<glm::vec3>& colors) {
    EffectSet effects;
    for (const PointLight& light : scene.lights) {
        if (non_zero(light.intensity)) ++effects.active_lights;
    }
    const PhongMaterial& m = scene.material;
    effects.ambient = scene.lighting.ambient && non_zero(m.ka * scene.ambient);
    effects.diffuse = scene.lighting.diffuse && non_zero(m.kd) && effects.active_lights > 0;
    effects.specular = scene.lighting.specular && non_zero(m.ks) && effects.active_lights > 0;
    effects.normals = effects.diffuse || effects.specular;
    // Bit for bit, not by value: -0 and +0 are equal values, but a kernel
    // that writes colors[0] for every vertex's colour would flip the sign of
    // a zero channel, and images are compared bit for bit.
    for (std::size_t i = 1; i < colors.size() && !effects.varying_colors; ++i) {
        effects.varying_colors = std::memcmp(&colors[i], &colors[0], sizeof(glm::vec3)) != 0;
    }
    return effects;
}

}  // namespace detail

std::string to_string(const EffectSet& effects) {
    std::string terms;
    const auto add = [&terms](bool on, const char* name) {
        if (!on) return;
        if (!terms.empty()) terms += '+';
        terms += name;
    };
    add(effects.ambient, "ambient");
    add(effects.diffuse, "diffuse");
    add(effects.specular, "specular");
    if (terms.empty()) terms = "none";
    return terms + (effects.varying_colors ? ", varying colours" : ", uniform colour") + ", " +
           std::to_string(effects.active_lights) + " active light(s)";
}

}  // namespace phongrast
