// write_ply, write_stl, write_glb: plain, exact (where the format allows)
// encodings of a Mesh, each to a temporary file renamed into place.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "phongrast/io/error.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/text_file.hpp"

namespace phongrast::io {
namespace {

/// Appends `value`'s bytes, reversed for a big-endian file.
template <class T>
void put(std::string& out, T value, bool big_endian = false) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big_endian) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

void write_bytes(const std::string& path, const std::string& bytes) {
    replace_file_atomically(path, [&](const std::string& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (file == nullptr) throw FileError(path + ": cannot write: " + std::strerror(errno));
        const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
        if (std::fclose(file) != 0 || !written) throw FileError(path + ": write failed: " + std::strerror(errno));
    });
}

/// The writers read positions through the triangles' indices (STL, glTF
/// bounds) or write them for a reader to follow: an index past the vertices
/// is the caller's mistake, refused before anything is written.
void require_valid_indices(const Mesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::size_t corner = 0; corner < 3; ++corner) {
            if (mesh.triangles[t][corner] >= mesh.positions.size()) {
                throw std::out_of_range("mesh.triangles[" + std::to_string(t) + "][" + std::to_string(corner) +
                                        "] = " + std::to_string(mesh.triangles[t][corner]) +
                                        ": expected a vertex index below mesh.positions.size() = " +
                                        std::to_string(mesh.positions.size()));
            }
        }
    }
}

glm::vec3 facet_normal(const Mesh& mesh, const Triangle& t) {
    const glm::dvec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    const double length = glm::length(n);
    return length > 0.0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0.0f);
}

}  // namespace

void write_ply(const Mesh& mesh, const std::string& path, PlyEncoding encoding) {
    require_valid_indices(mesh);
    const bool colored = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
    const bool big = encoding == PlyEncoding::binary_big_endian;
    std::string out = "ply\nformat ";
    out += encoding == PlyEncoding::ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
    out += " 1.0\nelement vertex " + std::to_string(mesh.positions.size()) +
           "\nproperty double x\nproperty double y\nproperty double z\n";
    if (colored) out += "property float red\nproperty float green\nproperty float blue\n";
    out += "element face " + std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    char line[160];
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3& p = mesh.positions[i];
        if (encoding == PlyEncoding::ascii) {
            int n = std::snprintf(line, sizeof line, "%.17g %.17g %.17g", p.x, p.y, p.z);
            if (colored) {
                const glm::vec3& c = mesh.colors[i];
                n += std::snprintf(line + n, sizeof line - n, " %.9g %.9g %.9g", double(c.r), double(c.g), double(c.b));
            }
            out.append(line, static_cast<std::size_t>(n)).push_back('\n');
            continue;
        }
        for (int k = 0; k < 3; ++k) put(out, p[k], big);
        if (colored) {
            for (int k = 0; k < 3; ++k) put(out, mesh.colors[i][k], big);
        }
    }
    for (const Triangle& t : mesh.triangles) {
        if (encoding == PlyEncoding::ascii) {
            out.append(line, static_cast<std::size_t>(std::snprintf(line, sizeof line, "3 %u %u %u\n", t[0], t[1], t[2])));
            continue;
        }
        put(out, std::uint8_t{3});
        for (int k = 0; k < 3; ++k) put(out, static_cast<std::int32_t>(t[static_cast<std::size_t>(k)]), big);
    }
    write_bytes(path, out);
}

void write_stl(const Mesh& mesh, const std::string& path, bool binary) {
    require_valid_indices(mesh);
    std::string out;
    if (binary) {
        out.assign(80, ' ');
        out.replace(0, 25, "binary STL from phongrast");
        put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    } else {
        out = "solid phongrast\n";
    }
    char line[200];
    for (const Triangle& t : mesh.triangles) {
        const glm::vec3 n = facet_normal(mesh, t);
        if (binary) {
            for (int k = 0; k < 3; ++k) put(out, n[k]);
            for (const std::uint32_t v : t) {
                for (int k = 0; k < 3; ++k) put(out, static_cast<float>(mesh.positions[v][k]));
            }
            put(out, std::uint16_t{0});
            continue;
        }
        out.append(line, static_cast<std::size_t>(std::snprintf(line, sizeof line, "facet normal %.9g %.9g %.9g\n outer loop\n",
                                                                 double(n.x), double(n.y), double(n.z))));
        for (const std::uint32_t v : t) {
            const glm::vec3 p(mesh.positions[v]);
            // 17 digits: the float's exact value, which a reader parsing decimals as double gets back.
            out.append(line, static_cast<std::size_t>(std::snprintf(line, sizeof line, "  vertex %.17g %.17g %.17g\n",
                                                                     double(p.x), double(p.y), double(p.z))));
        }
        out += " endloop\nendfacet\n";
    }
    if (!binary) out += "endsolid phongrast\n";
    write_bytes(path, out);
}

void write_glb(const Mesh& mesh, const std::string& path) {
    require_valid_indices(mesh);
    const bool colored = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
    std::string bin;
    glm::vec3 low(0.0f), high(0.0f);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p(mesh.positions[i]);
        low = i == 0 ? p : glm::min(low, p);
        high = i == 0 ? p : glm::max(high, p);
        for (int k = 0; k < 3; ++k) put(bin, p[k]);
    }
    const std::size_t position_bytes = bin.size();
    if (colored) {
        for (const glm::vec3& c : mesh.colors) {
            for (int k = 0; k < 3; ++k) put(bin, c[k]);
        }
    }
    const std::size_t index_offset = bin.size();
    for (const Triangle& t : mesh.triangles) {
        for (const std::uint32_t v : t) put(bin, v);
    }
    using nlohmann::json;
    json attributes = {{"POSITION", 0}};
    json accessors = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", mesh.positions.size()}, {"type", "VEC3"},
                                   {"min", {low.x, low.y, low.z}}, {"max", {high.x, high.y, high.z}}},
                                  {{"bufferView", 1}, {"componentType", 5125}, {"count", 3 * mesh.triangles.size()}, {"type", "SCALAR"}}});
    json views = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", position_bytes}},
                              {{"buffer", 0}, {"byteOffset", index_offset}, {"byteLength", bin.size() - index_offset}}});
    if (colored) {
        attributes["COLOR_0"] = 2;
        accessors.push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", mesh.positions.size()}, {"type", "VEC3"}});
        views.push_back({{"buffer", 0}, {"byteOffset", position_bytes}, {"byteLength", index_offset - position_bytes}});
    }
    const json document = {{"asset", {{"version", "2.0"}, {"generator", "phongrast"}}},
                           {"scene", 0}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", {{{"mesh", 0}}}},
                           {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", 1}}}}}}},
                           {"accessors", accessors}, {"bufferViews", views},
                           {"buffers", {{{"byteLength", bin.size()}}}}};
    std::string text = document.dump();
    text.append((4 - text.size() % 4) % 4, ' ');  // chunks are 4-byte aligned
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out = "glTF";
    put(out, std::uint32_t{2});
    put(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    put(out, static_cast<std::uint32_t>(text.size()));
    put(out, std::uint32_t{0x4E4F534A});
    out += text;
    put(out, static_cast<std::uint32_t>(bin.size()));
    put(out, std::uint32_t{0x004E4942});
    out += bin;
    write_bytes(path, out);
}

}  // namespace phongrast::io
