#include "bench_meshes.hpp"

#include <exception>
#include <filesystem>

#include "bench_scenes.hpp"

#if PHONGRAST_BENCH_WITH_IO
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"
#endif

namespace phongrast_bench {
namespace {

struct Catalogue {
    std::vector<BenchMesh> meshes;
    std::vector<std::string> notes;
};

#if PHONGRAST_BENCH_WITH_IO
// A shared mesh, framed like the generated ones (the README's camera recipe).
void add_shared_mesh(Catalogue& c, const std::string& file, ViewAxis axis) {
    const std::filesystem::path folder = PHONGRAST_SHARED_ASSETS_DIR;
    if (!std::filesystem::is_directory(folder)) {
        c.notes.push_back("skipping " + file + ": the shared assets folder " + folder.string() +
                          " is absent (it sits next to the repository, ../shared/assets)");
        return;
    }
    try {
        phongrast::io::ObjFile obj = phongrast::io::read_obj((folder / file).string());
        const std::string name = std::filesystem::path(file).stem().string();
        c.meshes.push_back({name, framed_scene(std::move(obj.mesh), kImageSize, kImageSize, axis), false, false});
    } catch (const std::exception& error) {
        c.notes.push_back("skipping " + file + ": " + error.what());
    }
}

// The project's default scene as the app renders it (its camera, image, material
// and lights); the benchmark then varies lighting, shader and lights.
void add_default_scene(Catalogue& c) {
    const std::filesystem::path path = std::filesystem::path(PHONGRAST_PROJECT_ASSETS_DIR) / "default.json";
    if (!std::filesystem::exists(path)) {
        c.notes.push_back("skipping the default scene: " + path.string() + " does not exist");
        return;
    }
    try {
        phongrast::io::SceneFile file = phongrast::io::read_scene_file(path.string());
        phongrast::io::ObjFile obj = phongrast::io::read_obj(file.mesh_path);
        BenchMesh mesh{"default", std::move(file.scene), false, true};
        mesh.scene.mesh = std::move(obj.mesh);
        mesh.scene.material = phongrast::io::resolve_material(file.material, obj.material, nullptr);
        c.meshes.push_back(std::move(mesh));
    } catch (const std::exception& error) {
        c.notes.push_back("skipping the default scene: " + std::string(error.what()));
    }
}
#endif

Catalogue build_catalogue() {
    Catalogue c;
    // 1,280 triangles of ~90 pixels each: the time goes into filling and shading.
    c.meshes.push_back({"icosphere-1k", framed_scene(icosphere(3), kImageSize, kImageSize), false, false});
    // 81,920 triangles, like the shared meshes' 70k-86k: ~1.5 pixels each, so
    // per-triangle setup weighs as much as per-pixel shading.
    c.meshes.push_back({"icosphere-82k", framed_scene(icosphere(6), kImageSize, kImageSize), false, false});
    // Seen from above at an angle: some inner back faces are painted over front faces.
    c.meshes.push_back({"torus", framed_scene(torus(256, 128, 1.0, 0.4), kImageSize, kImageSize), true, false});
#if PHONGRAST_BENCH_WITH_IO
    add_default_scene(c);
    add_shared_mesh(c, "spot.obj", ViewAxis::minus_z);   // closed; faces -z
    add_shared_mesh(c, "stanford-bunny.obj", ViewAxis::plus_z);  // open: 5 holes, never culled
    add_shared_mesh(c, "armadillo.obj", ViewAxis::plus_z);       // closed
#else
    c.notes.push_back("built without phongrast::io: only generated meshes are measured");
#endif
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
