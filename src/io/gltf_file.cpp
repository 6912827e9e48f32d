// glTF 2.0, as .gltf (JSON with external or base64 data: buffers) or .glb
// (binary container): every triangle primitive of every mesh instance in the
// default scene, with its node transforms, in the contract's order (a
// depth-first walk, each node before its children, primitives in order);
// vertex colours from COLOR_0 (else white), NORMAL as the file's normals
// (through the node matrices' inverse transpose), the texture's TEXCOORD_n as
// (u, 1 - v), and each primitive's material (gltf_materials.hpp).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <functional>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "file_bytes.hpp"
#include "gltf_accessors.hpp"
#include "gltf_materials.hpp"
#include "mesh_readers.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

using nlohmann::json;

std::uint32_t little_u32(std::string_view bytes, std::size_t offset) {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, 4);
    return value;
}

/// The JSON text and the BIN chunk of a .glb (an empty BIN when there is none).
std::pair<std::string_view, std::string_view> split_glb(std::string_view bytes, const std::string& path) {
    const auto fail = [&](std::size_t byte, const std::string& what) {
        throw FileError(path + ": byte " + std::to_string(byte) + ": " + what);
    };
    if (bytes.size() < 20) fail(bytes.size(), "the file ends inside the GLB header (a truncated file?)");
    if (little_u32(bytes, 4) != 2) fail(4, "GLB version " + std::to_string(little_u32(bytes, 4)) + "; expected 2");
    const std::uint32_t length = little_u32(bytes, 8);
    if (length > bytes.size()) {
        fail(8, "the header declares " + std::to_string(length) + " bytes, the file has " +
                    std::to_string(bytes.size()) + " (a truncated file?)");
    }
    std::string_view chunks[2];
    std::size_t offset = 12;
    for (int i = 0; i < 2 && offset + 8 <= length; ++i) {
        const std::uint32_t chunk_length = little_u32(bytes, offset);
        const std::uint32_t type = little_u32(bytes, offset + 4);
        if (chunk_length > length - offset - 8) {
            fail(offset, "chunk of " + std::to_string(chunk_length) + " bytes exceeds the file (a truncated file?)");
        }
        if (type != (i == 0 ? 0x4E4F534Au : 0x004E4942u)) fail(offset + 4, i == 0 ? "expected the JSON chunk" : "expected the BIN chunk");
        chunks[i] = bytes.substr(offset + 8, chunk_length);
        offset += 8 + chunk_length;
    }
    if (chunks[0].data() == nullptr) fail(12, "no JSON chunk");
    return {chunks[0], chunks[1]};
}

glm::dmat4 local_transform(const json& node, const std::string& where, const std::string& path) {
    const auto numbers = [&](const char* key, std::size_t count, std::vector<double> fallback) {
        const auto it = node.find(key);
        if (it == node.end()) return fallback;
        if (!it->is_array() || it->size() != count) {
            gltf_fail(path, where + "/" + key, "expected an array of " + std::to_string(count) + " numbers");
        }
        std::vector<double> values;
        for (const json& v : *it) {
            if (!v.is_number() || !std::isfinite(v.get<double>())) gltf_fail(path, where + "/" + key, "expected finite numbers");
            values.push_back(v.get<double>());
        }
        return values;
    };
    if (node.contains("matrix")) return glm::make_mat4(numbers("matrix", 16, {}).data());  // column-major, as glTF
    const std::vector<double> t = numbers("translation", 3, {0, 0, 0});
    const std::vector<double> r = numbers("rotation", 4, {0, 0, 0, 1});
    const std::vector<double> s = numbers("scale", 3, {1, 1, 1});
    const glm::dquat rotation(r[3], r[0], r[1], r[2]);  // glTF stores x y z w
    glm::dmat4 m = glm::mat4_cast(glm::normalize(rotation));
    for (int c = 0; c < 3; ++c) m[c] *= s[static_cast<std::size_t>(c)];
    m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    return m;
}

