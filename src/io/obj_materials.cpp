#include "obj_materials.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "tiny_obj_loader_double.hpp"

namespace phongrast::io {
namespace {

glm::vec3 to_vec3(const tinyobj::real_t (&values)[3]) {
    return {static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2])};
}

PhongMaterial to_phong(const tinyobj::material_t& material) {
    PhongMaterial phong;
    phong.ka = to_vec3(material.ambient);
    phong.kd = to_vec3(material.diffuse);
    phong.ks = to_vec3(material.specular);
    phong.n = static_cast<float>(material.shininess);
    return phong;
}

std::vector<std::string> split_warning_lines(const std::string& path, const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty()) lines.push_back(path + ": " + line);
    }
    return lines;
}

class MaterialLibrary {
public:
    explicit MaterialLibrary(const std::string& path) {
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        folder_ = folder.empty() ? std::string("./") : folder.string() + "/";
    }

    /// `mtllib a.mtl b.mtl`: the first file that loads, as tinyobjloader does.
    void load(const std::string& argument, std::size_t line) {
        std::istringstream words(argument);
        std::vector<std::string> names;
        for (std::string name; words >> name;) names.push_back(name);
        if (names.empty()) {
            warnings_ += "Looks like empty filename for mtllib. Use default material (line " +
                         std::to_string(line) + ".)\n";
            return;
        }
        tinyobj::MaterialFileReader reader(folder_);
        for (const std::string& name : names) {
            if (loaded_.count(name) > 0) return;
            std::string warning;
            std::string error;
            const bool ok = reader(name, &materials_, &ids_, &warning, &error);
            warnings_ += warning + error;
            if (ok) {
                loaded_.insert(name);
                return;
            }
        }
        warnings_ += "Failed to load material file(s). Use default material.\n";
    }

    /// `usemtl name`: its id, or -1 with a warning.
    int find(const std::string& name) {
        const auto it = ids_.find(name);
        if (it != ids_.end()) return it->second;
        warnings_ += "material [ '" + name + "' ] not found in .mtl\n";
        return -1;
    }

    const tinyobj::material_t& material(int id) const { return materials_[static_cast<std::size_t>(id)]; }
    const std::string& warnings() const { return warnings_; }

private:
    std::string folder_;
    std::vector<tinyobj::material_t> materials_;
    std::map<std::string, int> ids_;
    std::set<std::string> loaded_;
    std::string warnings_;
};

}  // namespace

ObjMaterialChoice choose_obj_material(const std::vector<ObjMaterialUse>& uses, std::size_t faces_in_file,
                                      const std::string& path) {
    ObjMaterialChoice choice;
    if (uses.empty()) return choice;
    MaterialLibrary library(path);
    int current = -1;
    std::size_t faces_at_current = 0;
    int chosen = -1;
    for (const ObjMaterialUse& use : uses) {
        if (chosen < 0 && current >= 0 && use.faces_before > faces_at_current) chosen = current;
        if (use.is_library) {
            library.load(use.argument, use.line);
            continue;
        }
        const int id = library.find(use.argument);
        if (id != current) {
            current = id;
            faces_at_current = use.faces_before;
        }
    }
    if (chosen < 0 && current >= 0 && faces_in_file > faces_at_current) chosen = current;
    if (chosen >= 0) {
        choice.material = to_phong(library.material(chosen));
        choice.name = library.material(chosen).name;
    }
    choice.warnings = split_warning_lines(path, library.warnings());
    return choice;
}

}  // namespace phongrast::io
