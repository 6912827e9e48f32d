#include "image_array.hpp"

#include <cstring>
#include <memory>

namespace phongrast::python {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 must be three packed floats");
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "glm::dvec3 must be three packed doubles");

namespace {

template <typename Owned>
py::capsule owning_capsule(std::unique_ptr<Owned> owned) {
    return py::capsule(owned.release(), [](void* pointer) { delete static_cast<Owned*>(pointer); });
}

}  // namespace

py::array image_to_array(Image&& image) {
    auto owned = std::make_unique<Image>(std::move(image));
    const py::ssize_t rows = owned->rows;
    const py::ssize_t columns = owned->columns;
    float* data = reinterpret_cast<float*>(owned->pixels.data());
    const py::capsule owner = owning_capsule(std::move(owned));
    const auto item = static_cast<py::ssize_t>(sizeof(float));
    return py::array_t<float>({rows, columns, py::ssize_t{3}}, {columns * 3 * item, 3 * item, item}, data, owner);
}

py::array points_to_array(std::vector<glm::vec3>&& values) {
    auto owned = std::make_unique<std::vector<glm::vec3>>(std::move(values));
    float* data = reinterpret_cast<float*>(owned->data());
    const std::size_t count = owned->size();
    return view_rows_of_three(data, count, owning_capsule(std::move(owned)), true);
}

Image array_to_image(py::handle value, const std::string& name) {
    const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!array || array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 1 || array.shape(1) < 1) {
        throw py::value_error(name + ": expected an M x N x 3 array of RGB values");
    }
    Image image(static_cast<int>(array.shape(0)), static_cast<int>(array.shape(1)));
    std::memcpy(image.pixels.data(), array.data(), image.pixels.size() * sizeof(glm::vec3));
    return image;
}

py::dict stats_to_dict(const RenderStats& stats) {
    py::dict d;
    d["triangles_in"] = stats.triangles_in;
    d["triangles_drawn"] = stats.triangles_drawn;
    d["triangles_dropped"] = stats.triangles_dropped;
    d["triangles_clipped"] = stats.triangles_clipped;
    d["triangles_culled"] = stats.triangles_culled;
    d["triangles_outside"] = stats.triangles_outside;
    d["triangles_between_samples"] = stats.triangles_between_samples;
    d["triangles_degenerate"] = stats.triangles_degenerate;
    d["samples_covered"] = stats.samples_covered;
    d["samples_shaded"] = stats.samples_shaded;
    d["nonfinite_values_replaced"] = stats.nonfinite_values_replaced;
    d["ambient_evaluations"] = stats.ambient_evaluations;
    d["diffuse_evaluations"] = stats.diffuse_evaluations;
    d["specular_evaluations"] = stats.specular_evaluations;
    d["normal_interpolations"] = stats.normal_interpolations;
    d["effects"] = to_string(stats.effects);
    d["back_faces_culled"] = stats.back_faces_culled;
    d["seconds"] = stats.seconds;
    return d;
}

}  // namespace phongrast::python
