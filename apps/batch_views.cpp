#include "batch_views.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "phongrast/camera.hpp"

namespace phongrast::cli {
namespace {

/// Tilts v up by `elevation` (about the x axis), then turns it by `azimuth`
/// about the y axis. Angles of 0 leave v exactly as it is.
glm::dvec3 turn(const glm::dvec3& v, double azimuth, double elevation) {
    const double ce = std::cos(elevation), se = std::sin(elevation);
    const double ca = std::cos(azimuth), sa = std::sin(azimuth);
    const glm::dvec3 tilted(v.x, v.y * ce + v.z * se, -v.y * se + v.z * ce);
    return {tilted.x * ca + tilted.z * sa, tilted.y, -tilted.x * sa + tilted.z * ca};
}

/// Half width and half height on the image plane that every vertex needs from `camera`.
std::pair<double, double> half_extent(const Mesh& mesh, const Camera& camera, int rows, int columns) {
    const CameraFrame frame = make_camera_frame(camera, rows, columns);
    double half_width = 0.0;
    double half_height = 0.0;
    for (const glm::dvec3& p : mesh.positions) {
        const glm::dvec3 c = frame.camera_from_world(p);
        if (!(c.z > 0.0)) continue;  // the eye is 2.5 diagonals from the centre: cannot happen
        half_width = std::max(half_width, std::abs(camera.focal * c.x / c.z));
        half_height = std::max(half_height, std::abs(camera.focal * c.y / c.z));
    }
    return {half_width, half_height};
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

bool renders_computed_normals(const Scene& scene) {
    // The renderer's version-1 path (src/scene_assembly.hpp, needs_assembly):
    // assembled scenes compute their normals their own way, so any
    // version-2 attribute, even one that would not need assembly, rules the
    // mesh out.
    const Mesh& mesh = scene.mesh;
    return scene.objects.empty() && scene.material_fields.empty() && mesh.normals.empty() && mesh.texcoords.empty() &&
           mesh.texcoord_triangles.empty() && mesh.file_normals.empty() && mesh.file_normal_triangles.empty() &&
           mesh.materials.empty() && mesh.face_materials.empty();
}

void give_computed_normals(Scene& scene, const std::shared_ptr<const io::MeshFile>& file, MeshFileCache& meshes) {
    if (!renders_computed_normals(scene)) return;
    // Normals computed from other positions or triangles would be wrong ones.
    if (!same_bits(scene.mesh.positions, file->mesh.positions) || !same_bits(scene.mesh.triangles, file->mesh.triangles)) {
        return;
    }
    scene.mesh.normals = *meshes.computed_normals(file);
}

std::vector<ViewDirection> turntable_directions(int views_per_ring, const std::vector<double>& elevations_degrees) {
    const double pi = std::acos(-1.0);
    std::vector<ViewDirection> directions;
    for (const double degrees : elevations_degrees) {
        for (int view = 0; view < views_per_ring; ++view) {
            directions.push_back({2.0 * pi * view / views_per_ring, degrees * pi / 180.0});
        }
    }
    return directions;
}

std::vector<ViewDirection> lattice_directions(int views, bool upper_half_only) {
    const double pi = std::acos(-1.0);
    const double golden_angle = pi * (3.0 - std::sqrt(5.0));
    std::vector<ViewDirection> directions;
    for (int i = 0; i < views; ++i) {
        // Equal-area bands: heights evenly spaced in z give equal areas on the sphere.
        const double z = upper_half_only ? 1.0 - (i + 0.5) / views : 1.0 - (2.0 * i + 1.0) / views;
        directions.push_back({std::fmod(i * golden_angle, 2.0 * pi), std::asin(z)});
    }
    return directions;
}

void make_views(const Scene& framed, const std::vector<ViewDirection>& directions, JobScenes& scenes) {
    scenes.cameras.assign(1, framed.camera);
    scenes.lights.assign(1, framed.lights);
    if (directions.size() == 1 && directions[0].azimuth == 0.0 && directions[0].elevation == 0.0) {
        return;  // render's own framing, untouched
    }
    const glm::dvec3 centre = framed.camera.lookat;
    const int rows = framed.image.rows;
    const int columns = framed.image.columns;
    scenes.cameras.clear();
    scenes.lights.clear();
    double half_width = 0.0;
    double half_height = 0.0;
    for (const ViewDirection& direction : directions) {
        Camera camera = framed.camera;
        camera.eye = centre + turn(framed.camera.eye - centre, direction.azimuth, direction.elevation);
        std::vector<PointLight> lights = framed.lights;
        for (PointLight& light : lights) {
            light.position = centre + turn(light.position - centre, direction.azimuth, direction.elevation);
        }
        const auto [width, height] = half_extent(framed.mesh, camera, rows, columns);
        half_width = std::max(half_width, width);
        half_height = std::max(half_height, height);
        scenes.cameras.push_back(camera);
        scenes.lights.push_back(std::move(lights));
    }
    const double aspect = static_cast<double>(columns) / static_cast<double>(rows);
    const double sensor_height = 2.2 * std::max(half_height, half_width / aspect);
    if (!(sensor_height > 0.0)) return;  // a single point: keep the framing's sensor
    for (Camera& camera : scenes.cameras) {
        camera.sensor_height = sensor_height;
        camera.sensor_width = sensor_height * aspect;
    }
}

void use_cameras(const Scene& framed, const std::vector<Camera>& cameras, JobScenes& scenes) {
    scenes.cameras = cameras;
    scenes.lights.assign(cameras.size(), framed.lights);
}

void make_turntable(const Scene& framed, int views, double elevation_degrees, JobScenes& scenes) {
    make_views(framed, turntable_directions(views, {elevation_degrees}), scenes);
}

std::vector<ViewDirection> job_directions(const BatchJob& job) {
    if (job.layout != ViewLayout::turntable) return lattice_directions(job.views, job.layout == ViewLayout::hemisphere);
    return turntable_directions(job.views / static_cast<int>(job.elevations.size()), job.elevations);
}

JobScenes load_job(const BatchJob& job, int threads, MeshFileCache* meshes,
                   std::shared_ptr<const io::MeshFile>* mesh_read) {
    SceneFlags flags;
    flags.input = job.kind == JobKind::inline_scene ? "" : job.path;
    flags.shader = job.settings.shader;
    flags.lighting = job.settings.lighting;
    flags.size = job.settings.size;
    flags.options = job.settings.options;
    flags.samples = job.settings.samples.value_or(1);
    flags.threads = threads;
    std::vector<std::shared_ptr<const io::MeshFile>> read;  // the files the job's scene was made from
    if (meshes != nullptr) {
        flags.read_mesh = [meshes, &read](const std::string& path) {
            read.push_back(meshes->read(path));
            return read.back();
        };
    }
    // Notes for thousands of jobs would drown the progress; errors go to the
    // log. One for every job (its constructor asks whether stderr is a terminal).
    static const Messages silent(true);

    JobScenes scenes;
    if (job.kind == JobKind::inline_scene) {
        const std::string name = "line " + std::to_string(job.line) + " /scene";
        scenes.prepared = prepare_scene_text(job.scene_json, name, job.folder, flags, silent);
    } else {
        scenes.prepared = prepare_scene(flags, silent);
    }
    if (read.size() == 1) give_computed_normals(scenes.prepared.scene, read.front(), *meshes);
    if (mesh_read != nullptr) *mesh_read = read.size() == 1 ? read.front() : nullptr;
    if (job.kind == JobKind::mesh && !job.cameras.empty()) {
        use_cameras(scenes.prepared.scene, job.cameras, scenes);
    } else if (job.kind == JobKind::mesh) {
        make_views(scenes.prepared.scene, job_directions(job), scenes);
    } else {
        scenes.cameras.assign(1, scenes.prepared.scene.camera);
        scenes.lights.assign(1, scenes.prepared.scene.lights);
    }
    return scenes;
}

namespace {

/// Everything of `job` (and `threads`) load_job() reads besides the files:
/// fields joined by a byte no path or name holds.
std::string memo_key(const BatchJob& job, int threads) {
    const char separator = '\0';
    std::string key = job.path;
    const auto add = [&](const std::string& field) {
        key += separator;
        key += field;
    };
    add(job.settings.shader);
    add(job.settings.lighting);
    add(job.settings.size);
    add(job.settings.samples ? std::to_string(*job.settings.samples) : "-");
    for (const auto& [name, value] : job.settings.options) add(name + "=" + value);
    add("layout " + std::to_string(static_cast<int>(job.layout)));
    add("views " + std::to_string(job.views));
    for (const double degrees : job.elevations) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", degrees);
        add(text);
    }
    add("threads " + std::to_string(threads));
    return key;
}

}  // namespace

std::shared_ptr<JobScenes> JobScenesMemo::load(const BatchJob& job, int threads) {
    if (job.kind != JobKind::mesh || !job.cameras.empty()) {
        return std::make_shared<JobScenes>(load_job(job, threads, &meshes_));
    }
    std::shared_ptr<const io::MeshFile> file;
    try {
        file = meshes_.read(job.path);  // the current file (parsed again if it changed)
    } catch (const std::exception&) {
        return std::make_shared<JobScenes>(load_job(job, threads, &meshes_));  // fails with load_job's own message
    }
    const std::string key = memo_key(job, threads);
    std::shared_ptr<JobScenes> kept;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto entry = entries_.begin(); entry != entries_.end();) {
            if (entry->key != key) {
                ++entry;
            } else if (entry->file != file) {  // made from an older file
                bytes_ -= entry->bytes;
                entry = entries_.erase(entry);
            } else if (entry->lent) {
                ++entry;
            } else {
                entries_.splice(entries_.begin(), entries_, entry);
                ++reuses_;
                entry->lent = true;
                kept = entry->scenes;
                break;
            }
        }
    }
    if (kept) return lend(std::move(kept));
    std::shared_ptr<const io::MeshFile> made_from;
    auto scenes = std::make_shared<JobScenes>(load_job(job, threads, &meshes_, &made_from));
    if (made_from != file) return scenes;  // the file changed meanwhile: not kept
    Entry fresh{key, file, scenes, {}, true, mesh_file_bytes(*file)};  // lent from the start
    fresh.made = {scenes->prepared.scene.camera, scenes->prepared.scene.lights, scenes->prepared.options};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        bytes_ += fresh.bytes;
        entries_.push_front(std::move(fresh));
        while (bytes_ > budget_ && entries_.size() > 1) {
            bytes_ -= entries_.back().bytes;
            entries_.pop_back();
        }
    }
    return lend(std::move(scenes));
}

std::shared_ptr<JobScenes> JobScenesMemo::lend(std::shared_ptr<JobScenes> kept) {
    // The pointer handed out owns nothing itself: its deleter gives the
    // object back, and the entry (or, once it is dropped, the deleter's
    // `kept`) owns it. Made outside the lock: should making it throw, the
    // deleter runs at once, and give_back takes the lock.
    JobScenes* const scenes = kept.get();
    return std::shared_ptr<JobScenes>(scenes, [this, kept = std::move(kept)](JobScenes*) { give_back(kept); });
}

void JobScenesMemo::give_back(const std::shared_ptr<JobScenes>& scenes) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (Entry& entry : entries_) {
        if (entry.scenes != scenes) continue;
        scenes->prepared.scene.camera = entry.made.camera;
        scenes->prepared.scene.lights = entry.made.lights;
        scenes->prepared.options = entry.made.options;
        entry.lent = false;
        return;
    }
}

std::size_t JobScenesMemo::reuses() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return reuses_;
}

std::size_t JobScenesMemo::kept() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return entries_.size();
}

}  // namespace phongrast::cli
