// The scenes the speed benchmarks share (bench_llvmpipe, bench_speed_once,
// bench_goals), by name, grouped in the classes the speed goals name:
//   512x512 scenes           icosphere-9.7k and the meshes of ../shared/assets (1k-86k triangles)
//   100k+ triangles          icosphere-125k at 640x640
//   1.3M sphere              icosphere-1.3M at 1024x1024 (about one pixel per triangle)
//   8M mesh                  icosphere-8M at 2048x2048 (optional: "huge")
// The icospheres are icosphere_scene(): dented, coloured, three lights, normals computed.
#ifndef PHONGRAST_SUPPORT_SPEED_SCENES_HPP
#define PHONGRAST_SUPPORT_SPEED_SCENES_HPP

#include <string>
#include <vector>

#include "scenes.hpp"

namespace phongrast::support {

/// Which speed scenes a benchmark runs.
struct SpeedSceneSelection {
    bool assets = true;  ///< the meshes of ../shared/assets, when present
    bool large = true;   ///< icosphere-1.3M
    bool huge = true;    ///< icosphere-8M (8,013,780 triangles: about 0.4 GB with normals, seconds per frame)
};

/// The selected scenes' names, in the order above (shared meshes smallest
/// first; a missing one is left out with a line in `notes` saying why).
std::vector<std::string> speed_scene_names(const SpeedSceneSelection& selection, std::vector<std::string>& notes);

/// The scene called `name` at its class's image size (rows x rows when rows > 0).
/// Throws std::invalid_argument naming the known scenes for an unknown or missing one.
NamedScene speed_scene(const std::string& name, int rows = 0);

/// The goals' class of the scene called `name` (one of the four above).
std::string speed_scene_class(const std::string& name);

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_SPEED_SCENES_HPP
