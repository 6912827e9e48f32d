// The OBJ's material: `mtllib` files loaded (through tinyobjloader's MTL
// reader) and `usemtl` followed in file order, as tinyobjloader's own OBJ
// reader did, so that the chosen material and the warnings stay the same.
#ifndef PHONGRAST_IO_OBJ_MATERIALS_HPP
#define PHONGRAST_IO_OBJ_MATERIALS_HPP

#include <optional>
#include <string>
#include <vector>

#include "phongrast/lighting.hpp"

namespace phongrast::io {

struct ObjMaterialUse {
    bool is_library = false;       ///< `mtllib FILE...`, else `usemtl NAME`
    std::string argument;
    std::size_t line = 0;          ///< in the file, 1-based
    std::size_t faces_before = 0;  ///< faces of the file before the statement
};

struct ObjMaterialChoice {
    std::optional<PhongMaterial> material;  ///< of the first face that has one
    std::string name;
    std::vector<std::string> warnings;      ///< "path: ..." lines
};

/// Follows the statements in order; MTL files are looked up next to `path`.
ObjMaterialChoice choose_obj_material(const std::vector<ObjMaterialUse>& uses, std::size_t faces_in_file,
                                      const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_MATERIALS_HPP
