// Scenes built from the meshes in ../shared/assets (when present), with the
// cameras of ../shared/assets/README.md and the lights of light_scene().
#ifndef PHONGRAST_BENCH_LLVMPIPE_ASSET_SCENES_HPP
#define PHONGRAST_BENCH_LLVMPIPE_ASSET_SCENES_HPP

#include <vector>

#include "scenes.hpp"

namespace llvmpipe_compare {

/// One scene per shared mesh found, rows x rows pixels. Prints a line to stderr
/// and returns fewer scenes (or none) when the folder or a mesh is missing, or
/// when phongrast was built without its OBJ reader.
std::vector<NamedScene> asset_scenes(int rows);

}  // namespace llvmpipe_compare

#endif  // PHONGRAST_BENCH_LLVMPIPE_ASSET_SCENES_HPP
