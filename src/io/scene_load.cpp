#include "phongrast/io/scene_load.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <sstream>

#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

namespace fs = std::filesystem;

/// Reads each mesh file once: objects placing the same file share it.
class MeshCache {
public:
    MeshCache(const SceneLoadOptions& options, LoadedScene& loaded) : options_(options), loaded_(loaded) {}

    /// The file at `path` (read now or earlier). Its warnings go to the
    /// loaded scene the first time.
    std::shared_ptr<const MeshFile> get(const std::string& path) {
        std::error_code error;
        fs::path key_path = fs::absolute(path, error);
        const std::string key = (error ? fs::path(path) : key_path).lexically_normal().string();
        const auto found = files_.find(key);
        if (found != files_.end()) return found->second;
        const auto start = std::chrono::steady_clock::now();
        std::shared_ptr<const MeshFile> file =
            options_.read_mesh ? options_.read_mesh(path) : std::make_shared<const MeshFile>(read_mesh(path));
        loaded_.load_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++loaded_.meshes_read;
        for (const std::string& warning : file->warnings) loaded_.warnings.push_back(warning);
        files_.emplace(key, file);
        return file;
    }

    /// The file at `path` for a scene of one mesh, which takes its mesh: read
    /// here and moved out whole (a large mesh is never held twice), or a copy
    /// of what the caller's reader keeps.
    MeshFile take(const std::string& path) {
        const auto start = std::chrono::steady_clock::now();
        MeshFile file = options_.read_mesh ? MeshFile(*options_.read_mesh(path)) : read_mesh(path);
        loaded_.load_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++loaded_.meshes_read;
        for (const std::string& warning : file.warnings) loaded_.warnings.push_back(warning);
        return file;
    }

private:
    const SceneLoadOptions& options_;
    LoadedScene& loaded_;
    std::map<std::string, std::shared_ptr<const MeshFile>> files_;
};

std::string describe(const PhongMaterial& m) {
    std::ostringstream out;
    out << "ka " << m.ka.x << ", kd " << m.kd.x << ", ks " << m.ks.x << ", n " << m.n;
    return out.str();
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

/// Which of the four fields some face of `mesh` takes from nowhere but the
/// base material: not in `given` (the object's fields over the scene's) and
/// not in the face's own material.
void find_fallbacks(const Mesh& mesh, const MaterialFields& given, bool fallback[4]) {
    const auto mark = [&](const MaterialFields* face) {
        fallback[0] = fallback[0] || (!given.ka && !(face && face->ka));
        fallback[1] = fallback[1] || (!given.kd && !(face && face->kd));
        fallback[2] = fallback[2] || (!given.ks && !(face && face->ks));
        fallback[3] = fallback[3] || (!given.n && !(face && face->n));
    };
    if (mesh.face_materials.size() != mesh.triangles.size()) {
        if (!mesh.triangles.empty()) mark(nullptr);
        return;
    }
    std::vector<bool> seen(mesh.materials.size() + 1, false);
    for (const std::uint32_t index : mesh.face_materials) {
        const std::size_t slot = index < mesh.materials.size() ? index : mesh.materials.size();
        if (seen[slot]) continue;
        seen[slot] = true;
        mark(slot < mesh.materials.size() ? &mesh.materials[slot].coefficients : nullptr);
    }
}

/// A mesh whose reader gave only the old whole-file material (the first
/// `usemtl`'s) and no per-face materials: that material as every face's own,
/// so that it takes its place in the contract's precedence below the scene's
/// and the object's fields.
std::shared_ptr<const Mesh> with_file_material(const std::shared_ptr<const MeshFile>& file) {
    if (!file->material || !file->mesh.face_materials.empty()) {
        return std::shared_ptr<const Mesh>(file, &file->mesh);
    }
    auto mesh = std::make_shared<Mesh>(file->mesh);
    FaceMaterial material;
    material.name = file->material_name;
    material.coefficients.ka = file->material->ka;
    material.coefficients.kd = file->material->kd;
    material.coefficients.ks = file->material->ks;
    material.coefficients.n = file->material->n;
    mesh->materials.push_back(std::move(material));
    mesh->face_materials.assign(mesh->triangles.size(), 0u);
    return mesh;
}

/// "scene.json: /objects/2/mesh: cup.glb: mesh not found (...)" before reading.
void require_mesh_file(const std::string& name, const std::string& pointer, const std::string& path) {
    std::error_code error;
    if (!fs::exists(path, error)) {
        throw FileError(name + ": " + pointer + ": " + path +
                        ": mesh not found (no such file; a relative \"mesh\" is relative to the scene file)");
    }
}

void set_defaults_note(LoadedScene& loaded, const std::string& source, const std::string& where_else) {
    if (loaded.defaults_used.empty()) return;
    loaded.defaults_note = "no " + joined(loaded.defaults_used) + " in " + source + where_else +
                           "; using the defaults, material: " + describe(loaded.scene.material);
}

/// A "mesh" scene: the version-1 scene, one mesh, with one of two material
/// rules. A mesh with per-face materials gets the contract's precedence (the
/// scene's fields over each face's, over the defaults); a mesh whose reader
/// gave only its first material gets that material under the scene's fields
/// for every face, as before per-face materials existed.
void load_single_mesh(SceneFile& file, const std::string& name, const SceneLoadOptions& options, MeshCache& meshes,
                      LoadedScene& loaded) {
    Scene& scene = loaded.scene;
    std::optional<PhongMaterial> from_file;
    bool per_face = false;
    if (options.mesh) {
        scene.mesh = *options.mesh;
        per_face = !scene.mesh.face_materials.empty();
    } else {
        std::string path = file.mesh_path;
        if (!options.mesh_override.empty()) {
            path = options.mesh_override;
        } else if (path.empty()) {
            throw FileError(name + ": /mesh: missing required field; expected a mesh file name (.obj, .ply, .stl, "
                                   ".gltf, .glb; or give --mesh), or \"objects\"");
        } else {
            require_mesh_file(name, "/mesh", path);
        }
        MeshFile mesh_file = meshes.take(path);
        scene.mesh = std::move(mesh_file.mesh);
        per_face = !scene.mesh.face_materials.empty();
        if (!per_face) from_file = mesh_file.material;
        loaded.mesh_path = path;
    }
    if (per_face) {
        scene.material = resolve_material(file.material, std::nullopt, nullptr);
        bool fallback[4] = {false, false, false, false};
        find_fallbacks(scene.mesh, file.material, fallback);
        const char* names[4] = {"ka", "kd", "ks", "n"};
        for (int i = 0; i < 4; ++i) {
            if (fallback[i]) loaded.defaults_used.push_back(names[i]);
        }
        set_defaults_note(loaded, name, " or the mesh's materials");
    } else {
        scene.material = resolve_material(file.material, from_file, &loaded.defaults_used);
        set_defaults_note(loaded, name, from_file ? " or the mesh's MTL" : " (and the mesh has no MTL)");
    }
}

void load_objects(SceneFile& file, const std::string& name, const SceneLoadOptions& options, MeshCache& meshes,
                  LoadedScene& loaded) {
    if (!options.mesh_override.empty() || options.mesh) {
        throw FileError(name + ": /objects: the scene places several objects; a replacement mesh (--mesh) "
                               "replaces a scene's single \"mesh\" only");
    }
    Scene& scene = loaded.scene;
    // Each file once, and its old whole-file material made per-face once.
    std::map<const MeshFile*, std::shared_ptr<const Mesh>> placed;
    const auto file_mesh = [&](std::size_t i, const SceneFileObject& entry) {
        const std::string pointer = "/objects/" + std::to_string(i) + "/mesh";
        require_mesh_file(name, pointer, entry.mesh_path);
        std::shared_ptr<const MeshFile> mesh_file;
        try {
            mesh_file = meshes.get(entry.mesh_path);
        } catch (const FileError& error) {
            throw FileError(name + ": " + pointer + ": " + error.what());
        }
        std::shared_ptr<const Mesh>& mesh = placed[mesh_file.get()];
        if (!mesh) mesh = with_file_material(mesh_file);
        return mesh;
    };
    bool fallback[4] = {false, false, false, false};
    for (std::size_t i = 0; i < file.objects.size(); ++i) {
        SceneFileObject& entry = file.objects[i];
        SceneObject object;
        if (i < options.object_meshes.size() && options.object_meshes[i]) {
            object.mesh = options.object_meshes[i];
        } else {
            object.mesh = file_mesh(i, entry);
        }
        object.transform = entry.transform;
        object.material = entry.material;
        object.normals = entry.normals;
        object.name = entry.name;
        find_fallbacks(*object.mesh, entry.material.or_else(file.material), fallback);
        scene.objects.push_back(std::move(object));
    }
    scene.material = resolve_material(file.material, std::nullopt, nullptr);
    const char* names[4] = {"ka", "kd", "ks", "n"};
    for (int i = 0; i < 4; ++i) {
        if (fallback[i]) loaded.defaults_used.push_back(names[i]);
    }
    set_defaults_note(loaded, name, ", its objects or their meshes' materials");
}

bool has_size(const SceneLoadOptions& options) { return options.rows > 0 && options.columns > 0; }

}  // namespace

