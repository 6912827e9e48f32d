#include "gltf_accessors.hpp"

#include <cmath>
#include <cstring>

#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

constexpr int unsigned_byte = 5121;
constexpr int unsigned_short = 5123;
constexpr int unsigned_int = 5125;
constexpr int float32 = 5126;

std::size_t component_size(int type) {
    switch (type) {
        case 5120:
        case unsigned_byte: return 1;
        case 5122:
        case unsigned_short: return 2;
        case unsigned_int:
        case float32: return 4;
        default: return 0;
    }
}

int component_count(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    if (type == "MAT4") return 16;
    return 0;
}

}  // namespace

void gltf_fail(const std::string& path, const std::string& where, const std::string& what) {
    throw FileError(path + ": " + where + ": " + what);
}

const nlohmann::json& gltf_array(const nlohmann::json& object, const char* key) {
    static const nlohmann::json empty = nlohmann::json::array();
    const auto it = object.is_object() ? object.find(key) : object.end();
    return it != object.end() && it->is_array() ? *it : empty;
}

const nlohmann::json& gltf_object(const nlohmann::json& object, const char* key) {
    static const nlohmann::json empty = nlohmann::json::object();
    const auto it = object.is_object() ? object.find(key) : object.end();
    return it != object.end() && it->is_object() ? *it : empty;
}

std::int64_t gltf_integer(const nlohmann::json& object, const char* key, const std::string& where,
                          const std::string& path, std::int64_t fallback) {
    if (!object.is_object()) gltf_fail(path, where, "expected an object");
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_integer() || it->get<std::int64_t>() < 0) {
        gltf_fail(path, where + "/" + key, "expected a non-negative integer, got " + it->dump());
    }
    return it->get<std::int64_t>();
}

GltfAccessors::View GltfAccessors::view(std::int64_t index, const char* expected_types) const {
    const std::string where = "/accessors/" + std::to_string(index);
    const nlohmann::json& accessors = gltf_array(document_, "accessors");
    if (index < 0 || static_cast<std::size_t>(index) >= accessors.size()) {
        gltf_fail(path_, where, "no such accessor (the file has " + std::to_string(accessors.size()) + ")");
    }
    const nlohmann::json& accessor = accessors[static_cast<std::size_t>(index)];
    if (!accessor.is_object()) gltf_fail(path_, where, "expected an object");
    if (accessor.contains("sparse")) gltf_fail(path_, where, "sparse accessors are not supported");
    View view;
    view.component_type = static_cast<int>(gltf_integer(accessor, "componentType", where, path_));
    view.components = component_count(accessor.value("type", std::string()));
    view.count = static_cast<std::size_t>(gltf_integer(accessor, "count", where, path_, 0));
    // "VEC3 of 5126" must be one of the comma-separated entries of `expected_types`, whole.
    const std::string type = accessor.value("type", std::string()) + " of " + std::to_string(view.component_type);
    const std::string expected = std::string(", ") + expected_types;
    const std::size_t at = expected.find(", " + type);
    const char after = at == std::string::npos ? '\0' : expected[at + 2 + type.size()];
    if (view.components == 0 || at == std::string::npos || (after != ',' && after != ' ')) {
        gltf_fail(path_, where, "type " + type + "; expected " + expected_types);
    }
    const std::int64_t buffer_view = gltf_integer(accessor, "bufferView", where, path_);
    const nlohmann::json& views = gltf_array(document_, "bufferViews");
    if (buffer_view < 0 || static_cast<std::size_t>(buffer_view) >= views.size()) {
        gltf_fail(path_, where + "/bufferView", "expected the index of one of the file's " +
                                                    std::to_string(views.size()) + " buffer views");
    }
    const std::string view_where = "/bufferViews/" + std::to_string(buffer_view);
    const nlohmann::json& buffer_view_object = views[static_cast<std::size_t>(buffer_view)];
    const std::int64_t buffer = gltf_integer(buffer_view_object, "buffer", view_where, path_);
    if (buffer < 0 || static_cast<std::size_t>(buffer) >= buffers_.size()) {
        gltf_fail(path_, view_where + "/buffer", "expected the index of one of the file's " +
                                                     std::to_string(buffers_.size()) + " buffers");
    }
    const auto view_offset = static_cast<std::uint64_t>(gltf_integer(buffer_view_object, "byteOffset", view_where, path_, 0));
    const auto view_length = static_cast<std::uint64_t>(gltf_integer(buffer_view_object, "byteLength", view_where, path_, 0));
    const std::string_view data = buffers_[static_cast<std::size_t>(buffer)];
    if (view_offset > data.size() || view_length > data.size() - view_offset) {
        gltf_fail(path_, view_where, "bytes " + std::to_string(view_offset) + " + " + std::to_string(view_length) +
                                         " exceed the buffer's " + std::to_string(data.size()) + " bytes");
    }
    const std::size_t element = component_size(view.component_type) * static_cast<std::size_t>(view.components);
    const auto stride = static_cast<std::uint64_t>(gltf_integer(buffer_view_object, "byteStride", view_where, path_, 0));
    view.stride = stride > 0 ? stride : element;
    const auto offset = static_cast<std::uint64_t>(gltf_integer(accessor, "byteOffset", where, path_, 0));
    if (view.count > 0 && (offset > view_length || view.stride < element ||
                           (view_length - offset - element) / view.stride < view.count - 1 ||
                           view_length - offset < element)) {
        gltf_fail(path_, where, std::to_string(view.count) + " elements of " + std::to_string(element) +
                                    " bytes (stride " + std::to_string(view.stride) + ") from byte " +
                                    std::to_string(offset) + " exceed buffer view " + std::to_string(buffer_view) +
                                    "'s " + std::to_string(view_length) + " bytes");
    }
    view.first = reinterpret_cast<const unsigned char*>(data.data()) + view_offset + offset;
    return view;
}

