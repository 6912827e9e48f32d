// The meshes the effect benchmark runs on: generated ones always, the shared
// OBJ meshes and the project's default scene when they can be loaded.
#ifndef PHONGRAST_BENCH_BENCH_MESHES_HPP
#define PHONGRAST_BENCH_BENCH_MESHES_HPP

#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast_bench {

struct BenchMesh {
    std::string name;
    phongrast::Scene scene;     ///< framed, two lights, full lighting, Phong
    bool culling_only = false;  ///< only the culling comparison is run on it
    bool own_lights = false;    ///< the effect table keeps the scene's lights (a scene file's)
};

/// Built once, on first call. Rendered at kImageSize x kImageSize unless the
/// mesh comes with its own scene file.
const std::vector<BenchMesh>& bench_meshes();
/// Why a mesh is missing (no assets folder, file not found, ...), for stderr.
const std::vector<std::string>& bench_mesh_notes();

constexpr int kImageSize = 512;

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_BENCH_MESHES_HPP