class GltfScene {
public:
    GltfScene(const json& document, const GltfAccessors& accessors, const std::string& path)
        : document_(document), accessors_(accessors), path_(path), materials_(document, accessors, path, file_.warnings) {}

    MeshFile read() {
        const json& nodes = gltf_array(document_, "nodes");
        for (const std::int64_t root : roots()) visit(root, glm::dmat4(1.0), 0);
        if (nodes.empty()) {  // meshes without nodes: each once, untransformed
            for (std::size_t m = 0; m < gltf_array(document_, "meshes").size(); ++m) add_mesh(static_cast<std::int64_t>(m), glm::dmat4(1.0));
        }
        if (file_.mesh.triangles.empty()) throw FileError(path_ + ": no triangles in the scene's meshes; expected at least one");
        Mesh& mesh = file_.mesh;
        // The per-triangle lists that were started, padded past the last primitive that had them.
        const std::size_t triangles = mesh.triangles.size();
        if (any_normals_) mesh.file_normal_triangles.resize(triangles, Triangle{kNoIndex, kNoIndex, kNoIndex});
        if (any_texcoords_) mesh.texcoord_triangles.resize(triangles, Triangle{kNoIndex, kNoIndex, kNoIndex});
        if (!mesh.materials.empty()) mesh.face_materials.resize(triangles, kNoIndex);
        warn_textured_faces_without_texcoords(file_, path_);
        file_.side_files.insert(file_.side_files.end(), materials_.image_files.begin(), materials_.image_files.end());
        return std::move(file_);
    }

private:
    std::vector<std::int64_t> roots() const {
        const json& scenes = gltf_array(document_, "scenes");
        std::vector<std::int64_t> result;
        if (!scenes.empty()) {
            const std::int64_t scene = gltf_integer(document_, "scene", "", path_, 0);
            if (static_cast<std::size_t>(scene) >= scenes.size()) gltf_fail(path_, "/scene", "no such scene");
            for (const json& n : gltf_array(scenes[static_cast<std::size_t>(scene)], "nodes")) {
                if (!n.is_number_integer()) gltf_fail(path_, "/scenes/" + std::to_string(scene) + "/nodes", "expected node indices");
                result.push_back(n.get<std::int64_t>());
            }
            return result;
        }
        const json& nodes = gltf_array(document_, "nodes");
        std::vector<bool> child(nodes.size(), false);
        for (const json& node : nodes) {
            for (const json& c : gltf_array(node, "children")) {
                if (c.is_number_unsigned() && c.get<std::size_t>() < nodes.size()) child[c.get<std::size_t>()] = true;
            }
        }
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (!child[i]) result.push_back(static_cast<std::int64_t>(i));
        }
        return result;
    }

    void visit(std::int64_t index, const glm::dmat4& parent, int depth) {
        const json& nodes = gltf_array(document_, "nodes");
        const std::string where = "/nodes/" + std::to_string(index);
        if (index < 0 || static_cast<std::size_t>(index) >= nodes.size()) gltf_fail(path_, where, "no such node");
        if (depth > 256) gltf_fail(path_, where, "nodes nested more than 256 deep (a cycle?)");
        // A node may be the child of several parents; a graph that repeats
        // itself could otherwise multiply the instances without end.
        if (++visits_ > max_node_instances) {
            gltf_fail(path_, where, "more than " + std::to_string(max_node_instances) + " node instances in the scene");
        }
        const json& node = nodes[static_cast<std::size_t>(index)];
        if (!node.is_object()) gltf_fail(path_, where, "expected an object");
        const glm::dmat4 world = parent * local_transform(node, where, path_);
        const std::int64_t mesh = gltf_integer(node, "mesh", where, path_);
        if (mesh >= 0) add_mesh(mesh, world);
        for (const json& c : gltf_array(node, "children")) {
            if (!c.is_number_integer()) gltf_fail(path_, where + "/children", "expected node indices");
            visit(c.get<std::int64_t>(), world, depth + 1);
        }
    }

    void add_mesh(std::int64_t index, const glm::dmat4& world) {
        const json& meshes = gltf_array(document_, "meshes");
        const std::string where = "/meshes/" + std::to_string(index);
        if (static_cast<std::size_t>(index) >= meshes.size()) gltf_fail(path_, where, "no such mesh");
        const json& primitives = gltf_array(meshes[static_cast<std::size_t>(index)], "primitives");
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            add_primitive(primitives[p], world, where + "/primitives/" + std::to_string(p));
        }
    }

    void add_primitive(const json& primitive, const glm::dmat4& world, const std::string& where);

    const json& document_;
    const GltfAccessors& accessors_;
    const std::string& path_;
    static constexpr std::size_t max_node_instances = 100000;
    MeshFile file_;
    GltfMaterials materials_;
    bool any_normals_ = false;
    bool any_texcoords_ = false;
    std::size_t visits_ = 0;
    bool warned_mode_ = false;
};