double GltfAccessors::component(const View& view, std::size_t element, int component) const {
    const unsigned char* at = view.first + element * view.stride + component_size(view.component_type) * component;
    switch (view.component_type) {
        case unsigned_byte: return *at;
        case unsigned_short: { std::uint16_t v; std::memcpy(&v, at, 2); return v; }
        case unsigned_int: { std::uint32_t v; std::memcpy(&v, at, 4); return v; }
        default: { float v; std::memcpy(&v, at, 4); return v; }
    }
}

std::vector<glm::dvec3> GltfAccessors::positions(std::int64_t accessor) const {
    const View v = view(accessor, "VEC3 of 5126 (float)");
    std::vector<glm::dvec3> result(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        for (int k = 0; k < 3; ++k) result[i][k] = component(v, i, k);
        if (!std::isfinite(result[i].x + result[i].y + result[i].z)) {
            gltf_fail(path_, "/accessors/" + std::to_string(accessor), "element " + std::to_string(i) +
                                                                          " is not finite; expected finite positions");
        }
    }
    return result;
}

std::vector<std::uint32_t> GltfAccessors::indices(std::int64_t accessor) const {
    const View v = view(accessor, "SCALAR of 5121, SCALAR of 5123, SCALAR of 5125 (unsigned byte, short or int)");
    std::vector<std::uint32_t> result(v.count);
    for (std::size_t i = 0; i < v.count; ++i) result[i] = static_cast<std::uint32_t>(component(v, i, 0));
    return result;
}

std::vector<glm::vec3> GltfAccessors::colors(std::int64_t accessor) const {
    const View v = view(accessor, "VEC3 of 5126, VEC4 of 5126, VEC3 of 5121, VEC4 of 5121, VEC3 of 5123, VEC4 of "
                                  "5123 (float, normalised unsigned byte or short)");
    const double scale = v.component_type == unsigned_byte ? 1.0 / 255 : v.component_type == unsigned_short ? 1.0 / 65535 : 1.0;
    std::vector<glm::vec3> result(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        for (int k = 0; k < 3; ++k) result[i][k] = static_cast<float>(component(v, i, k) * scale);
        if (!std::isfinite(result[i].x + result[i].y + result[i].z)) {
            gltf_fail(path_, "/accessors/" + std::to_string(accessor), "colour " + std::to_string(i) + " is not finite");
        }
    }
    return result;
}

}  // namespace phongrast::io

namespace phongrast::io {

std::vector<glm::vec3> GltfAccessors::normals(std::int64_t accessor) const {
    const View v = view(accessor, "VEC3 of 5126 (float)");
    std::vector<glm::vec3> result(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        glm::vec3 n;
        for (int k = 0; k < 3; ++k) n[k] = static_cast<float>(component(v, i, k));
        if (std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) result[i] = n;
    }
    return result;
}

std::vector<glm::vec2> GltfAccessors::texcoords(std::int64_t accessor) const {
    const View v = view(accessor, "VEC2 of 5126, VEC2 of 5121, VEC2 of 5123 (float, normalised unsigned byte or short)");
    const double scale = v.component_type == unsigned_byte ? 1.0 / 255 : v.component_type == unsigned_short ? 1.0 / 65535 : 1.0;
    std::vector<glm::vec2> result(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
        for (int k = 0; k < 2; ++k) result[i][k] = static_cast<float>(component(v, i, k) * scale);
        if (!std::isfinite(result[i].x) || !std::isfinite(result[i].y)) {
            gltf_fail(path_, "/accessors/" + std::to_string(accessor),
                      "texture coordinate " + std::to_string(i) + " is not finite; expected finite numbers");
        }
    }
    return result;
}

std::string_view GltfAccessors::buffer_view(std::int64_t index) const {
    const std::string where = "/bufferViews/" + std::to_string(index);
    const nlohmann::json& views = gltf_array(document_, "bufferViews");
    if (index < 0 || static_cast<std::size_t>(index) >= views.size()) gltf_fail(path_, where, "no such buffer view");
    const nlohmann::json& view = views[static_cast<std::size_t>(index)];
    const std::int64_t buffer = gltf_integer(view, "buffer", where, path_);
    if (buffer < 0 || static_cast<std::size_t>(buffer) >= buffers_.size()) {
        gltf_fail(path_, where + "/buffer", "expected the index of one of the file's " + std::to_string(buffers_.size()) + " buffers");
    }
    const auto offset = static_cast<std::uint64_t>(gltf_integer(view, "byteOffset", where, path_, 0));
    const auto length = static_cast<std::uint64_t>(gltf_integer(view, "byteLength", where, path_, 0));
    const std::string_view data = buffers_[static_cast<std::size_t>(buffer)];
    if (offset > data.size() || length > data.size() - offset) {
        gltf_fail(path_, where, "bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                                    " exceed the buffer's " + std::to_string(data.size()) + " bytes");
    }
    return data.substr(offset, length);
}

}  // namespace phongrast::io
