// The OBJ's materials (contract version 2, "Materials"): `mtllib` files read
// (MTL `Ka`, `Kd`, `Ks`, `Ns`, `map_Kd` with `-clamp on`), and every face
// given the material of the last `usemtl` before it.
#ifndef PHONGRAST_IO_OBJ_MATERIALS_HPP
#define PHONGRAST_IO_OBJ_MATERIALS_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "phongrast/lighting.hpp"
#include "phongrast/material.hpp"

namespace phongrast::io {

struct ObjMaterialUse {
    bool is_library = false;           ///< `mtllib FILE...`, else `usemtl NAME`
    std::string argument;
    std::size_t line = 0;              ///< in the file, 1-based
    std::size_t faces_before = 0;      ///< faces of the file before the statement
    std::size_t triangles_before = 0;  ///< and their triangles
};

struct ObjMaterials {
    /// The materials faces use, in order of first use (Mesh::materials).
    std::vector<FaceMaterial> materials;
    /// Per triangle, its index into `materials` or kNoIndex; empty when the
    /// file names no material that exists.
    std::vector<std::uint32_t> face_materials;
    /// The first face's material as version 1 read it (MeshFile::material):
    /// the MTL's fields, 0 for an absent Ka/Kd/Ks and 1 for an absent Ns.
    std::optional<PhongMaterial> first;
    std::string first_name;
    std::vector<std::string> warnings;  ///< "path:line: ..." lines
    std::vector<std::string> side_files;  ///< MTL files looked for and texture files named (MeshFile::side_files)
};

/// Follows the statements in order; MTL files are looked up next to `path`,
/// texture files next to their MTL. Throws FileError ("file.mtl:7: ...")
/// for an MTL value that is not a number.
ObjMaterials read_obj_materials(const std::vector<ObjMaterialUse>& uses, std::size_t triangles_in_file,
                                const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_MATERIALS_HPP
