// A program written the way a phongrast user writes one: render one triangle in
// memory and check two pixels. Exit status 0 only when both are right, so the
// consumer tests prove not just that it links but that the library it got works.
#include <cmath>
#include <cstdio>

#include <phongrast/phongrast.hpp>

// Never called, on purpose: -Wall warns about it (-Wunused-function), and this
// file is compiled without any warning flags. If phongrast pushed its own
// warnings plus -Werror onto the projects that use it, this file would fail to build.
static int deliberately_unused_function() { return 0; }

namespace {

bool close_to(const glm::vec3& got, const glm::vec3& want) {
    return std::abs(got.x - want.x) < 1e-5f && std::abs(got.y - want.y) < 1e-5f &&
           std::abs(got.z - want.z) < 1e-5f;
}

bool check_pixel(const phongrast::Image& image, int row, int column, const glm::vec3& want,
                 const char* what) {
    const glm::vec3& got = image.at(row, column);
    if (close_to(got, want)) return true;
    std::fprintf(stderr, "pixel (%d, %d), %s: got (%g, %g, %g), expected (%g, %g, %g)\n", row,
                 column, what, got.x, got.y, got.z, want.x, want.y, want.z);
    return false;
}

}  // namespace

int main() {
    // One triangle in the plane z = 0, counter-clockwise seen from the eye, so its
    // normal is +z; its centroid is the origin, right under the light.
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    phongrast::Scene scene;
    scene.mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 2, 0}};
    scene.mesh.colors = {color, color, color};
    scene.mesh.triangles = {{0, 1, 2}};
    scene.camera.eye = {0, 0, 5};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 2;
    scene.image.rows = scene.image.columns = 64;
    scene.image.background = glm::vec3(0.0f, 0.0f, 1.0f);
    scene.material.ka = glm::vec3(0.1f);
    scene.material.kd = glm::vec3(0.8f);
    scene.material.ks = glm::vec3(0.0f);
    scene.ambient = glm::vec3(0.2f);
    scene.lights = {{{0, 0, 10}, {1, 1, 1}}};
    scene.shader = phongrast::Shader::flat;

    const phongrast::RenderResult result = phongrast::render(scene, phongrast::RenderOptions::exact());

    // Flat shading lights the centroid: L = N = +z, so I = ka*Ia*c + Ip*kd*c*1 = 0.82 c.
    const bool ok = check_pixel(result.image, 32, 32, 0.82f * color, "inside the triangle") &&
                    check_pixel(result.image, 0, 0, scene.image.background, "background corner");
    if (ok) std::printf("phongrast %s: one triangle rendered as expected\n", PHONGRAST_VERSION_STRING);
    return ok ? 0 : 1;
}
