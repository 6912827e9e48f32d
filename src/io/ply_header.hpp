// The header of a PLY file: format, elements and their typed properties, and
// where the body starts. Unknown types and malformed lines are errors naming
// the header line.
#ifndef PHONGRAST_IO_PLY_HEADER_HPP
#define PHONGRAST_IO_PLY_HEADER_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace phongrast::io {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };
enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::size_t size_of(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  ///< the items' type for a list
    bool is_list = false;
    PlyType count_type = PlyType::uint8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    /// Bytes of one element in a binary file when it has no list, else the least.
    std::size_t least_bytes() const;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    std::size_t body_offset = 0;  ///< the byte after "end_header\n"
    std::size_t body_line = 0;    ///< the body's first line, 1-based (ASCII messages)
};

/// Throws FileError "path:line: ..." for a header that is not PLY 1.0.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_PLY_HEADER_HPP
