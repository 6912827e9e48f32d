// From a manifest line to the scenes it renders: the scene (file or inline)
// prepared exactly as `phongrast render` prepares it, the automatically
// framed mesh seen from generated views (turntable, sphere), or the framed
// mesh seen by the line's own cameras.
#ifndef PHONGRAST_APPS_BATCH_VIEWS_HPP
#define PHONGRAST_APPS_BATCH_VIEWS_HPP

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "batch_manifest.hpp"
#include "batch_mesh_cache.hpp"
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

/// Loads a job's files, meshes through `meshes` when given. Throws
/// io::FileError or std::invalid_argument for a bad scene or mesh (the job
/// fails, the batch goes on). `mesh_read`, when given, is set to the one
/// mesh file the scene was made from (null when it was made from none or
/// several, or without `meshes`).
JobScenes load_job(const BatchJob& job, int threads, MeshFileCache* meshes = nullptr,
                   std::shared_ptr<const io::MeshFile>* mesh_read = nullptr);

/// load_job() for a shard's loaders: a mesh job (views of a layout, not
/// "cameras") that asks for what an earlier one asked (the same mesh path,
/// shader, lighting, size, samples, options, layout, views and elevations,
/// threads) and whose mesh file is still the one that job's scenes were made
/// from (the same parsed file in `meshes`: its file, MTL and textures
/// unchanged) gets those scenes again, without preparing, framing and
/// checking the scene again (a few tenths of a millisecond per job for a
/// 12k-triangle mesh, most of the loader's time once every mesh is parsed).
/// load_job() is a function of those inputs and the file alone, so they are
/// what it would return.
///
/// The kept scenes are lent, not copied (a copy of a 12k-triangle mesh,
/// 0.4 MB of fresh memory, cost about as much as the job's PNG's write):
/// load() returns the kept object itself while no other job holds it, and
/// takes it back when the returned pointer's last copy is dropped. The
/// holder may change `prepared.scene.camera`, `prepared.scene.lights` and
/// `prepared.options` (a render lane sets each view's camera and lights
/// and its thread count), which are put back as load_job() made them when
/// it is returned; nothing else. A job asking for scenes that are all lent
/// (two jobs of one mesh in flight at once) gets them made by load_job()
/// again, and they are kept beside the others for the next such job.
/// Kept scenes are bounded by memory (their meshes, estimated as
/// mesh_file_bytes()), least recently used dropped first; dropped lent
/// ones are freed when they are returned.
/// Thread-safe (several loaders, lanes returning); scenes are made outside
/// the lock. Every returned pointer must be dropped before the memo is.
class JobScenesMemo {
public:
    static constexpr std::size_t kDefaultBudgetBytes = std::size_t{64} << 20;

    explicit JobScenesMemo(MeshFileCache& meshes, std::size_t budget_bytes = kDefaultBudgetBytes)
        : meshes_(meshes), budget_(budget_bytes) {}

    std::shared_ptr<JobScenes> load(const BatchJob& job, int threads);

    std::size_t reuses() const;  ///< loads answered with kept scenes
    std::size_t kept() const;    ///< scenes kept now (several of one job when they were lent at once)

private:
    /// What a holder may change, as load_job() made it.
    struct Changeable {
        Camera camera;
        std::vector<PointLight> lights;
        RenderOptions options;
    };
    struct Entry {
        std::string key;
        std::shared_ptr<const io::MeshFile> file;
        std::shared_ptr<JobScenes> scenes;
        Changeable made;
        bool lent = false;
        std::size_t bytes = 0;
    };

    /// An entry's scenes (already marked lent), lent until the returned
    /// pointer's last copy is dropped. Not under the lock.
    std::shared_ptr<JobScenes> lend(std::shared_ptr<JobScenes> kept);
    /// A lent object back: its changeable fields put back, free to lend again (unless dropped meanwhile).
    void give_back(const std::shared_ptr<JobScenes>& scenes);

    MeshFileCache& meshes_;
    std::size_t budget_;
    mutable std::mutex mutex_;
    std::list<Entry> entries_;  ///< most recently used first
    std::size_t bytes_ = 0;
    std::size_t reuses_ = 0;
};

/// Whether the renderer computes `scene`'s vertex normals from its mesh's
/// positions and triangles alone (calculate_normals): one mesh given without
/// normals and without any of contract version 2's attributes.
bool renders_computed_normals(const Scene& scene);

/// When renders_computed_normals(scene) and its mesh's positions and
/// triangles are `file`'s, bit for bit: gives the mesh the normals the
/// renderer would compute, kept in `meshes` with the file, so that the jobs
/// of one mesh compute them once. The picture is the same bits (the renderer
/// uses given normals as they are; a zero one, where no face has an area,
/// is computed again, zero again).
void give_computed_normals(Scene& scene, const std::shared_ptr<const io::MeshFile>& file, MeshFileCache& meshes);

/// Where one view looks from, relative to the automatic framing's view:
/// turned `azimuth` radians about the vertical (+y) axis through the look-at
/// point after being tilted up by `elevation` radians.
struct ViewDirection {
    double azimuth = 0.0;
    double elevation = 0.0;
};

/// Turntable rings: for each elevation (degrees) in order, `views_per_ring`
/// views 360 / views_per_ring degrees apart, starting at azimuth 0.
std::vector<ViewDirection> turntable_directions(int views_per_ring, const std::vector<double>& elevations_degrees);

/// `views` directions spread evenly over the sphere (or its upper half) by a
/// Fibonacci lattice: point i (from the top down) at height
/// z = 1 - (2i + 1) / views (hemisphere: 1 - (i + 0.5) / views), elevation
/// asin(z), azimuth i times the golden angle pi (3 - sqrt 5). Deterministic,
/// no random seed; every elevation is strictly inside (-90, 90) degrees (the
/// hemisphere's strictly inside (0, 90)), so the look-at up vector is never
/// parallel to a view.
std::vector<ViewDirection> lattice_directions(int views, bool upper_half_only);

/// The views of an automatically framed scene, one per direction: the eye
/// and the lights turn together, so every view is lit alike. One sensor size
/// fits every vertex in every view with the framing's 10% margin, so the mesh
/// keeps its size on screen. A single direction of (0, 0) is exactly the
/// framing of `phongrast render mesh.obj`.
void make_views(const Scene& framed, const std::vector<ViewDirection>& directions, JobScenes& scenes);

/// The views of a job's explicit "cameras": each camera exactly as given
/// (no framing, no sensor fitted: world units of the mesh file, K in pixels
/// of the image), under the automatic framing's lights, which stay where the
/// framing put them. So a view is exactly `phongrast render mesh.obj` with
/// that camera (--camera FILE, or --K and --world-to-camera).
void use_cameras(const Scene& framed, const std::vector<Camera>& cameras, JobScenes& scenes);

/// A turntable of `views` views at one elevation (degrees): make_views of
/// turntable_directions(views, {elevation_degrees}).
void make_turntable(const Scene& framed, int views, double elevation_degrees, JobScenes& scenes);

/// The directions of a mesh job's layout (views, elevations).
std::vector<ViewDirection> job_directions(const BatchJob& job);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_VIEWS_HPP
