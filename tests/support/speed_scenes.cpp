#include "speed_scenes.hpp"

#include <filesystem>
#include <stdexcept>

#include "shared_scenes.hpp"

namespace phongrast::support {
namespace {

/// A generated icosphere of the speed scenes: 20 * frequency^2 triangles at rows x rows.
struct SpeedIcosphere {
    const char* name;
    const char* scene_class;
    int frequency;
    int rows;
};

constexpr const char* kSmallClass = "512x512 scenes";

const SpeedIcosphere kIcospheres[] = {
    {"icosphere-9.7k", kSmallClass, 22, 512},
    {"icosphere-125k", "100k+ triangles", 79, 640},
    {"icosphere-1.3M", "1.3M sphere", 256, 1024},
    {"icosphere-8M", "8M mesh", 633, 2048},
};

const SpeedIcosphere* find_icosphere(const std::string& name) {
    for (const SpeedIcosphere& sphere : kIcospheres) {
        if (name == sphere.name) return &sphere;
    }
    return nullptr;
}

}  // namespace

std::vector<std::string> speed_scene_names(const SpeedSceneSelection& selection, std::vector<std::string>& notes) {
    std::vector<std::string> names = {"icosphere-9.7k"};
    if (selection.assets) {
        // Only whether the file is there: each benchmark reads the mesh when it gets to it.
        const std::string folder = shared_assets_folder();
        for (const SharedMesh& shared : shared_meshes()) {
            const std::string path = folder + "/" + shared.name + ".obj";
            if (std::filesystem::exists(path)) {
                names.push_back(shared.name);
            } else {
                notes.push_back(path + " not found: skipped (the shared meshes sit next to the repository, ../shared/assets)");
            }
        }
    }
    names.push_back("icosphere-125k");
    if (selection.large) names.push_back("icosphere-1.3M");
    if (selection.huge) names.push_back("icosphere-8M");
    return names;
}

NamedScene speed_scene(const std::string& name, int rows) {
    if (const SpeedIcosphere* sphere = find_icosphere(name)) {
        return icosphere_scene(name, sphere->frequency, rows > 0 ? rows : sphere->rows);
    }
    std::vector<std::string> notes;
    std::vector<NamedScene> scenes = comparison_scenes(rows > 0 ? rows : 512, notes, {name});
    if (scenes.size() == 1) return std::move(scenes.front());
    std::string why;
    for (const std::string& note : notes) why += "; " + note;
    throw std::invalid_argument("scene: expected icosphere-9.7k, icosphere-125k, icosphere-1.3M, icosphere-8M or a mesh "
                                "of ../shared/assets (suzanne, spot, ...), got '" + name + "'" + why);
}

std::string speed_scene_class(const std::string& name) {
    const SpeedIcosphere* sphere = find_icosphere(name);
    return sphere ? sphere->scene_class : kSmallClass;
}

}  // namespace phongrast::support
