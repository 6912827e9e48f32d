// Wavefront OBJ meshes in and out, as docs/scene-format.md (contract version 2)
// reads them: `v x y z [r g b]` positions with optional colours in [0,1]
// (vertices without a colour are white), faces of 3 or more vertices
// triangulated as a fan (v0 v1 v2, v0 v2 v3, ...), negative (relative)
// indices; `vt u v` as texture coordinates (s, t) = (u, v) and `vn` as the
// file's normals, per corner from `v/vt`, `v//vn` and `v/vt/vn`
// (Mesh::texcoords, Mesh::file_normals and their per-corner index lists);
// and a material per face, the last `usemtl` before it, from the `mtllib`
// files' `Ka`/`Kd`/`Ks`/`Ns`/`map_Kd` (Mesh::materials, Mesh::face_materials).
#ifndef PHONGRAST_IO_OBJ_FILE_HPP
#define PHONGRAST_IO_OBJ_FILE_HPP

#include <string>

#include "phongrast/io/mesh_file.hpp"

namespace phongrast::io {

/// The OBJ reader's result: the mesh (with its per-face materials), the MTL
/// material of the first face that has one (MeshFile::material, as version 1
/// read it), and warnings (a missing MTL file, an unknown material, an
/// unreadable texture, an ignored map_Kd option, textured faces without `vt`).
using ObjFile = MeshFile;

/// Reads and validates an OBJ file in one pass, in parallel over chunks of
/// large files; coordinates are the file's decimal values correctly rounded to
/// double. Throws FileError ("path:line: what was expected") for: a missing or
/// unreadable file, a non-numeric or non-finite coordinate or texture
/// coordinate, a face with fewer than 3 vertices, a zero or out-of-range `v`,
/// `vt` or `vn` index, a file without any face, and an MTL value that is not
/// a number ("file.mtl:line: ..."). A non-finite `vn` is kept as zero (the
/// contract's "take the computed normal").
ObjFile read_obj(const std::string& path);

/// Writes positions (with `significant_digits`, 17 keeps every double exactly),
/// colours when present (4 decimals), faces, and `comment` as '#' lines, to a
/// temporary file renamed into place. Throws FileError.
void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment = "",
               int significant_digits = 17);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_FILE_HPP
