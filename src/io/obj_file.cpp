#include "phongrast/io/obj_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "obj_check.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/text_file.hpp"
#include "tiny_obj_loader_double.hpp"

namespace phongrast::io {
namespace {

std::string read_whole_file(const std::string& path, const char* what) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
        throw FileError(path + ": " + what + " not found (no such file)");
    }
    if (std::filesystem::is_directory(path, error)) {
        throw FileError(path + ": is a folder; expected " + std::string(what) + " file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path + ": cannot read " + what + ": " + std::strerror(errno));
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) throw FileError(path + ": cannot read " + what + ": " + std::strerror(errno));
    return contents.str();
}

std::vector<std::string> split_warning_lines(const std::string& path, const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty()) lines.push_back(path + ": " + line);
    }
    return lines;
}

glm::vec3 to_vec3(const tinyobj::real_t (&values)[3]) {
    return {static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2])};
}

PhongMaterial to_phong(const tinyobj::material_t& material) {
    PhongMaterial phong;
    phong.ka = to_vec3(material.ambient);
    phong.kd = to_vec3(material.diffuse);
    phong.ks = to_vec3(material.specular);
    phong.n = static_cast<float>(material.shininess);
    return phong;
}

// Each face as a fan (v0 v_k v_k+1, the contract's order); the material of the
// first face that names one.
void add_faces(const std::vector<tinyobj::shape_t>& shapes, const std::vector<tinyobj::material_t>& materials,
               ObjFile& result) {
    Mesh& mesh = result.mesh;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t corner = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            const std::size_t corners = shape.mesh.num_face_vertices[face];
            auto vertex = [&](std::size_t k) {
                return static_cast<std::uint32_t>(shape.mesh.indices[corner + k].vertex_index);
            };
            for (std::size_t k = 1; k + 1 < corners; ++k) {  // fan: v0 v_k v_k+1
                mesh.triangles.push_back({vertex(0), vertex(k), vertex(k + 1)});
            }
            if (!result.material && face < shape.mesh.material_ids.size()) {
                const int id = shape.mesh.material_ids[face];
                if (id >= 0 && static_cast<std::size_t>(id) < materials.size()) {
                    result.material = to_phong(materials[static_cast<std::size_t>(id)]);
                    result.material_name = materials[static_cast<std::size_t>(id)].name;
                }
            }
            corner += corners;
        }
    }
}

}  // namespace

ObjFile read_obj(const std::string& path) {
    const std::string text = read_whole_file(path, "mesh");
    std::vector<glm::dvec3> exact_positions = check_obj_text(text, path);

    tinyobj::attrib_t attributes;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings;
    std::string errors;
    std::istringstream stream(text);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    tinyobj::MaterialFileReader material_reader(folder.empty() ? std::string("./") : folder.string() + "/");
    // triangulate = false: phongrast does the contract's fan itself (tinyobjloader
    // may split quads along the other diagonal).
    const bool loaded = tinyobj::LoadObj(&attributes, &shapes, &materials, &warnings, &errors, &stream,
                                         &material_reader, /*triangulate=*/false,
                                         /*default_vcols_fallback=*/true);
    if (!loaded || !errors.empty()) {
        throw FileError(path + ": cannot parse OBJ: " + (errors.empty() ? std::string("unknown error") : errors));
    }

    ObjFile result;
    result.warnings = split_warning_lines(path, warnings);
    Mesh& mesh = result.mesh;
    const std::size_t vertex_count = attributes.vertices.size() / 3;
    if (exact_positions.size() != vertex_count) {
        throw FileError(path + ": tinyobjloader read " + std::to_string(vertex_count) + " vertices, expected " +
                        std::to_string(exact_positions.size()) + " (one per 'v' line)");
    }
    // The same numbers tinyobjloader read, but correctly rounded (see check_obj_text).
    mesh.positions = std::move(exact_positions);
    // With default_vcols_fallback tinyobjloader gives every vertex a colour,
    // white (1, 1, 1) where the file has none, exactly the contract's default.
    if (attributes.colors.size() == attributes.vertices.size()) {
        mesh.colors.reserve(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i) {
            mesh.colors.emplace_back(static_cast<float>(attributes.colors[3 * i]),
                                     static_cast<float>(attributes.colors[3 * i + 1]),
                                     static_cast<float>(attributes.colors[3 * i + 2]));
        }
    }

    add_faces(shapes, materials, result);
    try {
        validate_mesh(mesh);  // the core's own check: a last guard, the pre-check should catch everything
    } catch (const std::invalid_argument& error) {
        throw FileError(path + ": " + error.what());
    }
    return result;
}

void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment,
               int significant_digits) {
    replace_file_atomically(path, [&](const std::string& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) throw FileError(path + ": cannot write: " + std::strerror(errno));
        std::istringstream comment_lines(comment);
        std::string line;
        while (std::getline(comment_lines, line)) std::fprintf(file, "# %s\n", line.c_str());
        const bool colored = mesh.colors.size() == mesh.positions.size();
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3& p = mesh.positions[i];
            if (colored) {
                const glm::vec3& c = mesh.colors[i];
                std::fprintf(file, "v %.*g %.*g %.*g %.4f %.4f %.4f\n", significant_digits, p.x,
                             significant_digits, p.y, significant_digits, p.z, double(c.r), double(c.g),
                             double(c.b));
            } else {
                std::fprintf(file, "v %.*g %.*g %.*g\n", significant_digits, p.x, significant_digits, p.y,
                             significant_digits, p.z);
            }
        }
        for (const Triangle& t : mesh.triangles) {
            std::fprintf(file, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        }
        const bool failed = std::ferror(file) != 0;
        if (std::fclose(file) != 0 || failed) throw FileError(path + ": write failed: " + std::strerror(errno));
    });
}

}  // namespace phongrast::io
