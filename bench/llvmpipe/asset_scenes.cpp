#include "asset_scenes.hpp"

#include <filesystem>
#include <iostream>

#include <glm/geometric.hpp>

#ifdef PHONGRAST_LLVMPIPE_HAS_IO
#include "phongrast/io/obj_file.hpp"
#endif

namespace llvmpipe_compare {

#ifdef PHONGRAST_LLVMPIPE_HAS_IO
namespace {

/// A row of the camera table in ../shared/assets/README.md ("Cameras").
struct AssetCamera {
    const char* file;
    glm::dvec3 up;
    glm::dvec3 eye;
    glm::dvec3 lookat;
    double focal;
    double sensor;
};

const AssetCamera kAssetCameras[] = {
    {"suzanne.obj", {0, 1, 0}, {-2.494, 1.252, 13.54}, {-2.494, 1.252, 4.104}, 9.438, 2.856},
    {"dolphins_colored.obj", {0, 0, 1}, {-63.86, -2819, 193.1}, {-63.86, 0, 193.1}, 2819, 938.2},
    {"spot.obj", {0, 1, 0}, {0, 0.1084, -6.280}, {0, 0.1084, 0.1900}, 6.470, 1.999},
    {"teapot.obj", {0, 1, 0}, {0.217, 1.575, 20.51}, {0.217, 1.575, 0}, 20.51, 7.087},
    {"stanford-bunny.obj", {0, 1, 0}, {-0.01684, 0.1102, 0.6241}, {-0.01684, 0.1102, -0.001537}, 0.6256, 0.1808},
    {"armadillo.obj", {0, 1, 0}, {-0.01597, -0.07343, 3.781}, {-0.01597, -0.07343, 0.001924}, 3.779, 1.158},
};

}  // namespace

std::vector<NamedScene> asset_scenes(int rows) {
    const std::filesystem::path folder = PHONGRAST_SHARED_ASSETS_DIR;
    std::vector<NamedScene> scenes;
    for (const AssetCamera& entry : kAssetCameras) {
        const std::filesystem::path path = folder / entry.file;
        if (!std::filesystem::exists(path)) {
            std::cerr << "bench_llvmpipe: " << path.string() << " not found, scene skipped\n";
            continue;
        }
        NamedScene named;
        named.name = std::filesystem::path(entry.file).stem().string();
        phongrast::Scene& scene = named.scene;
        scene.mesh = phongrast::io::read_obj(path.string()).mesh;
        scene.camera.eye = entry.eye;
        scene.camera.lookat = entry.lookat;
        scene.camera.up = entry.up;
        scene.camera.focal = entry.focal;
        scene.camera.sensor_height = scene.camera.sensor_width = entry.sensor;
        scene.image.rows = scene.image.columns = rows;
        // The recipe puts the eye 2.5 bounding-box diagonals from the centre.
        light_scene(scene, entry.lookat, glm::length(entry.eye - entry.lookat) / 2.5);
        compute_normals(scene);
        scenes.push_back(std::move(named));
    }
    return scenes;
}

#else

std::vector<NamedScene> asset_scenes(int /*rows*/) {
    std::cerr << "bench_llvmpipe: shared asset meshes skipped (this build has no phongrast::io OBJ reader; "
                 "configure with PHONGRAST_BUILD_IO=ON)\n";
    return {};
}

#endif

}  // namespace llvmpipe_compare
