// Shared by the fuzz targets: a scratch file writer, a small, bounded render,
// and the loop body of the mesh-reader targets.
#ifndef PHONGRAST_FUZZ_COMMON_HPP
#define PHONGRAST_FUZZ_COMMON_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <stdexcept>

#include <unistd.h>

#include "phongrast/io/error.hpp"
#include "phongrast/render.hpp"

namespace phongrast_fuzz {

inline bool write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr) return false;
    const bool ok = std::fwrite(data, 1, size, file) == size;
    return std::fclose(file) == 0 && ok;
}

inline phongrast::Mesh tetrahedron() {
    phongrast::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

/// Renders `mesh` (in `scene`, or a default scene looking at the mesh) at most
/// 24 x 24 pixels and 20000 triangles, so one input stays fast, and aborts on
/// a non-finite pixel: the renderer promises there is none.
inline void render_small(const phongrast::Mesh& mesh, const phongrast::Scene* given = nullptr) {
    phongrast::Scene scene;
    if (given != nullptr) {
        scene = *given;
    } else {
        scene.camera.eye = {0.3, 0.4, 5};
        scene.lights = {{{2, 3, 4}, {1, 1, 1}}};
    }
    if (mesh.triangles.size() > 20000) return;
    scene.mesh = mesh;
    scene.image.rows = std::clamp(scene.image.rows, 1, 24);
    scene.image.columns = std::clamp(scene.image.columns, 1, 24);
    for (const phongrast::RenderOptions& options : {phongrast::RenderOptions::seed(), phongrast::RenderOptions::exact()}) {
        phongrast::RenderOptions bounded = options;
        bounded.threads = 1;
        const phongrast::RenderResult result = phongrast::render(scene, bounded);
        for (const glm::vec3& p : result.image.pixels) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
        }
        if (result.stats.nonfinite_values_replaced != 0) std::abort();
    }
}

/// One input to a mesh reader that takes a path: written to a scratch file
/// (one per fuzzing process, ending in `extension`), read, and rendered small.
/// A clear error (FileError, or std::invalid_argument from validation) is the
/// expected answer to bad input; anything else -- a crash, a sanitizer report,
/// another exception type, a non-finite pixel -- is a finding.
template <class Reader>
int fuzz_mesh_reader(const std::uint8_t* data, std::size_t size, const char* extension, Reader read) {
    // The process id zero-padded to a fixed width: error messages quote the
    // path, and a path of another length would take other branches in the
    // string code, so the same seed would fuzz other inputs on another run.
    static const std::string path = [extension] {
        char pid[16];
        std::snprintf(pid, sizeof pid, "%010ld", static_cast<long>(getpid()));
        return "/tmp/phongrast_fuzz_" + std::string(pid) + "_" + std::string(extension + 1) + std::string(extension);
    }();
    if (!write_file(path, data, size)) return 0;
    try {
        render_small(read(path).mesh);
    } catch (const phongrast::io::FileError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}

}  // namespace phongrast_fuzz

#endif  // PHONGRAST_FUZZ_COMMON_HPP
