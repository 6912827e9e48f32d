// One chunk of an OBJ file (whole lines) parsed and checked in one pass:
// positions, colours, texture coordinates (`vt`), normals (`vn`),
// fan-triangulated faces with their per-corner `vt`/`vn` indices, and the
// material statements.
// Chunks are parsed in parallel, so a face's indices cannot be resolved until
// every chunk before it has counted its vertices: corners are kept tagged
// (absolute, or relative to this chunk's vertices) and resolved afterwards.
#ifndef PHONGRAST_IO_OBJ_CHUNK_HPP
#define PHONGRAST_IO_OBJ_CHUNK_HPP

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phongrast::io {

/// A face corner: 2 x index for an absolute (1-based) index, 2 x r + 1 for a
/// relative one, r being the 1-based index counted from this chunk's first
/// vertex (zero or negative when it reaches into earlier chunks). `vt` and
/// `vn` indices are tagged the same way, counted in their own lines; for
/// them 0 (which no index gives) means "this corner has none".
using TaggedCorner = std::int64_t;
constexpr TaggedCorner kNoCorner = 0;

/// `mtllib` or `usemtl`, with what followed it and where.
struct ObjMaterialStatement {
    bool is_library = false;
    std::string argument;
    std::size_t line = 0;           ///< 1-based, within the chunk
    std::size_t faces_before = 0;   ///< faces of this chunk before the statement
    std::size_t triangles_before = 0;  ///< and their triangles
};

struct ObjChunkError {
    std::size_t line = 0;  ///< 1-based, within the chunk
    std::string message;   ///< what was expected, without the file and line
};

struct ObjChunk {
    std::vector<glm::dvec3> positions;  ///< one per `v` line (a bad one still counts, as 0)
    std::vector<glm::vec3> colors;      ///< one per `v` line, white without `r g b`
    std::vector<std::array<TaggedCorner, 3>> triangles;
    std::vector<glm::vec2> texcoords;  ///< one per `vt` line: (u, v)
    std::vector<glm::vec3> normals;    ///< one per `vn` line (a non-finite one as 0: "take the computed normal")
    /// Per triangle, its corners' `vt` (and `vn`) indices, kNoCorner where a
    /// corner has none; empty when no face of the chunk has any (a plain OBJ
    /// pays nothing for them).
    std::vector<std::array<TaggedCorner, 3>> texcoord_triangles;
    std::vector<std::array<TaggedCorner, 3>> normal_triangles;
    std::vector<ObjMaterialStatement> materials;
    std::size_t newlines = 0;
    std::size_t faces = 0;
    std::optional<ObjChunkError> error;  ///< the chunk's first bad line
};

/// What is known once every chunk is counted: lets parse_obj_chunk check the
/// index ranges itself, with the messages of a sequential reader.
struct ObjIndexRange {
    std::int64_t vertices_before = 0;  ///< `v` lines in the chunks before this one
    std::int64_t vertices_in_file = 0;
    std::int64_t texcoords_before = 0;  ///< `vt` lines likewise
    std::int64_t texcoords_in_file = 0;
    std::int64_t normals_before = 0;  ///< `vn` lines likewise
    std::int64_t normals_in_file = 0;
};

/// Parses `text` (whole lines). With `range`, also stops at the first index out
/// of range; without, indices are only checked for syntax and zero.
ObjChunk parse_obj_chunk(std::string_view text, const ObjIndexRange* range = nullptr);

/// The 1-based vertex a tagged corner names, given the vertices before its chunk.
inline std::int64_t resolve_corner(TaggedCorner corner, std::int64_t vertices_before) {
    const std::int64_t relative = corner & 1;
    const std::int64_t value = (corner - relative) / 2;
    return relative ? vertices_before + value : value;
}

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_OBJ_CHUNK_HPP
