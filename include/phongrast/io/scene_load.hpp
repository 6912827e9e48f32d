// The one way to build a renderable scene from files: a scene file (contract
// version 2: "mesh" or "objects"), a scene's JSON text, an already parsed
// SceneFile, or a mesh file alone (framed automatically). The command line
// (render, sheet, batch), Python and the tests all build scenes here, so a
// scene file gives the same Scene everywhere.
//
// What it does beyond reading the scene file (scene_file.hpp):
//  - loads every mesh file, each once however many objects place it (the
//    objects share one std::shared_ptr<const Mesh>);
//  - resolves the material as the contract's precedence says: Scene::material
//    is the base (the scene's fields, else the defaults) and
//    Scene::material_fields the scene's own fields, which win over each
//    face's material from its mesh file; the defaults that some face ends up
//    with are listed in `defaults_used` and said in `defaults_note`;
//  - a mesh file alone is framed by frame_mesh (auto_scene.hpp) and uses the
//    file's normals ("normals": "file") when the file has any.
#ifndef PHONGRAST_IO_SCENE_LOAD_HPP
#define PHONGRAST_IO_SCENE_LOAD_HPP

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/render.hpp"

namespace phongrast::io {

struct SceneLoadOptions {
    /// A mesh file to use instead of the scene's "mesh" (the command's
    /// --mesh). An error for a scene of "objects".
    std::string mesh_override;
    /// A mesh in memory to use instead of the scene's "mesh" (Python's
    /// Scene.load(path, mesh=...)). An error for a scene of "objects".
    std::shared_ptr<const Mesh> mesh;
    /// Meshes in memory for a scene of "objects": entry i, when not null, is
    /// objects[i]'s mesh and its "mesh" file is not read (Python's objects
    /// whose "mesh" is a phongrast.Mesh). Objects sharing one pointer share it.
    std::vector<std::shared_ptr<const Mesh>> object_meshes;
    /// The image size when both are positive (the command's --size); a mesh
    /// alone is framed for it. Otherwise the scene's, or 512 x 512 for a mesh alone.
    int rows = 0;
    int columns = 0;
    /// Reads a mesh file; empty: read_mesh. A cache (the batch command keeps
    /// parsed meshes for the jobs that name them again) passes its own.
    std::function<std::shared_ptr<const MeshFile>(const std::string& path)> read_mesh;
};

struct LoadedScene {
    /// Ready for render(): one `mesh` (a "mesh" scene or a mesh alone, the
    /// version-1 scene) or `objects`.
    Scene scene;
    /// Problems that do not stop the load, one line each naming the file:
    /// unknown fields, the mesh readers' warnings (each file's once).
    std::vector<std::string> warnings;
    /// The material fields that fell back to the contract's defaults for some
    /// face ("ka", "n", ...), and the line saying so (empty when none did).
    std::vector<std::string> defaults_used;
    std::string defaults_note;
    /// The file's stem ("bunny" for bunny.obj or bunny.json), or the name given.
    std::string name;
    /// The single mesh file (a "mesh" scene or a mesh alone); empty for "objects"
    /// or an in-memory mesh.
    std::string mesh_path;
    /// True for a mesh file alone, framed automatically.
    bool framed = false;
    /// Mesh files read, each once.
    std::size_t meshes_read = 0;
    /// Time spent reading mesh files.
    double load_seconds = 0.0;
};

/// A scene file (.json), or a mesh file alone (by its extension: .obj, .ply,
/// .stl, .gltf, .glb) framed automatically. Throws FileError naming the file
/// and the field (JSON pointer) or line.
LoadedScene load_scene(const std::string& path, const SceneLoadOptions& options = {});

/// A scene from its JSON text: `name` stands for the file in messages,
/// `folder` is where relative mesh paths start.
LoadedScene load_scene_text(const std::string& text, const std::string& name, const std::string& folder,
                            const SceneLoadOptions& options = {});

/// A scene file already read (read_scene_file, parse_scene_json) with its meshes loaded.
LoadedScene build_scene(SceneFile file, const std::string& name, const SceneLoadOptions& options = {});

/// A mesh file alone, framed by frame_mesh for options.rows x options.columns
/// (512 x 512 when not given); its MTL material (if any) replaces the
/// framing's neutral one, and the file's normals are used when it has any.
LoadedScene load_mesh_scene(const std::string& path, const SceneLoadOptions& options = {});

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_SCENE_LOAD_HPP