void GltfScene::add_primitive(const json& primitive, const glm::dmat4& world, const std::string& where) {
    const std::int64_t mode = gltf_integer(primitive, "mode", where, path_, 4);
    if (mode < 4 || mode > 6) {  // points and lines have no surface to shade
        if (!warned_mode_) file_.warnings.push_back(path_ + ": " + where + ": points or lines (mode " + std::to_string(mode) + ") skipped");
        warned_mode_ = true;
        return;
    }
    const json& attributes = gltf_object(primitive, "attributes");
    const std::int64_t position = gltf_integer(attributes, "POSITION", where + "/attributes", path_);
    if (position < 0) gltf_fail(path_, where + "/attributes", "missing POSITION; expected a VEC3 float accessor");
    const std::vector<glm::dvec3> positions = accessors_.positions(position);
    const std::int64_t color = gltf_integer(attributes, "COLOR_0", where + "/attributes", path_);
    std::vector<glm::vec3> colors = color >= 0 ? accessors_.colors(color) : std::vector<glm::vec3>(positions.size(), glm::vec3(1.0f));
    if (colors.size() != positions.size()) gltf_fail(path_, where + "/attributes/COLOR_0", "expected one colour per position");
    const GltfMaterials::Use material = materials_.use(primitive, where, file_.mesh.materials);
    const std::int64_t normal = gltf_integer(attributes, "NORMAL", where + "/attributes", path_);
    const std::vector<glm::vec3> normals = normal >= 0 ? accessors_.normals(normal) : std::vector<glm::vec3>();
    if (normal >= 0 && normals.size() != positions.size()) gltf_fail(path_, where + "/attributes/NORMAL", "expected one normal per position");
    // The texture's set, else TEXCOORD_0 (for the uv output of untextured faces).
    const std::string texcoord_name = "TEXCOORD_" + std::to_string(material.texcoord_set);
    const std::int64_t texcoord = gltf_integer(attributes, texcoord_name.c_str(), where + "/attributes", path_);
    const std::vector<glm::vec2> texcoords = texcoord >= 0 ? accessors_.texcoords(texcoord) : std::vector<glm::vec2>();
    if (texcoord >= 0 && texcoords.size() != positions.size()) {
        gltf_fail(path_, where + "/attributes/" + texcoord_name, "expected one texture coordinate per position");
    }
    std::vector<std::uint32_t> indices;
    const std::int64_t index_accessor = gltf_integer(primitive, "indices", where, path_);
    if (index_accessor >= 0) {
        indices = accessors_.indices(index_accessor);
    } else {
        indices.resize(positions.size());
        for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= positions.size()) {
            gltf_fail(path_, "/accessors/" + std::to_string(index_accessor), "index " + std::to_string(i) + " is " +
                      std::to_string(indices[i]) + ", out of range: POSITION has " + std::to_string(positions.size()) + " elements");
        }
    }
    Mesh& mesh = file_.mesh;
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    // Room for this primitive, growing geometrically: an exact reserve per
    // primitive would copy the whole mesh again for every instance.
    const auto make_room = [](auto& items, std::size_t more) {
        if (items.capacity() < items.size() + more) items.reserve(std::max(2 * items.capacity(), items.size() + more));
    };
    make_room(mesh.positions, positions.size());
    make_room(mesh.colors, positions.size());
    make_room(mesh.triangles, indices.size() / 3);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3 p = glm::dvec3(world * glm::dvec4(positions[i], 1.0));
        if (!std::isfinite(p.x + p.y + p.z)) gltf_fail(path_, where, "a transformed position is not finite");
        mesh.positions.push_back(p);
        mesh.colors.push_back(colors[i]);
    }
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    const auto normal_base = static_cast<std::uint32_t>(mesh.file_normals.size());
    if (!normals.empty()) {
        // The inverse transpose of the node matrix, as its cofactor matrix (the
        // same direction, defined for a singular matrix too) with the
        // determinant's sign, so that mirrored normals stay outward.
        const glm::dmat3 m(world);
        const glm::dmat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
        const double sign = mirrored ? -1.0 : 1.0;
        make_room(mesh.file_normals, normals.size());
        for (const glm::vec3& n : normals) {
            const glm::dvec3 world_normal = sign * (cofactor * glm::dvec3(n));
            const double length = glm::length(world_normal);
            // Zero stays zero: the contract's "take the computed normal".
            mesh.file_normals.push_back(length > 0.0 && std::isfinite(length) ? glm::vec3(world_normal / length)
                                                                              : glm::vec3(0.0f));
        }
        any_normals_ = true;
    }
    const auto texcoord_base = static_cast<std::uint32_t>(mesh.texcoords.size());
    if (!texcoords.empty()) {
        make_room(mesh.texcoords, texcoords.size());
        for (const glm::vec2& uv : texcoords) mesh.texcoords.emplace_back(uv.x, 1.0f - uv.y);  // glTF's v = 0 is the top row
        any_texcoords_ = true;
    }
    // The per-triangle lists are kept from the first primitive that has such
    // an attribute on, padded with kNoIndex for the triangles before it.
    const std::size_t triangles_before = mesh.triangles.size();
    const bool keep_normals = any_normals_;
    const bool keep_texcoords = any_texcoords_;
    const bool keep_materials = !mesh.materials.empty();
    if (keep_normals) mesh.file_normal_triangles.resize(triangles_before, Triangle{kNoIndex, kNoIndex, kNoIndex});
    if (keep_texcoords) mesh.texcoord_triangles.resize(triangles_before, Triangle{kNoIndex, kNoIndex, kNoIndex});
    if (keep_materials) mesh.face_materials.resize(triangles_before, kNoIndex);
    // A mirroring transform turns the winding around; undo it so normals stay
    // outward (the corners' normals and texture coordinates follow their corners).
    const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (mirrored) std::swap(b, c);
        mesh.triangles.push_back({base + a, base + b, base + c});
        if (keep_normals) {
            mesh.file_normal_triangles.push_back(normals.empty() ? Triangle{kNoIndex, kNoIndex, kNoIndex}
                                                                 : Triangle{normal_base + a, normal_base + b, normal_base + c});
        }
        if (keep_texcoords) {
            mesh.texcoord_triangles.push_back(texcoords.empty()
                                                  ? Triangle{kNoIndex, kNoIndex, kNoIndex}
                                                  : Triangle{texcoord_base + a, texcoord_base + b, texcoord_base + c});
        }
        if (keep_materials) mesh.face_materials.push_back(material.slot);
    };
    const std::size_t n = indices.size();
    if (mode == 4) {
        for (std::size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
    } else if (mode == 5) {  // strip: every other triangle reversed
        for (std::size_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0) add(indices[i], indices[i + 1], indices[i + 2]);
            else add(indices[i + 1], indices[i], indices[i + 2]);
        }
    } else {  // fan
        for (std::size_t i = 1; i + 1 < n; ++i) add(indices[0], indices[i], indices[i + 1]);
    }
}

