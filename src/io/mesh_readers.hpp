// The format readers behind read_mesh, each on the file's bytes already in
// memory (read_mesh reads the file once and picks the reader from its content).
#ifndef PHONGRAST_IO_MESH_READERS_HPP
#define PHONGRAST_IO_MESH_READERS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "phongrast/io/mesh_file.hpp"

namespace phongrast::io {

MeshFile parse_obj(std::string_view text, const std::string& path);
MeshFile parse_ply(std::string_view bytes, const std::string& path);
MeshFile parse_stl(std::string_view bytes, const std::string& path);
/// External buffers (.gltf) are looked up next to `path`.
MeshFile parse_gltf(std::string_view bytes, const std::string& path);

/// One vertex per distinct position of `corners` (three per triangle), in
/// order of first appearance; the triangles index them.
Mesh weld_corners(const std::vector<glm::dvec3>& corners);

/// The contract's one warning for faces whose material has a texture but
/// whose corners lack texture coordinates (they draw with T = 1).
void warn_textured_faces_without_texcoords(MeshFile& file, const std::string& path);

/// validate_mesh, its complaint as a FileError naming `path`.
void check_mesh(const Mesh& mesh, const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_MESH_READERS_HPP
