// glTF 2.0 accessors read into the mesh's types, every offset, stride and
// count checked against its buffer view and buffer; the messages name the
// accessor ("/accessors/3") and what was expected.
#ifndef PHONGRAST_IO_GLTF_ACCESSORS_HPP
#define PHONGRAST_IO_GLTF_ACCESSORS_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace phongrast::io {

/// Throws FileError "path: /where: what".
[[noreturn]] void gltf_fail(const std::string& path, const std::string& where, const std::string& what);

/// The integer member `key` of `object` (at `where`), or `fallback` when absent.
std::int64_t gltf_integer(const nlohmann::json& object, const char* key, const std::string& where,
                          const std::string& path, std::int64_t fallback = -1);

/// The array (or object) member `key` of `object`, by reference; an empty one
/// when absent or of another type.
const nlohmann::json& gltf_array(const nlohmann::json& object, const char* key);
const nlohmann::json& gltf_object(const nlohmann::json& object, const char* key);

class GltfAccessors {
public:
    GltfAccessors(const nlohmann::json& document, std::vector<std::string_view> buffers, std::string path)
        : document_(document), buffers_(std::move(buffers)), path_(std::move(path)) {}

    /// VEC3 float positions, all finite.
    std::vector<glm::dvec3> positions(std::int64_t accessor) const;
    /// SCALAR unsigned byte, short or int indices.
    std::vector<std::uint32_t> indices(std::int64_t accessor) const;
    /// VEC3 or VEC4 colours: float, or normalised unsigned byte or short (alpha dropped).
    std::vector<glm::vec3> colors(std::int64_t accessor) const;
    /// VEC3 float normals (a non-finite one becomes 0: "take the computed normal").
    std::vector<glm::vec3> normals(std::int64_t accessor) const;
    /// VEC2 texture coordinates (u, v): float, or normalised unsigned byte or
    /// short; all finite.
    std::vector<glm::vec2> texcoords(std::int64_t accessor) const;
    /// The bytes of a buffer view (an image stored in the file's buffers).
    std::string_view buffer_view(std::int64_t index) const;

private:
    struct View {
        const unsigned char* first = nullptr;
        std::size_t stride = 0;
        std::size_t count = 0;
        int component_type = 0;
        int components = 0;
    };
    View view(std::int64_t accessor, const char* expected_types) const;
    double component(const View& view, std::size_t element, int component) const;

    const nlohmann::json& document_;
    std::vector<std::string_view> buffers_;
    std::string path_;
};

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_GLTF_ACCESSORS_HPP
