// A line-by-line check of an OBJ file's `v` and `f` lines, run before
// tinyobjloader parses it. tinyobjloader silently reads "nan" or "abc" as 0,
// keeps faces of 1 or 2 vertices, and reports an out-of-range index only as a
// warning on the file's last line; the contract needs each of these to be an
// error that names the line.
#ifndef PHONGRAST_IO_OBJ_CHECK_HPP
#define PHONGRAST_IO_OBJ_CHECK_HPP

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace phongrast::io {

/// Throws FileError "path:line: ..." for the first bad `v` or `f` line, and
/// "path: ..." when the file has no face at all. Returns the `v` positions as
/// std::strtod reads them: correctly rounded, unlike tinyobjloader's own
/// number parser, which can be off in the last bits even in double mode.
std::vector<glm::dvec3> check_obj_text(const std::string& text, const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_CHECK_HPP
