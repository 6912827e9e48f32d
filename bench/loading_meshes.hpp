// The loading benchmark's test files: a coloured latitude-longitude sphere of
// about N triangles, written once per size in every format. Kept apart from
// the timing so that a shared mesh generator can replace it.
#ifndef PHONGRAST_BENCH_LOADING_MESHES_HPP
#define PHONGRAST_BENCH_LOADING_MESHES_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "phongrast/mesh.hpp"

namespace phongrast_bench {

/// A closed sphere of radius 1 with about `triangles` triangles and a colour per vertex.
phongrast::Mesh loading_sphere(std::size_t triangles);

struct LoadingFile {
    std::string format;  ///< "obj", "ply-ascii", "ply-binary", "stl-binary", "glb"
    std::string path;
    std::uintmax_t bytes = 0;
    std::size_t triangles = 0;
};

/// Writes `mesh` in each format into `folder` (names start with `stem`, which
/// should name the size); an existing non-empty file is kept, so reruns skip the writing.
std::vector<LoadingFile> write_loading_files(const phongrast::Mesh& mesh, const std::string& folder,
                                             const std::string& stem);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_LOADING_MESHES_HPP
