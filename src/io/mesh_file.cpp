#include "phongrast/io/mesh_file.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "file_bytes.hpp"
#include "mesh_readers.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

std::string lower_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

bool starts_with(const char* bytes, std::size_t size, const char* prefix) {
    const std::size_t length = std::strlen(prefix);
    return size >= length && std::memcmp(bytes, prefix, length) == 0;
}

/// A binary STL's size is exactly 84 + 50 x its triangle count.
bool looks_like_binary_stl(const char* bytes, std::size_t size) {
    if (size < 84) return false;
    std::uint32_t count = 0;
    std::memcpy(&count, bytes + 80, 4);  // little endian, as the format says (and x86)
    return 84 + 50 * std::uint64_t(count) == size;
}

/// "solid" then, within the first KB, "facet": ASCII STL (a binary STL's
/// 80-byte header may begin with "solid" too, hence the second word).
bool looks_like_ascii_stl(const char* bytes, std::size_t size) {
    std::size_t start = 0;
    while (start < size && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
    if (!starts_with(bytes + start, size - start, "solid")) return false;
    const std::string_view head(bytes, std::min<std::size_t>(size, 1024));
    return head.find("facet") != std::string_view::npos || head.find("endsolid") != std::string_view::npos;
}

}  // namespace

const char* to_string(MeshFormat format) {
    switch (format) {
        case MeshFormat::obj: return "OBJ";
        case MeshFormat::ply: return "PLY";
        case MeshFormat::stl: return "STL";
        case MeshFormat::gltf: return "glTF";
    }
    return "unknown";
}

bool has_mesh_extension(const std::string& path) {
    const std::string extension = lower_extension(path);
    return extension == ".obj" || extension == ".ply" || extension == ".stl" || extension == ".gltf" ||
           extension == ".glb";
}

MeshFormat detect_mesh_format(const std::string& path, const char* bytes, std::size_t size) {
    // Content first, where it is unambiguous: an extension may lie.
    if (starts_with(bytes, size, "glTF")) return MeshFormat::gltf;
    if (starts_with(bytes, size, "ply\n") || starts_with(bytes, size, "ply\r")) return MeshFormat::ply;
    if (looks_like_ascii_stl(bytes, size) || looks_like_binary_stl(bytes, size)) return MeshFormat::stl;
    const std::string extension = lower_extension(path);
    if (extension == ".obj") return MeshFormat::obj;
    if (extension == ".ply") return MeshFormat::ply;
    if (extension == ".stl") return MeshFormat::stl;
    if (extension == ".gltf" || extension == ".glb") return MeshFormat::gltf;
    throw FileError(path + ": unknown mesh format (extension '" + extension +
                    "'); expected .obj, .ply, .stl, .gltf or .glb, or a file that starts like one");
}

MeshFile read_mesh(const std::string& path) {
    const FileBytes bytes = FileBytes::read(path, "mesh");
    switch (detect_mesh_format(path, bytes.data(), bytes.size())) {
        case MeshFormat::obj: return parse_obj(bytes.view(), path);
        case MeshFormat::ply: return parse_ply(bytes.view(), path);
        case MeshFormat::stl: return parse_stl(bytes.view(), path);
        case MeshFormat::gltf: return parse_gltf(bytes.view(), path);
    }
    throw FileError(path + ": unknown mesh format");
}

MeshFile read_ply(const std::string& path) { return parse_ply(FileBytes::read(path, "mesh").view(), path); }
MeshFile read_stl(const std::string& path) { return parse_stl(FileBytes::read(path, "mesh").view(), path); }
MeshFile read_gltf(const std::string& path) { return parse_gltf(FileBytes::read(path, "mesh").view(), path); }

void warn_textured_faces_without_texcoords(MeshFile& file, const std::string& path) {
    const Mesh& mesh = file.mesh;
    if (mesh.face_materials.empty()) return;
    std::size_t without = 0;
    std::string example;
    for (std::size_t t = 0; t < mesh.face_materials.size(); ++t) {
        const std::uint32_t material = mesh.face_materials[t];
        if (material == kNoIndex || !mesh.materials[material].texture) continue;
        const bool has = t < mesh.texcoord_triangles.size() && mesh.texcoord_triangles[t][0] != kNoIndex &&
                         mesh.texcoord_triangles[t][1] != kNoIndex && mesh.texcoord_triangles[t][2] != kNoIndex;
        if (has) continue;
        if (without++ == 0) example = mesh.materials[material].name;
    }
    if (without > 0) {
        file.warnings.push_back(path + ": " + std::to_string(without) + " triangle" + (without == 1 ? "" : "s") +
                                " with a textured material (" + example +
                                ") have no texture coordinates; they draw with T = 1");
    }
}

void check_mesh(const Mesh& mesh, const std::string& path) {
    try {
        validate_mesh(mesh);  // the core's own check: a last guard, each reader checks first
    } catch (const std::invalid_argument& error) {
        throw FileError(path + ": " + error.what());
    }
}

}  // namespace phongrast::io