/// The file's buffers: the GLB's BIN chunk, base64 data: URIs, or files next
/// to `path` (their names appended to `file_names`).
std::vector<std::string_view> load_buffers(const json& document, std::string_view bin, const std::string& path,
                                           std::vector<std::string>& decoded, std::vector<FileBytes>& files,
                                           std::vector<std::string>& file_names) {
    const json& buffers = gltf_array(document, "buffers");
    std::vector<std::string_view> views;
    decoded.reserve(buffers.size());
    files.reserve(buffers.size());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const std::string where = "/buffers/" + std::to_string(i);
        const json& uri_value = buffers[i].is_object() && buffers[i].contains("uri") ? buffers[i]["uri"] : json("");
        if (!uri_value.is_string()) gltf_fail(path, where + "/uri", "expected a string");
        const std::string uri = uri_value.get<std::string>();
        std::string_view data = bin;
        if (uri.rfind("data:", 0) == 0) {
            decoded.push_back(decode_data_uri(uri, path, where + "/uri"));
            data = decoded.back();
        } else if (!uri.empty()) {
            const std::filesystem::path folder = std::filesystem::path(path).parent_path();
            file_names.push_back((folder / uri).string());
            files.push_back(FileBytes::read(file_names.back(), "buffer"));
            data = files.back().view();
        }
        const auto length = static_cast<std::uint64_t>(gltf_integer(buffers[i], "byteLength", where, path, 0));
        if (length > data.size()) {
            gltf_fail(path, where + "/byteLength", std::to_string(length) + " bytes declared, only " +
                                                      std::to_string(data.size()) + " present (a truncated file?)");
        }
        views.push_back(data.substr(0, length));
    }
    return views;
}

}  // namespace

