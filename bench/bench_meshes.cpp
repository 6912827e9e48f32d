#include "bench_meshes.hpp"

#include "bench_scenes.hpp"

namespace phongrast_bench {
namespace {

struct Catalogue {
    std::vector<BenchMesh> meshes;
    std::vector<std::string> notes;
};

Catalogue build_catalogue() {
    Catalogue c;
    // 1,280 triangles of ~90 pixels each: the time goes into filling and shading.
    c.meshes.push_back({"icosphere-1k", framed_scene(icosphere(3), kImageSize, kImageSize), false});
    // 81,920 triangles, like the shared meshes' 70k-86k: ~1.5 pixels each, so
    // per-triangle setup weighs as much as per-pixel shading.
    c.meshes.push_back({"icosphere-82k", framed_scene(icosphere(6), kImageSize, kImageSize), false});
    // Seen from above at an angle: some inner back faces are painted over front faces.
    c.meshes.push_back({"torus", framed_scene(torus(256, 128, 1.0, 0.4), kImageSize, kImageSize), true});
    return c;
}

const Catalogue& catalogue() {
    static const Catalogue instance = build_catalogue();
    return instance;
}

}  // namespace

const std::vector<BenchMesh>& bench_meshes() { return catalogue().meshes; }
const std::vector<std::string>& bench_mesh_notes() { return catalogue().notes; }

}  // namespace phongrast_bench
