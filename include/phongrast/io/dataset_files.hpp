// Per-image files for datasets, next to the colour image (`--aov-files`):
// the extra outputs (aov.hpp) in the plain formats training pipelines read.
//
//   NAME.depth.exr    camera depth z_c (along the optical axis, scene units), 32-bit float "Z", +inf = background
//   NAME.depth.png    the same as 16-bit grey: round(z_c / depth_scale), at least 1; 0 = background
//   NAME.distance.exr distance from the eye (scene units), 32-bit float "Z" as in NAME.depth.exr, +inf = background
//                     (orthographic camera: from the image plane through the eye, = z_c; AovPlanes::distance)
//   NAME.mask.png     8-bit grey: the pixel's covered fraction x 255
//   NAME.id.png       16-bit grey: triangle index + 1; 0 = background
//   NAME.normal.png   8-bit RGB: (n + 1) / 2 of the unit WORLD-space shading normal; 0,0,0 = background
//   NAME.object.png   16-bit grey: object index + 1 (scenes of several objects); 0 = background
//
// NAME is the colour image's path without its extension. Depth, distance, id,
// normal and object come from one sample per pixel, never blended across an edge
// (with supersampling, the pixel's nearest covered sample: AovPlanes).
#ifndef PHONGRAST_IO_DATASET_FILES_HPP
#define PHONGRAST_IO_DATASET_FILES_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "phongrast/aov.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/render.hpp"

namespace phongrast::io {

/// Which files to write.
struct DatasetFiles {
    bool depth = false;    ///< NAME.depth.exr
    bool depth16 = false;  ///< NAME.depth.png
    bool mask = false;
    bool id = false;
    bool normal = false;
    bool object = false;
    bool distance = false;  ///< NAME.distance.exr

    bool any() const { return depth || depth16 || mask || id || normal || object || distance; }
    /// The extra planes the render must fill for these files.
    AovRequest planes() const;
    /// Adds planes() to what `aovs` already asks for.
    void add_planes_to(AovRequest& aovs) const;
};

/// "depth,depth16,mask,id,normal,object,distance" (any subset, comma-separated);
/// "all" among them stands for depth, mask, id, normal, object and distance
/// (everything but depth16). Throws std::invalid_argument
/// naming an unknown entry and listing the valid ones.
DatasetFiles parse_dataset_files(std::string_view text);
std::string to_string(const DatasetFiles& files);

struct DatasetFileOptions {
    /// Scene units per step of NAME.depth.png: 0.001 stores millimetres when
    /// the scene is in metres (the range is then 0.001 to 65.535).
    double depth_scale = 0.001;
    PngCompression png_compression = PngCompression::standard;
};

/// The paths `files` names for the colour image `colour_path`, in the order
/// of DatasetFiles' fields.
std::vector<std::string> dataset_file_paths(const std::string& colour_path, const DatasetFiles& files);

/// Throws std::invalid_argument (naming the option) when a 16-bit file cannot
/// hold what a scene of `triangles` triangles and `objects` objects may
/// draw, or depth_scale is not a positive finite number; call it before
/// rendering.
void check_dataset_files(const DatasetFiles& files, const DatasetFileOptions& options, std::size_t triangles,
                         std::size_t objects);
/// The same for the triangles and objects of `scene`.
void check_dataset_files(const DatasetFiles& files, const DatasetFileOptions& options, const Scene& scene);

/// The index of each object's first triangle in the render's triangle list
/// (the id output's numbering): {0} for a scene of one mesh, else the running
/// sum of Scene::objects' triangle counts.
std::vector<std::size_t> object_first_triangles(const Scene& scene);

/// Writes the files `files` names next to `colour_path` from the planes of
/// one render (each must have been requested: DatasetFiles::planes()).
/// `object_first_triangles` holds, for a scene of several objects, the index
/// of each object's first triangle in the render's triangle list (the id
/// output's numbering); it is needed only for the object file. Every value is
/// checked before any file is written: a depth beyond the 16-bit range names
/// the largest depth and the depth_scale it needs (FileError). Each file is
/// written to a temporary file and renamed. Throws FileError.
void write_dataset_files(const AovPlanes& planes, const std::vector<std::size_t>& object_first_triangles,
                         const std::string& colour_path, const DatasetFiles& files, const DatasetFileOptions& options);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_DATASET_FILES_HPP
