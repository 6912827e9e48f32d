// The manifest of `phongrast batch`: JSON Lines, one job per line.
//
//   {"scene": "figures/knot.json"}                          a scene file
//   {"scene": {"mesh": "knot.obj", "camera": {...}, ...}}   a scene written inline
//   {"mesh": "chair.obj", "views": 24, "elevation": 20}     a turntable around the framed mesh
//   {"mesh": "chair.obj", "views": 8, "elevations": [-15, 30]}  one turntable ring per elevation
//   {"mesh": "chair.obj", "layout": "sphere", "views": 50}  views spread evenly over a sphere
//   {"mesh": "chair.obj", "layout": "hemisphere", "views": 50}   ... over the upper half
//   {"mesh": "cup.obj", "size": "640x480", "cameras": [{"eye": [...], "lookat": [...], "focal": 4, "sensor": [3, 4]},
//                       {"K": [[...]], "world_to_camera": [[...]]}]}    one image per camera, exactly as given
//   {"mesh": "cup.obj", "aov_files": "mask,depth16", "depth_scale": 0.0005}   files next to each image
//   {"mesh": "cup.obj", "layout": "sphere", "views": 50, "output": "cup/{view}.png",
//    "camera_out": "cup/cameras.json", "transforms_out": "cup/transforms.json"}   the views' cameras
//
// Optional on every line: "shader", "lighting", "size" ("WxH"), "samples",
// the rendering options of the library's table of names (option_names.hpp:
// "mode" ("exact" or "seed"), "visibility", "overdraw", "precision",
// "sample_pattern", "back_faces", "texture_filter") and "output", a name pattern relative to the
// output folder with {name} (the scene's or mesh's file stem, "line-N" for an
// inline scene), {line} and {view} (zero-padded to the width of the last view
// number; {view:N} pads to N digits). The pattern's extension chooses PNG or
// EXR. Relative paths resolve against the manifest's folder (a scene file's
// own "mesh" against the scene file's folder, as for `render`).
//
// "cameras" (mesh jobs only, instead of views/layout/elevation(s)) holds camera
// objects of the scene file's "camera" schema (docs/scene-format.md),
// read by the scene file's reader (io::parse_camera_object) and used exactly
// as given, without framing, under the automatic framing's lights: a view is
// `render mesh.obj` with that camera. An OpenCV K is in pixels, so its job
// needs a "size" and K's principal point must lie on that image.
//
// Every line is checked before anything is rendered: a malformed line (NaN or
// Infinity named by its field), a field of the wrong type or value, an unknown
// field (a typo would otherwise waste a whole cluster run; in a camera too,
// where a scene file only warns) or two jobs writing the same image is an
// io::FileError naming the manifest, the line and the field
// ("jobs.jsonl:3: /cameras/2/world_to_camera: the 3x3 part is not a rotation
// ..."). Files the jobs name are only read when the job runs: a missing or bad
// mesh fails that job alone.
#ifndef PHONGRAST_APPS_BATCH_MANIFEST_HPP
#define PHONGRAST_APPS_BATCH_MANIFEST_HPP

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "phongrast/camera.hpp"
#include "phongrast/io/dataset_files.hpp"

namespace phongrast::cli {

/// Settings a manifest line (or the command line, for every job) may override.
/// Empty / unset: the scene file's value, or the automatic framing's.
struct JobSettings {
    std::string shader;
    std::string lighting;
    std::string size;  ///< "WxH"
    std::optional<int> samples;
    /// Named rendering options by key (option_names.hpp), "mode" among them.
    std::map<std::string, std::string> options;
    /// Files next to each image (render's --aov-files); empty: none.
    std::string dataset_files;
    std::optional<double> depth_scale;  ///< scene units per step of NAME.depth.png
    /// Per-job camera files, name patterns with {name} and {line}: every
    /// view's camera (render's --camera-out format), and a transforms.json.
    std::string camera_out;
    std::string transforms_out;
};

enum class JobKind { scene_file, inline_scene, mesh };

/// Where a mesh job's cameras are (batch_views.hpp computes them).
enum class ViewLayout {
    turntable,   ///< rings around the vertical axis, one per elevation
    sphere,      ///< a Fibonacci lattice over the whole sphere of directions
    hemisphere,  ///< the same over the upper half (elevations above 0)
};

struct BatchJob {
    int line = 0;  ///< 1-based line of the manifest
    JobKind kind = JobKind::scene_file;
    std::string path;         ///< scene file or mesh, resolved against the manifest's folder
    std::string scene_json;   ///< inline_scene: the scene object as JSON text
    std::string folder;       ///< the manifest's folder: an inline scene's "mesh" is relative to it
    ViewLayout layout = ViewLayout::turntable;  ///< mesh jobs only
    /// Images of the job: for a turntable, views per ring x rings; for a
    /// sphere or hemisphere, the lattice's points; with "cameras", one per camera.
    int views = 1;
    /// Turntable: the rings' elevations in degrees above the horizontal, each
    /// in (-90, 90), ring by ring in this order; views / elevations.size()
    /// views per ring, 360 / that degrees apart.
    std::vector<double> elevations{0.0};
    /// "cameras": view i's camera, exactly as given (no framing); empty: the
    /// views of `layout`. The scene file's camera schema, checked as it is.
    std::vector<Camera> cameras;
    JobSettings settings;     ///< the line's fields over the command line's
    std::vector<std::string> outputs;  ///< one per view, relative to the output folder
    io::DatasetFiles dataset_files;    ///< written next to each output (settings.dataset_files parsed)
    io::DatasetFileOptions dataset_options;
    /// The job's camera file and transforms.json, relative to the output
    /// folder (settings.camera_out / transforms_out expanded); empty: none.
    std::string camera_file;
    std::string transforms_file;

    /// Every file of view `view`: its dataset files, then its image (written
    /// last, so an existing image means a complete view).
    std::vector<std::string> files_of_view(std::size_t view) const;
    /// The job's own files (camera file, transforms.json), written after every view.
    std::vector<std::string> files_of_job() const;
};

struct Manifest {
    std::string path;
    std::string folder;  ///< where relative paths start
    std::vector<BatchJob> jobs;
};

/// Reads and checks a manifest file. `defaults` (from the command line) fill
/// the settings a line leaves out. Throws io::FileError (exit status 2).
Manifest read_manifest(const std::string& path, const JobSettings& defaults);

/// The same from text; `name` is used in messages, `folder` to resolve paths.
Manifest parse_manifest(const std::string& text, const std::string& name, const std::string& folder,
                        const JobSettings& defaults);

/// True when every image of `job` exists in `output_folder`. Images are
/// renamed into place whole, so an existing image is a complete one.
bool outputs_exist(const BatchJob& job, const std::string& output_folder);

/// Expands an output pattern for one view. Throws std::invalid_argument
/// describing a bad placeholder.
std::string expand_output_pattern(const std::string& pattern, const std::string& name, int line, int view,
                                  int views);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_MANIFEST_HPP