LoadedScene build_scene(SceneFile file, const std::string& name, const SceneLoadOptions& options) {
    LoadedScene loaded;
    loaded.name = fs::path(name).stem().string();
    loaded.warnings = std::move(file.warnings);
    loaded.scene = std::move(file.scene);
    loaded.scene.material_fields = file.material;
    MeshCache meshes(options, loaded);
    if (file.objects.empty()) {
        load_single_mesh(file, name, options, meshes, loaded);
    } else {
        load_objects(file, name, options, meshes, loaded);
    }
    if (has_size(options)) {
        loaded.scene.image.rows = options.rows;
        loaded.scene.image.columns = options.columns;
    }
    return loaded;
}

LoadedScene load_scene_text(const std::string& text, const std::string& name, const std::string& folder,
                            const SceneLoadOptions& options) {
    return build_scene(parse_scene_json(text, name, folder), name, options);
}

LoadedScene load_mesh_scene(const std::string& path, const SceneLoadOptions& options) {
    LoadedScene loaded;
    loaded.name = fs::path(path).stem().string();
    loaded.mesh_path = path;
    loaded.framed = true;
    MeshCache meshes(options, loaded);
    MeshFile file = meshes.take(path);
    const int rows = has_size(options) ? options.rows : 512;
    const int columns = has_size(options) ? options.columns : 512;
    const bool per_face = !file.mesh.face_materials.empty();
    const bool has_normals = !file.mesh.file_normals.empty();
    loaded.scene = frame_mesh(std::move(file.mesh), rows, columns);
    // The framing's neutral material is the base; an old whole-file MTL
    // material replaces it, per-face materials win over it face by face.
    if (file.material && !per_face) loaded.scene.material = *file.material;
    if (has_normals) loaded.scene.normals = NormalSource::file;
    return loaded;
}

LoadedScene load_scene(const std::string& path, const SceneLoadOptions& options) {
    if (has_mesh_extension(path)) {
        if (!options.mesh_override.empty() || options.mesh) {
            throw FileError(path + ": a mesh given alone cannot take a replacement mesh; give a scene file");
        }
        return load_mesh_scene(path, options);
    }
    return build_scene(read_scene_file(path), path, options);
}

}  // namespace phongrast::io
