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
    for (const RenderCounter& counter : render_counters()) d[counter.name] = stats.*counter.field;
    d["effects"] = to_string(stats.effects);
    d["back_faces_culled"] = stats.back_faces_culled;
    d["empty_scene"] = stats.empty_scene;
    d["seconds"] = stats.seconds;
    return d;
}

namespace {

/// An M x N (x 3 for vec3) array that takes over `values`.
template <typename Value, typename Component>
py::array plane_to_array(std::vector<Value>&& values, py::ssize_t rows, py::ssize_t columns) {
    auto owned = std::make_unique<std::vector<Value>>(std::move(values));
    auto* data = reinterpret_cast<Component*>(owned->data());
    const py::capsule owner = owning_capsule(std::move(owned));
    const auto item = static_cast<py::ssize_t>(sizeof(Component));
    constexpr py::ssize_t channels = sizeof(Value) / sizeof(Component);
    if (channels == 1) return py::array_t<Component>({rows, columns}, {columns * item, item}, data, owner);
    return py::array_t<Component>({rows, columns, channels}, {columns * channels * item, channels * item, item}, data,
                                  owner);
}

}  // namespace

py::dict aovs_to_dict(AovPlanes&& aovs) {
    py::dict planes;
    const py::ssize_t rows = aovs.rows, columns = aovs.columns;
    if (!aovs.depth.empty()) planes["depth"] = plane_to_array<float, float>(std::move(aovs.depth), rows, columns);
    if (!aovs.normal.empty()) {
        planes["normal"] = plane_to_array<glm::vec3, float>(std::move(aovs.normal), rows, columns);
    }
    if (!aovs.id.empty()) planes["id"] = plane_to_array<std::int32_t, std::int32_t>(std::move(aovs.id), rows, columns);
    if (!aovs.alpha.empty()) planes["alpha"] = plane_to_array<float, float>(std::move(aovs.alpha), rows, columns);
    return planes;
}

}  // namespace phongrast::python
