// Scene files (docs/scene-format.md, contract version 1) read with
// nlohmann-json, and written back for the user to copy.
//
// Required: "mesh" (unless the caller supplies one, e.g. `--mesh`),
// "camera" with "eye", "lookat", "focal", "sensor", and "image" with "height"
// and "width". Optional, with these defaults: camera.up [0,1,0],
// image.background [1,1,1], ambient [0.2,0.2,0.2], lights [] (ambient only),
// shader "phong", lighting "full", material: see resolve_material.
// Unknown fields are not an error: they are listed in `warnings`.
#ifndef PHONGRAST_IO_SCENE_FILE_HPP
#define PHONGRAST_IO_SCENE_FILE_HPP

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "phongrast/lighting.hpp"
#include "phongrast/render.hpp"

namespace phongrast::io {

/// The material fields a scene file gave; absent ones come from the MTL or defaults.
struct MaterialFields {
    std::optional<glm::vec3> ka, kd, ks;
    std::optional<float> n;
};

struct SceneFile {
    /// Everything but the mesh (not loaded yet) and the material (see resolve_material).
    Scene scene;
    /// "mesh" resolved against the scene file's folder; empty when absent.
    std::string mesh_path;
    MaterialFields material;
    /// One line per ignored unknown field, naming it ("scene.json: ignoring unknown field /foo").
    std::vector<std::string> warnings;
};

/// Reads and validates a scene file. Throws FileError naming the file and the
/// JSON pointer of the field ("scene.json: /camera/eye/2: expected a finite
/// number, got string") or, for malformed JSON, its line and column.
SceneFile read_scene_file(const std::string& path);

/// The same from text: `name` is used in messages, `folder` to resolve "mesh".
SceneFile parse_scene_json(const std::string& text, const std::string& name,
                           const std::string& folder);

/// The defaults used when neither the scene nor the OBJ's MTL gives a material
/// field: the contract's example material, ka 0.1, kd 0.8, ks 1, n 1.
PhongMaterial default_material();

/// Scene fields first, then the MTL's, then default_material(). Each field
/// that fell back to the default is named in `defaults_used` ("ka", "n", ...).
PhongMaterial resolve_material(const MaterialFields& fields,
                               const std::optional<PhongMaterial>& from_mtl,
                               std::vector<std::string>* defaults_used);

/// A scene file (pretty JSON) describing `scene` with "mesh": mesh_path.
std::string scene_to_json(const Scene& scene, const std::string& mesh_path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_SCENE_FILE_HPP
