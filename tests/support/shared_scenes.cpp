#include "shared_scenes.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <utility>

#include <glm/geometric.hpp>

#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/io/scene_load.hpp"

namespace phongrast::support {
namespace {

/// World coordinates to the frame in which `axis` is +z and the up vector +y.
glm::dvec3 to_framing(ViewAxis axis, const glm::dvec3& p) {
    switch (axis) {
        case ViewAxis::minus_z: return {-p.x, p.y, -p.z};
        case ViewAxis::minus_y_z_up: return {p.x, p.z, -p.y};
        case ViewAxis::plus_z: break;
    }
    return p;
}

/// The inverse of to_framing.
glm::dvec3 from_framing(ViewAxis axis, const glm::dvec3& p) {
    switch (axis) {
        case ViewAxis::minus_z: return {-p.x, p.y, -p.z};
        case ViewAxis::minus_y_z_up: return {p.x, -p.z, p.y};
        case ViewAxis::plus_z: break;
    }
    return p;
}

}  // namespace

Scene framed_scene(Mesh mesh, int rows, int columns, ViewAxis axis) {
    if (axis == ViewAxis::plus_z) return io::frame_mesh(std::move(mesh), rows, columns);
    Mesh turned;
    turned.positions.reserve(mesh.positions.size());
    for (const glm::dvec3& p : mesh.positions) turned.positions.push_back(to_framing(axis, p));
    Scene scene = io::frame_mesh(std::move(turned), rows, columns);
    scene.camera.eye = from_framing(axis, scene.camera.eye);
    scene.camera.lookat = from_framing(axis, scene.camera.lookat);
    scene.camera.up = from_framing(axis, scene.camera.up);
    for (PointLight& light : scene.lights) light.position = from_framing(axis, light.position);
    scene.mesh = std::move(mesh);
    return scene;
}

const std::vector<SharedMesh>& shared_meshes() {
    // The views of the camera table in ../shared/assets/README.md.
    static const std::vector<SharedMesh> meshes = {
        {"suzanne", ViewAxis::plus_z},         {"dolphins_colored", ViewAxis::minus_y_z_up},
        {"spot", ViewAxis::minus_z},           {"teapot", ViewAxis::plus_z},
        {"stanford-bunny", ViewAxis::plus_z},  {"armadillo", ViewAxis::plus_z},
    };
    return meshes;
}

std::string shared_assets_folder() { return PHONGRAST_SHARED_ASSETS_DIR; }

std::vector<SharedMeshFile> read_shared_meshes(const std::string& folder, const std::vector<std::string>& names,
                                               std::vector<std::string>& notes) {
    std::vector<SharedMeshFile> meshes;
    if (!std::filesystem::is_directory(folder)) {
        notes.push_back("the shared meshes are skipped: the folder " + folder +
                        " is absent (it sits next to the repository, ../shared/assets)");
        return meshes;
    }
    for (const SharedMesh& shared : shared_meshes()) {
        if (!names.empty() && std::find(names.begin(), names.end(), shared.name) == names.end()) continue;
        const std::string path = folder + "/" + shared.name + ".obj";
        if (!std::filesystem::exists(path)) {
            notes.push_back(path + " not found: skipped");
            continue;
        }
        try {
            meshes.push_back({shared.name, io::read_obj(path).mesh, shared.axis});
        } catch (const std::exception& error) {
            notes.push_back(path + " skipped: " + error.what());
        }
    }
    return meshes;
}

std::vector<NamedScene> shared_scenes(const std::string& folder, int rows, int columns,
                                      const std::vector<std::string>& names, std::vector<std::string>& notes) {
    std::vector<NamedScene> scenes;
    for (SharedMeshFile& file : read_shared_meshes(folder, names, notes)) {
        const std::string description = "../shared/assets/" + file.name + ".obj, " +
                                        std::to_string(file.mesh.triangles.size()) + " triangles, framed by io::frame_mesh";
        scenes.push_back({file.name, description, framed_scene(std::move(file.mesh), rows, columns, file.axis)});
    }
    return scenes;
}

std::vector<NamedScene> comparison_scenes(int rows, std::vector<std::string>& notes,
                                          const std::vector<std::string>& names) {
    std::vector<NamedScene> scenes = shared_scenes(shared_assets_folder(), rows, rows, names, notes);
    for (NamedScene& named : scenes) {
        Scene& scene = named.scene;
        // The recipe puts the eye 2.5 bounding-box diagonals from the centre.
        three_lights(scene, scene.camera.lookat, glm::length(scene.camera.eye - scene.camera.lookat) / 2.5);
        scene.mesh.normals = calculate_normals(scene.mesh);
    }
    return scenes;
}

Scene read_scene_with_mesh(const std::string& path) { return io::load_scene(path).scene; }

}  // namespace phongrast::support
