#include "phongrast/io/auto_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "phongrast/camera.hpp"

namespace phongrast::io {

namespace {

/// The recipe on world-space points: camera, image, lights, ambient and the
/// neutral material of `scene` set to frame every point.
void frame_points(const std::vector<glm::dvec3>& points, int rows, int columns, Scene& scene) {
    glm::dvec3 low = points.front();
    glm::dvec3 high = low;
    for (const glm::dvec3& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 centre = 0.5 * (low + high);
    double diagonal = glm::length(high - low);
    // A single point (or a mesh too small to measure) still gets a usable camera.
    if (!(diagonal > 0.0) || !std::isfinite(diagonal)) diagonal = 1.0;

    scene.image.rows = rows;
    scene.image.columns = columns;
    scene.image.background = glm::vec3(1.0f);
    scene.camera.model = CameraModel::look_at;  // framing makes a look-at camera, whatever the scene had
    scene.camera.lookat = centre;
    scene.camera.eye = centre + glm::dvec3(0.0, 0.0, 2.5 * diagonal);
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.focal = 2.5 * diagonal;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.0;  // provisional, for the projection below

    // Fit every vertex with a 10% margin: on the image plane x = focal x_c / z_c.
    const CameraFrame frame = make_camera_frame(scene.camera, rows, columns);
    double half_width = 0.0;
    double half_height = 0.0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 c = frame.camera_from_world(p);
        if (!(c.z > 0.0)) continue;  // cannot happen: the eye is 2 diagonals outside the box
        half_width = std::max(half_width, std::abs(scene.camera.focal * c.x / c.z));
        half_height = std::max(half_height, std::abs(scene.camera.focal * c.y / c.z));
    }
    const double aspect = static_cast<double>(columns) / static_cast<double>(rows);
    double sensor_height = 2.2 * std::max(half_height, half_width / aspect);
    if (!(sensor_height > 0.0)) sensor_height = diagonal;
    scene.camera.sensor_height = sensor_height;
    scene.camera.sensor_width = sensor_height * aspect;

    // Key light above right in front, a weaker fill on the left, a rim light behind.
    const auto at = [&](double x, double y, double z) { return centre + diagonal * glm::dvec3(x, y, z); };
    scene.lights = {
        {at(1.2, 1.5, 2.0), glm::vec3(0.75f)},
        {at(-1.8, 0.3, 1.2), glm::vec3(0.3f)},
        {at(0.3, 1.8, -1.5), glm::vec3(0.35f)},
    };
    scene.ambient = glm::vec3(1.0f);
    scene.material.ka = glm::vec3(0.12f);
    scene.material.kd = glm::vec3(0.75f);
    scene.material.ks = glm::vec3(0.3f);
    scene.material.n = 32.0f;
}

}  // namespace

Scene frame_mesh(Mesh mesh, int rows, int columns) {
    validate_image_size(rows, columns, "rows", "columns");
    if (mesh.positions.empty()) throw std::invalid_argument("frame_mesh: the mesh has no vertices");
    Scene scene;
    frame_points(mesh.positions, rows, columns, scene);
    scene.shader = Shader::phong;
    scene.lighting = Lighting::full();
    scene.mesh = std::move(mesh);
    return scene;
}

void frame_scene(Scene& scene, int rows, int columns) {
    validate_image_size(rows, columns, "rows", "columns");
    std::vector<glm::dvec3> points = scene.mesh.positions;
    for (const SceneObject& object : scene.objects) {
        for (const glm::dvec3& p : object.mesh->positions) {
            const glm::dvec4 world = object.transform * glm::dvec4(p, 1.0);
            points.emplace_back(world.x, world.y, world.z);
        }
    }
    for (const glm::dvec3& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw std::invalid_argument("frame_scene: a vertex is not finite in world space");
        }
    }
    if (points.empty()) throw std::invalid_argument("frame_scene: the scene has no vertices");
    frame_points(points, rows, columns, scene);
}

}  // namespace phongrast::io
