// --aov-files and --depth-scale, shared by render and batch.
#include "commands.hpp"

namespace phongrast::cli {

void add_dataset_file_flags(CLI::App& command, std::string& files, double& depth_scale) {
    command.add_option("--aov-files", files,
                       "Extra outputs as files next to each image NAME.png/.exr: depth (NAME.depth.exr, camera "
                       "depth z_c, float), depth16 (NAME.depth.png, 16-bit, z_c / --depth-scale, 0 = background), "
                       "mask (NAME.mask.png, 8-bit coverage), id (NAME.id.png, 16-bit triangle index + 1), normal "
                       "(NAME.normal.png, (n + 1) / 2 in world space), object (NAME.object.png, 16-bit object "
                       "index + 1), distance (NAME.distance.exr, float, Euclidean distance from the eye; orthographic: = "
                       "z_c); comma-separated, or all (all but depth16). See docs/datasets.md");
    command.add_option("--depth-scale", depth_scale,
                       "Scene units per step of NAME.depth.png (default 0.001: millimetres for a scene in metres)")
        ->check(CLI::PositiveNumber);
}

}  // namespace phongrast::cli
