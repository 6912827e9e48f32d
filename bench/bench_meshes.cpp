#include "bench_meshes.hpp"

#include <exception>
#include <filesystem>
#include <utility>

#include "bench_scenes.hpp"
#include "support/meshes.hpp"
#include "support/shared_scenes.hpp"

namespace phongrast_bench {
namespace {

namespace support = phongrast::support;

struct Catalogue {
    std::vector<BenchMesh> meshes;
    std::vector<std::string> notes;
};

// The project's default scene as the app renders it (its camera, image, material
// and lights); the benchmark then varies lighting, shader and lights.
void add_default_scene(Catalogue& c) {
    const std::filesystem::path path = std::filesystem::path(PHONGRAST_PROJECT_ASSETS_DIR) / "default.json";
    try {
        c.meshes.push_back({"default", support::read_scene_with_mesh(path.string()), false, true});
    } catch (const std::exception& error) {
        c.notes.push_back("skipping the default scene: " + std::string(error.what()));
    }
}

Catalogue build_catalogue() {
    Catalogue c;
    // 1,280 triangles of ~90 pixels each: the time goes into filling and shading.
    c.meshes.push_back({"icosphere-1k", effect_scene(support::icosphere(8), kImageSize, kImageSize), false, false});
    // 81,920 triangles, like the shared meshes' 70k-86k: ~1.5 pixels each, so
    // per-triangle setup weighs as much as per-pixel shading.
    c.meshes.push_back({"icosphere-82k", effect_scene(support::icosphere(64), kImageSize, kImageSize), false, false});
    // Tilted toward the eye, seen from above at an angle: some inner back faces are painted over front faces.
    phongrast::Mesh ring = support::rotated_about_x(support::torus(256, 128, 1.0, 0.4), 30.0);
    support::color_by_position(ring);
    c.meshes.push_back({"torus", effect_scene(std::move(ring), kImageSize, kImageSize), true, false});
    add_default_scene(c);
    // spot is closed (and faces -z); the bunny is open (5 holes, never culled); the armadillo is closed.
    for (support::SharedMeshFile& file : support::read_shared_meshes(
             support::shared_assets_folder(), {"spot", "stanford-bunny", "armadillo"}, c.notes)) {
        c.meshes.push_back({file.name, effect_scene(std::move(file.mesh), kImageSize, kImageSize, file.axis), false, false});
    }
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
