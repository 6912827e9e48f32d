#include "bench_scenes.hpp"

#include <utility>

#include "support/scenes.hpp"

namespace phongrast_bench {

phongrast::Scene effect_scene(phongrast::Mesh mesh, int rows, int columns, phongrast::support::ViewAxis axis) {
    phongrast::Scene scene = phongrast::support::framed_scene(std::move(mesh), rows, columns, axis);
    scene.image.background = {0.05f, 0.05f, 0.1f};
    scene.material = phongrast::PhongMaterial{};  // ka 0.1, kd 0.8, ks 1, n 1: the contract's example
    scene.material.n = 16.0f;
    scene.ambient = glm::vec3(0.2f);
    scene.shader = phongrast::Shader::phong;
    scene.lighting = phongrast::Lighting::full();
    scene.lights = phongrast::support::lights_around(scene, 2);
    return scene;
}

std::vector<EffectVariant> effect_variants() {
    using phongrast::Lighting;
    return {
        {"ambient", Lighting::only_ambient(), false, false},
        {"diffuse", Lighting::only_diffuse(), false, false},
        {"specular", Lighting::only_specular(), false, false},
        {"full", Lighting::full(), false, false},
        {"full-kd0", Lighting::full(), true, false},
        {"full-ks0", Lighting::full(), false, true},
    };
}

phongrast::Scene with_effect(phongrast::Scene scene, const EffectVariant& variant) {
    scene.lighting = variant.lighting;
    if (variant.zero_kd) scene.material.kd = glm::vec3(0.0f);
    if (variant.zero_ks) scene.material.ks = glm::vec3(0.0f);
    return scene;
}

}  // namespace phongrast_bench
