// The checks that keep a caller's mistake from reaching the pipeline as
// undefined behaviour (internal header): enums outside their values, the
// image and sample counts against the shared size limit, user normals, and
// coefficients and intensities that must not be negative. Each throws a
// standard exception naming the C++ member the caller set (`image.rows`,
// `options.visibility`, `lights[2].intensity`); docs/robustness.md lists the
// cases and what is an error and what is defined behaviour.
#ifndef PHONGRAST_SRC_API_CHECKS_HPP
#define PHONGRAST_SRC_API_CHECKS_HPP

#include <vector>

#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Every enum of RenderOptions within its values, samples_per_axis 1 to 16,
/// threads 0 or more: std::invalid_argument otherwise.
void validate_option_values(const RenderOptions& options);
/// Scene::shader within its values: std::invalid_argument otherwise.
void validate_scene_enums(const Scene& scene);
/// The image against validate_image_size(), and its samples (rows x columns x
/// samples_per_axis^2) against kMaxImagePixels: std::length_error past them.
void validate_image_request(const ImageSpec& image, const RenderOptions& options);
/// Mesh::normals finite: std::invalid_argument naming the first bad one.
/// (A zero normal is defined behaviour: the computed one replaces it.)
void validate_user_normals(const Mesh& mesh);
/// Every index of `triangles` below `vertex_count`: std::out_of_range naming
/// `what` (e.g. "triangles"), the triangle, the corner and the index.
void validate_triangle_indices(const std::vector<Triangle>& triangles, std::size_t vertex_count, const char* what);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_API_CHECKS_HPP
