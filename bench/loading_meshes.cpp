#include "loading_meshes.hpp"

#include <cmath>
#include <filesystem>

#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"

namespace phongrast_bench {

phongrast::Mesh loading_sphere(std::size_t triangles) {
    // 2 x slices x (stacks - 1) triangles with slices = 2 x stacks.
    const int stacks = std::max(2, static_cast<int>(std::lround(std::sqrt(double(triangles) / 4.0))));
    const int slices = 2 * stacks;
    const double pi = 3.14159265358979323846;
    phongrast::Mesh mesh;
    mesh.positions.push_back({0, 1, 0});
    for (int i = 1; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const double theta = pi * i / stacks;
            const double phi = 2 * pi * j / slices;
            mesh.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    }
    mesh.positions.push_back({0, -1, 0});
    for (const glm::dvec3& p : mesh.positions) mesh.colors.emplace_back(glm::vec3(0.5 + 0.5 * p));
    const auto ring = [slices](int i, int j) { return std::uint32_t(1 + (i - 1) * slices + (j % slices)); };
    const auto bottom = std::uint32_t(mesh.positions.size() - 1);
    for (int j = 0; j < slices; ++j) {
        mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < stacks; ++i) {
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        mesh.triangles.push_back({ring(stacks - 1, j), bottom, ring(stacks - 1, j + 1)});
    }
    return mesh;
}

std::vector<LoadingFile> write_loading_files(const phongrast::Mesh& mesh, const std::string& folder,
                                             const std::string& stem) {
    namespace io = phongrast::io;
    std::filesystem::create_directories(folder);
    const std::string base = (std::filesystem::path(folder) / stem).string();
    std::vector<LoadingFile> files = {{"obj", base + ".obj"},
                                      {"ply-ascii", base + "-ascii.ply"},
                                      {"ply-binary", base + "-binary.ply"},
                                      {"stl-binary", base + ".stl"},
                                      {"glb", base + ".glb"}};
    for (LoadingFile& file : files) {
        std::error_code missing;
        if (std::filesystem::file_size(file.path, missing) == 0 || missing) {
            if (file.format == "obj") io::write_obj(mesh, file.path);
            if (file.format == "ply-ascii") io::write_ply(mesh, file.path, io::PlyEncoding::ascii);
            if (file.format == "ply-binary") io::write_ply(mesh, file.path, io::PlyEncoding::binary_little_endian);
            if (file.format == "stl-binary") io::write_stl(mesh, file.path, true);
            if (file.format == "glb") io::write_glb(mesh, file.path);
        }
        file.bytes = std::filesystem::file_size(file.path);
        file.triangles = mesh.triangles.size();
    }
    return files;
}

}  // namespace phongrast_bench
