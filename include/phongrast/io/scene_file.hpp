// Scene files (docs/scene-format.md, contract version 2) read with
// nlohmann-json, and written back for the user to copy. This reads the file
// alone; io::load_scene (scene_load.hpp) loads its meshes too.
//
// Required: "mesh" or "objects" (not both; neither only when the caller
// supplies a mesh, e.g. `--mesh`), "camera" (look-at: "eye", "lookat",
// "focal", "sensor"; OpenCV: "K" and "world_to_camera" or "camera_to_world";
// orthographic: "projection": "orthographic", "eye", "lookat", "sensor"), and
// "image" with "height" and "width". Optional, with these
// defaults: camera.up [0,1,0], image.background [1,1,1], ambient
// [0.2,0.2,0.2], lights [] (ambient only), shader "phong", lighting "full",
// normals "computed", material: see resolve_material.
// Unknown fields are not an error (the contract: "extra fields are allowed
// and ignored with a warning"): they are listed in `warnings`, named by their
// JSON pointer (/objects/2/colour names the object and the field).
#ifndef PHONGRAST_IO_SCENE_FILE_HPP
#define PHONGRAST_IO_SCENE_FILE_HPP

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "phongrast/lighting.hpp"
#include "phongrast/material.hpp"
#include "phongrast/render.hpp"

namespace phongrast::io {

/// The material fields a scene file gave (the library's type: material.hpp).
using MaterialFields = phongrast::MaterialFields;

/// One entry of "objects", its mesh not loaded yet.
struct SceneFileObject {
    /// "mesh" resolved against the scene file's folder.
    std::string mesh_path;
    /// "transform", or T * R * S from "translation", "rotation", "scale"
    /// (identity when none is given). Finite, last row 0 0 0 1, not singular.
    glm::dmat4 transform{1.0};
    MaterialFields material;              ///< the object's "material" fields
    std::optional<NormalSource> normals;  ///< the object's "normals", if given
    std::string name;                     ///< "objects[2] (cup.glb)", for messages
};

struct SceneFile {
    /// Everything but the meshes (not loaded yet) and the material (see
    /// resolve_material); scene.normals is the scene's "normals".
    Scene scene;
    /// "mesh" resolved against the scene file's folder; empty when absent.
    std::string mesh_path;
    /// "objects", in order; empty for a scene with "mesh".
    std::vector<SceneFileObject> objects;
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

/// A camera file: a JSON object that is a scene's "camera" (any of the
/// contract's three forms), or an object with a "camera" field holding one
/// (a scene file, or what `render --camera-out` writes). Other fields of such
/// an object are not read. Throws FileError naming `name` and the JSON
/// pointer; `warnings` gets the camera's ignored fields.
Camera parse_camera_json(const std::string& text, const std::string& name, std::vector<std::string>* warnings);

/// What a camera object's fields that the camera does not use become:
/// unknown fields, the look-at fields beside "K" (the matrices place an
/// OpenCV camera), an orthographic camera's "focal".
enum class UnusedCameraFields {
    warn,    ///< a warning each, as a scene file has them (the contract)
    refuse,  ///< an error naming the field (a batch manifest: a typo must not pass)
};

/// One camera object (JSON text) in exactly the scene file's "camera" schema
/// (any of the contract's three forms), read by the scene file's own reader.
/// `where` is the object's JSON pointer in the document it came from
/// ("/cameras/2", or "" for the root): every message is
/// "NAME: WHERE/FIELD: what" ("jobs.jsonl:3: /cameras/2/K/0/0: expected fx,
/// a positive number, got -5"). Throws FileError for a bad camera (wrong
/// shape, non-finite numbers, K with fx or fy <= 0, a pose that is not a
/// rotation, eye == lookat, up parallel to the view), std::invalid_argument
/// for a `where` that is not a JSON pointer. Warnings go into `warnings`.
Camera parse_camera_object(const std::string& text, const std::string& name, const std::string& where,
                          UnusedCameraFields unused, std::vector<std::string>* warnings);

/// parse_camera_json of a file's contents.
Camera read_camera_file(const std::string& path, std::vector<std::string>* warnings);

/// The defaults used when neither the scene nor the OBJ's MTL gives a material
/// field: the contract's example material, ka 0.1, kd 0.8, ks 1, n 1.
PhongMaterial default_material();

/// Scene fields first, then the MTL's, then default_material(). Each field
/// that fell back to the default is named in `defaults_used` ("ka", "n", ...).
PhongMaterial resolve_material(const MaterialFields& fields,
                               const std::optional<PhongMaterial>& from_mtl,
                               std::vector<std::string>* defaults_used);

/// A scene file (pretty JSON) describing `scene` with "mesh": mesh_path
/// (and "normals": "file" when scene.normals says so).
std::string scene_to_json(const Scene& scene, const std::string& mesh_path);

/// T * R * S (contract "Objects"): `rotation` a unit quaternion [x, y, z, w]
/// (normalised here), `scale` per axis. The model matrix of an object given
/// by translation, rotation and scale.
glm::dmat4 compose_transform(const glm::dvec3& translation, const glm::dvec4& rotation, const glm::dvec3& scale);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_SCENE_FILE_HPP
