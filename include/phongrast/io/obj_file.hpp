// Wavefront OBJ meshes in and out, as docs/scene-format.md ("mesh") reads them:
// `v x y z [r g b]` positions with optional colours in [0,1] (vertices without
// a colour are white), faces of 3 or more vertices triangulated as a fan
// (v0 v1 v2, v0 v2 v3, ...), negative (relative) indices, and the MTL
// `Ka`/`Kd`/`Ks`/`Ns` of the first material the faces use.
// `vn` and `vt` are read but not used: the renderer computes its own normals.
#ifndef PHONGRAST_IO_OBJ_FILE_HPP
#define PHONGRAST_IO_OBJ_FILE_HPP

#include <string>

#include "phongrast/io/mesh_file.hpp"

namespace phongrast::io {

/// The OBJ reader's result: the mesh, the MTL material of the first face
/// that names one (`usemtl`), and warnings.
using ObjFile = MeshFile;

/// Reads and validates an OBJ file in one pass, in parallel over chunks of
/// large files; coordinates are the file's decimal values correctly rounded to
/// double. Throws FileError ("path:line: what was expected") for: a missing or
/// unreadable file, a non-numeric or non-finite coordinate, a face with fewer
/// than 3 vertices, a zero or out-of-range index, and a file without any face.
ObjFile read_obj(const std::string& path);

/// Writes positions (with `significant_digits`, 17 keeps every double exactly),
/// colours when present (4 decimals), faces, and `comment` as '#' lines, to a
/// temporary file renamed into place. Throws FileError.
void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment = "",
               int significant_digits = 17);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_FILE_HPP
