#include "validation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "finite.hpp"
#include "raster.hpp"
#include "triangle_setup.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast {
namespace detail {
namespace {

void require_finite(const glm::vec3& value, const char* field) {
    if (!all_finite(value)) throw std::invalid_argument(std::string(field) + ": expected finite numbers");
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

void validate_options_and_size(const Scene& scene, const RenderOptions& options) {
    if (options.samples_per_axis < 1 || options.samples_per_axis > 16) {
        throw std::invalid_argument("samples_per_axis: expected 1 to 16, got " +
                                    std::to_string(options.samples_per_axis));
    }
    if (options.threads < 0) throw std::invalid_argument("threads: expected 0 (all cores) or more");
    const int factor = options.samples_per_axis;
    const long long sample_rows = static_cast<long long>(scene.image.rows) * factor;
    const long long sample_columns = static_cast<long long>(scene.image.columns) * factor;
    if (scene.image.rows < 1 || sample_rows > kMaxImageSide) {
        throw std::invalid_argument("image.height: expected 1 to " + std::to_string(kMaxImageSide / factor) +
                                    " rows, got " + std::to_string(scene.image.rows));
    }
    if (scene.image.columns < 1 || sample_columns > kMaxImageSide) {
        throw std::invalid_argument("image.width: expected 1 to " + std::to_string(kMaxImageSide / factor) +
                                    " columns, got " + std::to_string(scene.image.columns));
    }
}

}  // namespace

void validate_camera(const Camera& camera) {
    if (!all_finite(camera.eye)) throw std::invalid_argument("camera.eye: expected finite numbers");
    if (!all_finite(camera.lookat)) throw std::invalid_argument("camera.lookat: expected finite numbers");
    if (!all_finite(camera.up)) throw std::invalid_argument("camera.up: expected finite numbers");
    require_positive_finite(camera.focal, "focal");
    require_positive_finite(camera.sensor_height, "sensor[0] (height)");
    require_positive_finite(camera.sensor_width, "sensor[1] (width)");
}

void validate_render_request(const Scene& scene, const RenderOptions& options) {
    validate_material_and_lights(scene);
    validate_mesh(scene.mesh);
    validate_options_and_size(scene, options);
    validate_camera(scene.camera);
}

}  // namespace detail

namespace {

/// The smallest i in [0, n) for which bad(i) holds, or n: the same answer as
/// a loop from 0, found in parallel over blocks (large meshes are checked
/// on every render).
template <typename Bad>
std::size_t first_bad(std::size_t n, const Bad& bad) {
    constexpr std::size_t kBlock = 65536;
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, kBlock), n,
        [&](const tbb::blocked_range<std::size_t>& range, std::size_t found) {
            for (std::size_t i = range.begin(); i < range.end() && i < found; ++i) {
                if (bad(i)) return i;
            }
            return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

}  // namespace

void validate_mesh(const Mesh& mesh) {
    const std::string vertices = std::to_string(mesh.positions.size());
    const std::size_t bad_position =
        first_bad(mesh.positions.size(), [&](std::size_t i) { return !detail::all_finite(mesh.positions[i]); });
    if (bad_position < mesh.positions.size()) {
        throw std::invalid_argument("mesh: position of vertex " + std::to_string(bad_position) + " is not finite");
    }
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.colors.size()) + " colours for " + vertices +
                                    " vertices (expected one per vertex, or none)");
    }
    const std::size_t bad_color =
        first_bad(mesh.colors.size(), [&](std::size_t i) { return !detail::all_finite(mesh.colors[i]); });
    if (bad_color < mesh.colors.size()) {
        throw std::invalid_argument("mesh: colour of vertex " + std::to_string(bad_color) + " is not finite");
    }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.normals.size()) + " normals for " + vertices +
                                    " vertices (expected one per vertex, or none)");
    }
    if (mesh.triangles.size() > detail::DrawnTriangle::kMaxTriangles) {
        throw std::invalid_argument("mesh: " + std::to_string(mesh.triangles.size()) + " triangles, expected at most " +
                                    std::to_string(detail::DrawnTriangle::kMaxTriangles));
    }
    const std::size_t bad_triangle = first_bad(mesh.triangles.size(), [&](std::size_t i) {
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

}  // namespace phongrast
