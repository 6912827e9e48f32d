// From a manifest line to the scenes it renders: the scene (file or inline)
// prepared exactly as `phongrast render` prepares it, or the automatically
// framed mesh turned around its vertical axis for a turntable.
#ifndef PHONGRAST_APPS_BATCH_VIEWS_HPP
#define PHONGRAST_APPS_BATCH_VIEWS_HPP

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "batch_manifest.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "scene_setup.hpp"

namespace phongrast::cli {

/// One loaded job: the mesh is loaded once and shared by all views, which
/// differ only in camera and lights.
struct JobScenes {
    PreparedScene prepared;
    std::vector<Camera> cameras;                    ///< one per view
    std::vector<std::vector<PointLight>> lights;    ///< one set per view
};

/// Keeps the last OBJ file read (known by its path, size and modification
/// time), so that consecutive jobs of a shard sharing a mesh parse it once.
class LastMesh {
public:
    std::shared_ptr<const io::MeshFile> read(const std::string& path);

private:
    std::string key_;
    std::shared_ptr<const io::MeshFile> mesh_;
};

/// Loads a job's files, meshes through `meshes` when given. Throws
/// io::FileError or std::invalid_argument for a bad scene or mesh (the job
/// fails, the batch goes on).
JobScenes load_job(const BatchJob& job, int threads, LastMesh* meshes = nullptr);

/// Turntable views of an automatically framed scene: view v looks from
/// 360 v / views degrees around the vertical (+y) axis through the look-at
/// point, `elevation` degrees above the horizontal; the lights turn with the
/// camera, so every view is lit alike. One sensor size fits every vertex in
/// every view with the framing's 10% margin, so the mesh keeps its size on
/// screen. With one view and no elevation this is exactly the framing of
/// `phongrast render mesh.obj`.
void make_turntable(const Scene& framed, int views, double elevation_degrees, JobScenes& scenes);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_VIEWS_HPP
