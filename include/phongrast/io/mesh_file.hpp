// Triangle meshes from files as users have them: Wavefront OBJ (with its MTL),
// PLY (ASCII, binary little or big endian), STL (ASCII or binary) and glTF 2.0
// (.gltf with its buffers, or .glb). read_mesh picks the reader by the file's
// content when it is unambiguous (a "ply" line, a "glTF" magic, "solid ..."
// followed by "facet", a binary STL whose size matches its triangle count),
// else by the extension. The writers exist for tests, benchmarks and
// conversions; each writes a temporary file renamed into place.
#ifndef PHONGRAST_IO_MESH_FILE_HPP
#define PHONGRAST_IO_MESH_FILE_HPP

#include <optional>
#include <string>
#include <vector>

#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast::io {

struct MeshFile {
    /// The mesh with what contract version 2 reads besides geometry: texture
    /// coordinates and file normals per corner, a material per face (OBJ/MTL,
    /// glTF), each texture's image loaded once per process (texture_file.hpp).
    Mesh mesh;
    /// The OBJ material of the first face that has one, as version 1 read it
    /// (the MTL's fields, an absent Ka/Kd/Ks as 0 and Ns as 1), for callers
    /// that use one material for the whole mesh; mesh.materials has them all.
    std::optional<PhongMaterial> material;
    std::string material_name;  ///< its name, for messages
    /// Problems that do not stop the load (an MTL file or a texture that is
    /// missing, an unknown material, ...), one per line, each naming the file.
    std::vector<std::string> warnings;
    /// The other files the reader read or looked for: an OBJ's MTL files and
    /// texture images, a glTF's external buffers and images. A cache of
    /// MeshFiles (the batch command's) checks them as well as the mesh file,
    /// so that an edited MTL or texture is read again.
    std::vector<std::string> side_files;
};

enum class MeshFormat { obj, ply, stl, gltf };

/// "OBJ", "PLY", "STL", "glTF".
const char* to_string(MeshFormat format);

/// True when `path` ends in .obj, .ply, .stl, .gltf or .glb (any case).
bool has_mesh_extension(const std::string& path);

/// The format of `bytes` (the file's first bytes, or all of it) read from
/// `path`: by content when it says so, else by extension. Throws FileError
/// when neither names a mesh format.
MeshFormat detect_mesh_format(const std::string& path, const char* bytes, std::size_t size);

/// Reads a mesh of any supported format. Throws FileError naming the file and
/// the place (line, element, byte offset or accessor) and what was expected.
MeshFile read_mesh(const std::string& path);

/// The single-format readers (read_mesh chooses among them).
MeshFile read_ply(const std::string& path);
MeshFile read_stl(const std::string& path);
MeshFile read_gltf(const std::string& path);

enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

/// PLY: double x y z, float red green blue when the mesh has colours, int
/// vertex_indices (ASCII with 17 significant digits: every double exactly).
void write_ply(const Mesh& mesh, const std::string& path, PlyEncoding encoding = PlyEncoding::binary_little_endian);
/// STL (binary or ASCII): positions rounded to float, colours dropped, each
/// triangle's facet normal from its corners.
void write_stl(const Mesh& mesh, const std::string& path, bool binary = true);
/// GLB: one mesh, one node, float positions, COLOR_0 when the mesh has colours.
void write_glb(const Mesh& mesh, const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_MESH_FILE_HPP
