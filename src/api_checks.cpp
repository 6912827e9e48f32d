#include "api_checks.hpp"

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "finite.hpp"
#include "mesh_scans.hpp"
#include "image_size.hpp"

namespace phongrast::detail {
namespace {

/// Throws when `value` is not one of `count` enumerators numbered from 0
/// (every enum of the API is): `member` names the field, `names` its values.
template <typename Enum>
void require_enum(Enum value, int count, const char* member, const char* names) {
    const int number = static_cast<int>(value);
    if (number < 0 || number >= count) {
        throw std::invalid_argument(std::string(member) + ": " + std::to_string(number) +
                                    " is not one of its values (expected " + names + ")");
    }
}

std::string vector_text(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
    return text;
}

}  // namespace

void validate_option_values(const RenderOptions& options) {
    require_enum(options.light_vectors, 2, "options.light_vectors", "triangle_centroid or shaded_point");
    require_enum(options.interpolation, 2, "options.interpolation", "screen_affine or perspective_correct");
    require_enum(options.border, 2, "options.border", "drop_triangle or clip");
    require_enum(options.visibility, 2, "options.visibility", "painter or depth_buffer");
    require_enum(options.overdraw, 3, "options.overdraw", "shade_all, shade_visible or automatic");
    require_enum(options.precision, 2, "options.precision", "single_float or double_float");
    require_enum(options.sample_pattern, 2, "options.sample_pattern", "ordered_grid or rotated_grid");
    require_enum(options.back_faces, 2, "options.back_faces", "draw or cull_when_hidden");
    if (options.samples_per_axis < 1 || options.samples_per_axis > 16) {
        throw std::invalid_argument("options.samples_per_axis: expected 1 to 16, got " +
                                    std::to_string(options.samples_per_axis));
    }
    if (options.threads < 0) {
        throw std::invalid_argument("options.threads: expected 0 (every core) or more, got " +
                                    std::to_string(options.threads));
    }
}

void validate_scene_enums(const Scene& scene) {
    require_enum(scene.shader, 3, "shader", "flat, gouraud or phong");
}

void validate_image_request(const ImageSpec& image, const RenderOptions& options) {
    validate_image_size(image.rows, image.columns, "image.rows", "image.columns");
    const double factor = options.samples_per_axis;
    const double samples = double(image.rows) * double(image.columns) * factor * factor;
    if (samples > double(kMaxImagePixels)) {
        throw std::length_error("image.rows x image.columns x options.samples_per_axis^2: " +
                                std::to_string(image.rows) + " x " + std::to_string(image.columns) + " x " +
                                std::to_string(options.samples_per_axis) + "^2 samples would take " +
                                memory_text(samples * double(kImageBytesPerPixel)) + " as float RGB; expected " +
                                image_limit_text("samples") + ": fewer samples per axis or a smaller image");
    }
}

void validate_user_normals(const Mesh& mesh) {
    const std::uint32_t finite[3] = {finite_magnitude_bits(), finite_magnitude_bits(), finite_magnitude_bits()};
    const std::size_t i = first_bad(
        mesh.normals.size(),
        [&](std::size_t begin, std::size_t end) { return any_beyond(mesh.normals.data(), begin, end, finite); },
        [&](std::size_t n) { return !all_finite(mesh.normals[n]); });
    if (i < mesh.normals.size()) {
        throw std::invalid_argument("mesh.normals[" + std::to_string(i) + "]: " + vector_text(mesh.normals[i]) +
                                    " is not finite (a zero normal is taken as \"compute this one\")");
    }
}

void validate_triangle_indices(const std::vector<Triangle>& triangles, std::size_t vertex_count, const char* what) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t index = triangles[t][static_cast<std::size_t>(corner)];
            if (index >= vertex_count) {
                throw std::out_of_range(std::string(what) + "[" + std::to_string(t) + "][" +
                                        std::to_string(corner) + "] = " + std::to_string(index) +
                                        ": expected a vertex index below positions.size() = " +
                                        std::to_string(vertex_count));
            }
        }
    }
}

}  // namespace phongrast::detail