static MeshFile parse_gltf_document(std::string_view bytes, const std::string& path) {
    const bool binary = bytes.substr(0, 4) == "glTF";
    std::string_view text = bytes;
    std::string_view bin;
    if (binary) std::tie(text, bin) = split_glb(bytes, path);
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& error) {
        throw FileError(path + ": malformed glTF JSON at byte " + std::to_string(error.byte) + " of the JSON" +
                        (binary ? " chunk" : "") + ": expected a glTF 2.0 document");
    }
    if (!document.is_object()) throw FileError(path + ": expected a glTF JSON object");
    const json& version_value = gltf_object(document, "asset").contains("version") ? document["asset"]["version"] : json();
    const std::string version = version_value.is_string() ? version_value.get<std::string>() : version_value.dump();
    if (version.rfind("2.", 0) != 0) gltf_fail(path, "/asset/version", "'" + version + "'; expected 2.0");
    for (const json& extension : gltf_array(document, "extensionsRequired")) {
        gltf_fail(path, "/extensionsRequired", "requires " + extension.dump() + ", which phongrast does not support");
    }
    std::vector<std::string> decoded;
    std::vector<FileBytes> files;
    std::vector<std::string> buffer_files;
    const GltfAccessors accessors(document, load_buffers(document, bin, path, decoded, files, buffer_files), path);
    MeshFile file = GltfScene(document, accessors, path).read();
    file.side_files.insert(file.side_files.begin(), buffer_files.begin(), buffer_files.end());
    if (file.mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) throw FileError(path + ": too many vertices");
    check_mesh(file.mesh, path);
    return file;
}

MeshFile parse_gltf(std::string_view bytes, const std::string& path) {
    try {
        return parse_gltf_document(bytes, path);
    } catch (const nlohmann::json::exception& error) {  // a member of a type the checks did not expect
        throw FileError(path + ": unexpected glTF structure: " + error.what());
    }
}

}  // namespace phongrast::io
