// Scenes for the meshes of ../shared/assets and for scene files, through the
// I/O library: its OBJ reader, its scene-file reader and its framing
// (io::frame_mesh, the camera recipe of ../shared/assets/README.md).
#ifndef PHONGRAST_SUPPORT_SHARED_SCENES_HPP
#define PHONGRAST_SUPPORT_SHARED_SCENES_HPP

#include <string>
#include <vector>

#include "scenes.hpp"

namespace phongrast::support {

/// Where the eye sits relative to the mesh's bounding-box centre, and which way is up.
enum class ViewAxis {
    plus_z,         ///< eye on +z, +y up (the recipe's default)
    minus_z,        ///< eye on -z, +y up (a mesh facing -z)
    minus_y_z_up,   ///< eye on -y, +z up (a z-up mesh)
};

/// io::frame_mesh seen along `axis`: the mesh is framed turned so that `axis`
/// becomes +z, and the camera and lights are turned back (an exact signed
/// permutation of coordinates), so the mesh itself is not touched.
Scene framed_scene(Mesh mesh, int rows, int columns, ViewAxis axis = ViewAxis::plus_z);

/// A mesh of ../shared/assets and the view its README suggests.
struct SharedMesh {
    const char* name;  ///< file name without ".obj"
    ViewAxis axis;
};
/// Every mesh of ../shared/assets, smallest first.
const std::vector<SharedMesh>& shared_meshes();

/// The folder the build was configured with (PHONGRAST_SHARED_ASSETS_DIR).
std::string shared_assets_folder();

/// A shared mesh as read from its file, and the view to frame it along.
struct SharedMeshFile {
    std::string name;
    Mesh mesh;
    ViewAxis axis;
};

/// The shared meshes named in `names` (all when empty) that exist in `folder`,
/// smallest first. A mesh that is missing or unreadable is skipped with a line
/// in `notes` saying why.
std::vector<SharedMeshFile> read_shared_meshes(const std::string& folder, const std::vector<std::string>& names,
                                               std::vector<std::string>& notes);

/// The shared meshes named in `names` (all when empty) that exist in `folder`,
/// each framed by framed_scene() at rows x columns. A mesh that is missing or
/// unreadable is skipped with a line in `notes` saying why.
std::vector<NamedScene> shared_scenes(const std::string& folder, int rows, int columns,
                                      const std::vector<std::string>& names, std::vector<std::string>& notes);

/// Every shared mesh found in shared_assets_folder() (those named in `names`,
/// all when empty) as the llvmpipe comparison, the speed runner and the scaling
/// benchmark render it: framed_scene() at rows x rows, three_lights() scaled to
/// the mesh, vertex normals computed.
std::vector<NamedScene> comparison_scenes(int rows, std::vector<std::string>& notes,
                                          const std::vector<std::string>& names = {});

/// A scene file with its mesh and material resolved, as `phongrast render` reads it.
/// Throws (io errors name the file) when it cannot be read.
Scene read_scene_with_mesh(const std::string& path);

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_SHARED_SCENES_HPP
