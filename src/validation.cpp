#include "validation.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "api_checks.hpp"
#include "finite.hpp"
#include "mesh_scans.hpp"
#include "raster.hpp"
#include "triangle_setup.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast {
namespace detail {
namespace {

void require_finite(const glm::vec3& value, const char* field) {
    if (!all_finite(value)) throw std::invalid_argument(std::string(field) + ": expected finite numbers");
}

void require_finite_camera_number(double value, const char* field) {
    if (!std::isfinite(value)) {
        throw std::invalid_argument(std::string("camera.") + field + ": expected a finite number, got " +
                                    std::to_string(value));
    }
}

void require_positive_finite(double value, const char* field) {
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument(std::string("camera.") + field + ": expected a positive finite number, got " +
                                    std::to_string(value));
    }
}

void validate_material_and_lights(const Scene& scene) {
    const PhongMaterial& m = scene.material;
    require_finite(m.ka, "material.ka");
    require_finite(m.kd, "material.kd");
    require_finite(m.ks, "material.ks");
    if (!(m.n >= 0.0f) || !std::isfinite(m.n)) {
        throw std::invalid_argument("material.n: expected a non-negative finite number");
    }
    require_finite(scene.ambient, "ambient");
    require_finite(scene.image.background, "image.background");
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (!all_finite(scene.lights[i].position) || !all_finite(scene.lights[i].intensity)) {
            throw std::invalid_argument("lights[" + std::to_string(i) + "]: expected finite position and intensity");
        }
    }
}

/// Short decimal form of a magnitude for messages ("2e+38", not 39 digits).
std::string short_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

/// How far the selected terms can light a channel: |I| <= |c| * per_colour +
/// fixed, since the dot products and max(0, R.V)^n are at most 1. In double,
/// so the bound itself cannot overflow.
struct LitBound {
    glm::dvec3 per_colour{0.0};  ///< |ka Ia| + sum over lights of |kd Ip|
    glm::dvec3 fixed{0.0};       ///< sum over lights of |ks Ip| (specular does not scale with c)
};

LitBound lit_bound(const Scene& scene) {
    const PhongMaterial& m = scene.material;
    LitBound bound;
    if (scene.lighting.ambient) bound.per_colour += glm::abs(glm::dvec3(m.ka) * glm::dvec3(scene.ambient));
    for (const PointLight& light : scene.lights) {
        const glm::dvec3 intensity = glm::abs(glm::dvec3(light.intensity));
        if (scene.lighting.diffuse) bound.per_colour += intensity * glm::abs(glm::dvec3(m.kd));
        if (scene.lighting.specular) bound.fixed += intensity * glm::abs(glm::dvec3(m.ks));
    }
    return bound;
}

double largest(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

/// Rejects scenes whose lit values could pass kMaxLitValue (validation.hpp)
/// whatever the mesh colours; returns the largest |colour| per channel a
/// vertex may have, which validate_mesh() then checks vertex by vertex.
glm::dvec3 colour_limit(const LitBound& bound, bool white_surface) {
    if (largest(bound.fixed) > kMaxLitValue) {
        throw std::invalid_argument("lights: the specular term (ks x intensity, summed over the lights) could reach " +
                                    short_number(largest(bound.fixed)) + ", expected at most " +
                                    short_number(kMaxLitValue) + "; scale ks or the light intensities down");
    }
    if (white_surface && largest(bound.per_colour + bound.fixed) > kMaxLitValue) {
        throw std::invalid_argument("material and lights: a white surface could be lit to " +
                                    short_number(largest(bound.per_colour + bound.fixed)) + ", expected at most " +
                                    short_number(kMaxLitValue) +
                                    "; scale ka, kd, the ambient or the light intensities down");
    }
    glm::dvec3 limit;
    for (int channel = 0; channel < 3; ++channel) {
        limit[channel] = bound.per_colour[channel] > 0.0
                             ? (kMaxLitValue - bound.fixed[channel]) / bound.per_colour[channel]
                             : std::numeric_limits<double>::infinity();
    }
    return limit;
}

}  // namespace

