#include "loading_meshes.hpp"

#include <cmath>
#include <filesystem>

#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "support/meshes.hpp"

namespace phongrast_bench {

phongrast::Mesh loading_sphere(std::size_t triangles) {
    // 2 x slices x (stacks - 1) triangles with slices = 2 x stacks.
    const int stacks = std::max(2, static_cast<int>(std::lround(std::sqrt(double(triangles) / 4.0))));
    phongrast::Mesh mesh = phongrast::support::uv_sphere(stacks, 2 * stacks, 1.0);
    for (const glm::dvec3& p : mesh.positions) mesh.colors.emplace_back(glm::vec3(0.5 + 0.5 * p));
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
