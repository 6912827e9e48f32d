#include "image_array.hpp"

#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>

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

namespace {

/// Buffers of freed rendered images, waiting for the next render call.
/// Created once and never destroyed: arrays may be freed while the
/// interpreter shuts down, after static objects' destructors have run.
struct RecycledImages {
    std::mutex lock;
    std::vector<Image> spare;
};
RecycledImages& recycled_images() {
    static RecycledImages* const images = new RecycledImages;
    return *images;
}
constexpr std::size_t kSpareImages = 2;  // the array being replaced and the one replacing it
constexpr std::size_t kSpareImageBytes = std::size_t{64} << 20;

}  // namespace

Image take_recycled_image() {
    RecycledImages& images = recycled_images();
    const std::lock_guard<std::mutex> hold(images.lock);
    if (images.spare.empty()) return Image();
    Image image = std::move(images.spare.back());
    images.spare.pop_back();
    return image;
}

py::array image_to_recycling_array(Image&& image) {
    auto owned = std::make_unique<Image>(std::move(image));
    const py::ssize_t rows = owned->rows;
    const py::ssize_t columns = owned->columns;
    float* data = reinterpret_cast<float*>(owned->pixels.data());
    const py::capsule owner(owned.release(), [](void* pointer) {
        std::unique_ptr<Image> freed(static_cast<Image*>(pointer));
        if (freed->pixels.capacity() * sizeof(glm::vec3) > kSpareImageBytes) return;
        RecycledImages& images = recycled_images();
        const std::lock_guard<std::mutex> hold(images.lock);
        if (images.spare.size() < kSpareImages) images.spare.push_back(std::move(*freed));
    });
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
    // The scale follows the dtype, as numpy/PIL images mean it: uint8 holds
    // 0 to 255 (divided by 255 here), floats hold 0 to 1. Any other integer
    // type is ambiguous (0-255? 0-65535? 0-1?) and refused.
    const py::array any = py::array::ensure(value);
    if (!any) throw py::type_error(name + ": expected a numpy array (or nested lists) of RGB values");
    const char kind = any.dtype().kind();
    const bool bytes = kind == 'u' && any.dtype().itemsize() == 1;
    if (!bytes && kind != 'f') {
        throw py::type_error(name + ": expected dtype uint8 (0 to 255) or a float dtype (0 to 1), got " +
                             std::string(py::str(any.dtype())));
    }
    if (any.ndim() != 3 || any.shape(2) != 3 || any.shape(0) < 1 || any.shape(1) < 1) {
        throw py::value_error(name + ": expected an M x N x 3 array of RGB values");
    }
    validate_image_size(any.shape(0), any.shape(1), (name + ".shape[0]").c_str(), (name + ".shape[1]").c_str());
    Image image(static_cast<int>(any.shape(0)), static_cast<int>(any.shape(1)));
    if (bytes) {
        const auto array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(any);
        const std::uint8_t* data = array.data();
        float* pixels = &image.pixels.data()->x;
        for (std::size_t i = 0; i < image.pixels.size() * 3; ++i) pixels[i] = static_cast<float>(data[i]) / 255.0f;
    } else {
        const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(any);
        std::memcpy(image.pixels.data(), array.data(), image.pixels.size() * sizeof(glm::vec3));
    }
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
    if (!aovs.distance.empty()) {
        planes["distance"] = plane_to_array<float, float>(std::move(aovs.distance), rows, columns);
    }
    if (!aovs.normal.empty()) {
        planes["normal"] = plane_to_array<glm::vec3, float>(std::move(aovs.normal), rows, columns);
    }
    if (!aovs.id.empty()) planes["id"] = plane_to_array<std::int32_t, std::int32_t>(std::move(aovs.id), rows, columns);
    if (!aovs.alpha.empty()) planes["alpha"] = plane_to_array<float, float>(std::move(aovs.alpha), rows, columns);
    return planes;
}

}  // namespace phongrast::python