void validate_mesh(const Mesh& mesh, const glm::dvec3& colour_limit,
                   const std::function<double(const glm::vec3&)>& lit_value) {
    const std::string vertices = std::to_string(mesh.positions.size());
    const std::size_t bad_position = first_bad(
        mesh.positions.size(),
        [&](std::size_t begin, std::size_t end) { return any_nonfinite(mesh.positions.data(), begin, end); },
        [&](std::size_t i) { return !detail::all_finite(mesh.positions[i]); });
    if (bad_position < mesh.positions.size()) {
        throw std::invalid_argument("mesh: position of vertex " + std::to_string(bad_position) + " is not finite");
    }
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.colors.size()) + " colours for " + vertices +
                                    " vertices (expected one per vertex, or none)");
    }
    // Finite and within the limit in one pass (a NaN fails the comparison).
    const std::uint32_t colour_bits[3] = {passing_magnitude_bits(colour_limit.x),
                                          passing_magnitude_bits(colour_limit.y),
                                          passing_magnitude_bits(colour_limit.z)};
    const auto any_bad_colour = [&](std::size_t begin, std::size_t end) {
        return any_beyond(mesh.colors.data(), begin, end, colour_bits);
    };
    const std::size_t bad_color = first_bad(mesh.colors.size(), any_bad_colour, [&](std::size_t i) {
        const glm::vec3& c = mesh.colors[i];
        return !(std::abs(double(c.x)) <= colour_limit.x && std::abs(double(c.y)) <= colour_limit.y &&
                 std::abs(double(c.z)) <= colour_limit.z) ||
               !detail::all_finite(c);
    });
    if (bad_color < mesh.colors.size()) {
        const glm::vec3& c = mesh.colors[bad_color];
        const std::string vertex = "mesh: colour of vertex " + std::to_string(bad_color);
        if (!detail::all_finite(c)) throw std::invalid_argument(vertex + " is not finite");
        throw std::invalid_argument(vertex + " (" + short_number(c.x) + ", " + short_number(c.y) + ", " +
                                    short_number(c.z) + ") could be lit to " + short_number(lit_value(c)) +
                                    ", expected at most " + short_number(kMaxLitValue) +
                                    "; scale the colours, ka, kd or the light intensities down");
    }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.normals.size()) + " normals for " + vertices +
                                    " vertices (expected one per vertex, or none)");
    }
    if (mesh.triangles.size() > DrawSpan::kMaxTriangles) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.triangles.size()) + " triangles, expected at most " +
                                    std::to_string(detail::DrawSpan::kMaxTriangles));
    }
    const auto any_bad_index = [&](std::size_t begin, std::size_t end) {
        return any_index_at_least(mesh.triangles.data(), begin, end, mesh.positions.size());
    };
    const std::size_t bad_triangle = first_bad(mesh.triangles.size(), any_bad_index, [&](std::size_t i) {
        const Triangle& triangle = mesh.triangles[i];
        return std::max({triangle[0], triangle[1], triangle[2]}) >= mesh.positions.size();
    });
    if (bad_triangle == mesh.triangles.size()) return;
    for (std::uint32_t index : mesh.triangles[bad_triangle]) {
        if (index >= mesh.positions.size()) {
            throw std::invalid_argument("mesh: triangle " + std::to_string(bad_triangle) + " has vertex index " +
                                        std::to_string(index) + ", expected below " + vertices);
        }
    }
}

void validate_camera(const Camera& camera) {
    switch (camera.model) {
        case CameraModel::look_at:
        case CameraModel::orthographic:
            break;
        case CameraModel::opencv: {
            const OpenCvCamera& cv = camera.opencv;
            require_positive_finite(cv.fx, "opencv.fx");
            require_positive_finite(cv.fy, "opencv.fy");
            require_finite_camera_number(cv.cx, "opencv.cx");
            require_finite_camera_number(cv.cy, "opencv.cy");
            require_finite_camera_number(cv.skew, "opencv.skew");
            validate_pose(cv.world_to_camera, "camera.opencv.world_to_camera");
            return;  // the look-at fields are not used
        }
        default:
            throw std::invalid_argument("camera.model: expected look_at, opencv or orthographic, got " +
                                        std::to_string(static_cast<int>(camera.model)));
    }
    if (!all_finite(camera.eye)) throw std::invalid_argument("camera.eye: expected finite numbers");
    if (!all_finite(camera.lookat)) throw std::invalid_argument("camera.lookat: expected finite numbers");
    if (!all_finite(camera.up)) throw std::invalid_argument("camera.up: expected finite numbers");
    if (camera.model == CameraModel::look_at) require_positive_finite(camera.focal, "focal");  // orthographic: unused
    require_positive_finite(camera.sensor_height, "sensor_height");
    require_positive_finite(camera.sensor_width, "sensor_width");
}

void validate_render_request(const Scene& scene, const RenderOptions& options) {
    // api_checks.cpp: the caller's enums, sizes, signs and normals.
    validate_option_values(options);
    validate_scene_enums(scene);
    validate_material_and_lights(scene);
    const LitBound bound = lit_bound(scene);
    validate_mesh(scene.mesh, colour_limit(bound, scene.mesh.colors.empty()), [&](const glm::vec3& colour) {
        return largest(glm::abs(glm::dvec3(colour)) * bound.per_colour + bound.fixed);
    });
    validate_user_normals(scene.mesh);
    validate_image_request(scene.image, options);
    validate_camera(scene.camera);
}

}  // namespace detail

void validate_mesh(const Mesh& mesh) {
    const double any = std::numeric_limits<double>::infinity();
    detail::validate_mesh(mesh, glm::dvec3(any), [](const glm::vec3&) { return 0.0; });
}

}  // namespace phongrast
