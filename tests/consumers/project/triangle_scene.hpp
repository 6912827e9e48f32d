// The consumer programs' scene: one triangle whose lit colour is known in closed
// form, and a check of two pixels of an image rendered from it.
#ifndef PHONGRAST_CONSUMER_TRIANGLE_SCENE_HPP
#define PHONGRAST_CONSUMER_TRIANGLE_SCENE_HPP

#include <cmath>
#include <cstdio>

#include <phongrast/phongrast.hpp>

namespace consumer {

const glm::vec3 triangle_color(1.0f, 0.5f, 0.25f);
const glm::vec3 background(0.0f, 0.0f, 1.0f);

inline phongrast::Scene triangle_scene() {
    // One triangle in the plane z = 0, counter-clockwise seen from the eye, so its
    // normal is +z; its centroid is the origin, right under the light.
    phongrast::Scene scene;
    scene.mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 2, 0}};
    scene.mesh.colors = {triangle_color, triangle_color, triangle_color};
    scene.mesh.triangles = {{0, 1, 2}};
    scene.camera.eye = {0, 0, 5};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 2;
    scene.image.rows = scene.image.columns = 64;
    scene.image.background = background;
    scene.material.ka = glm::vec3(0.1f);
    scene.material.kd = glm::vec3(0.8f);
    scene.material.ks = glm::vec3(0.0f);
    scene.ambient = glm::vec3(0.2f);
    scene.lights = {{{0, 0, 10}, {1, 1, 1}}};
    scene.shader = phongrast::Shader::flat;
    return scene;
}

inline bool check_pixel(const phongrast::Image& image, int row, int column, const glm::vec3& want,
                        const char* what) {
    const glm::vec3& got = image.at(row, column);
    if (std::abs(got.x - want.x) < 1e-5f && std::abs(got.y - want.y) < 1e-5f &&
        std::abs(got.z - want.z) < 1e-5f)
        return true;
    std::fprintf(stderr, "pixel (%d, %d), %s: got (%g, %g, %g), expected (%g, %g, %g)\n", row,
                 column, what, got.x, got.y, got.z, want.x, want.y, want.z);
    return false;
}

/// Flat shading lights the centroid: L = N = +z, so I = ka*Ia*c + Ip*kd*c*1 = 0.82 c
/// at the centre; the corner is background.
inline bool image_is_right(const phongrast::Image& image) {
    if (image.rows != 64 || image.columns != 64) {
        std::fprintf(stderr, "image is %d x %d, expected 64 x 64\n", image.rows, image.columns);
        return false;
    }
    return check_pixel(image, 32, 32, 0.82f * triangle_color, "inside the triangle") &&
           check_pixel(image, 0, 0, background, "background corner");
}

}  // namespace consumer

#endif  // PHONGRAST_CONSUMER_TRIANGLE_SCENE_HPP
