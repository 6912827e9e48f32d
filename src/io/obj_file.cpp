#include "phongrast/io/obj_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <limits>
#include <sstream>

#include <tbb/parallel_for.h>

#include "file_bytes.hpp"
#include "mesh_readers.hpp"
#include "obj_chunk.hpp"
#include "obj_materials.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/text_file.hpp"

namespace phongrast::io {
namespace {

/// Chunks of about this many bytes, cut after a newline: large enough that
/// the per-chunk bookkeeping is noise, small enough to balance the cores.
constexpr std::size_t chunk_bytes = std::size_t(1) << 20;

/// body(i) for every chunk: on the calling thread for a single chunk (small
/// files pay no task overhead), else in parallel.
template <class Body>
void for_each_chunk(std::size_t count, const Body& body) {
    if (count == 1) {
        body(std::size_t(0));
    } else {
        tbb::parallel_for(std::size_t(0), count, body, tbb::simple_partitioner());
    }
}

std::vector<std::string_view> split_into_chunks(std::string_view text) {
    std::vector<std::string_view> chunks;
    std::size_t start = 0;
    while (start < text.size() || chunks.empty()) {
        std::size_t cut = text.size();
        if (text.size() - start > 2 * chunk_bytes) {
            const std::size_t newline = text.find('\n', start + chunk_bytes);
            cut = newline == std::string_view::npos ? text.size() : newline + 1;
        }
        chunks.push_back(text.substr(start, cut - start));
        start = cut;
    }
    return chunks;
}

/// Where each chunk starts in the file: lines, `v` lines and faces before it.
struct ChunkStarts {
    std::vector<std::size_t> lines;
    std::vector<std::int64_t> vertices;
    std::vector<std::size_t> faces;
    std::vector<std::size_t> triangles;
    std::vector<std::int64_t> texcoords;
    std::vector<std::int64_t> normals;
    std::int64_t vertices_in_file = 0;
    std::int64_t texcoords_in_file = 0;
    std::int64_t normals_in_file = 0;
    bool any_texcoord_corner = false;
    bool any_normal_corner = false;
    std::size_t faces_in_file = 0;
    std::size_t triangles_in_file = 0;
};

ChunkStarts count_chunk_starts(const std::vector<ObjChunk>& chunks) {
    ChunkStarts starts;
    std::size_t lines = 0;
    for (const ObjChunk& chunk : chunks) {
        starts.lines.push_back(lines);
        starts.vertices.push_back(starts.vertices_in_file);
        starts.faces.push_back(starts.faces_in_file);
        starts.triangles.push_back(starts.triangles_in_file);
        starts.texcoords.push_back(starts.texcoords_in_file);
        starts.normals.push_back(starts.normals_in_file);
        lines += chunk.newlines;
        starts.texcoords_in_file += static_cast<std::int64_t>(chunk.texcoords.size());
        starts.normals_in_file += static_cast<std::int64_t>(chunk.normals.size());
        starts.any_texcoord_corner = starts.any_texcoord_corner || !chunk.texcoord_triangles.empty();
        starts.any_normal_corner = starts.any_normal_corner || !chunk.normal_triangles.empty();
        starts.vertices_in_file += static_cast<std::int64_t>(chunk.positions.size());
        starts.faces_in_file += chunk.faces;
        starts.triangles_in_file += chunk.triangles.size();
    }
    return starts;
}

/// True when every corner of `triangles` (kNoCorner aside) names one of the file's items.
bool corners_in_range(const std::vector<std::array<TaggedCorner, 3>>& triangles, std::int64_t before,
                      std::int64_t in_file) {
    for (const auto& triangle : triangles) {
        for (const TaggedCorner corner : triangle) {
            if (corner == kNoCorner) continue;  // only vt/vn corners are ever kNoCorner
            const std::int64_t item = resolve_corner(corner, before);
            if (item < 1 || item > in_file) return false;
        }
    }
    return true;
}

bool chunk_in_range(const ObjChunk& chunk, const ChunkStarts& starts, std::size_t i) {
    return corners_in_range(chunk.triangles, starts.vertices[i], starts.vertices_in_file) &&
           corners_in_range(chunk.texcoord_triangles, starts.texcoords[i], starts.texcoords_in_file) &&
           corners_in_range(chunk.normal_triangles, starts.normals[i], starts.normals_in_file);
}

/// Throws the file's first error, in line order, as a sequential reader would:
/// the first chunk with a bad line or index is parsed again, knowing the
/// vertices before it, for the precise message.
void throw_first_error(const std::vector<std::string_view>& texts, const std::vector<ObjChunk>& chunks,
                       const ChunkStarts& starts, const std::string& path) {
    std::vector<char> bad(chunks.size(), 0);
    for_each_chunk(chunks.size(), [&](std::size_t i) {
        bad[i] = chunks[i].error.has_value() || !chunk_in_range(chunks[i], starts, i);
    });
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        if (!bad[i]) continue;
        const ObjIndexRange range{starts.vertices[i],  starts.vertices_in_file, starts.texcoords[i],
                                  starts.texcoords_in_file, starts.normals[i], starts.normals_in_file};
        const ObjChunk checked = parse_obj_chunk(texts[i], &range);
        const ObjChunkError error = checked.error.value_or(ObjChunkError{1, "unreadable face"});
        throw FileError(path + ":" + std::to_string(starts.lines[i] + error.line) + ": " + error.message);
    }
    if (starts.faces_in_file == 0) {
        throw FileError(path + ": no faces ('f' lines); expected a mesh with at least one triangle");
    }
    const std::pair<std::int64_t, const char*> counts[] = {{starts.vertices_in_file, " vertices"},
                                                           {starts.texcoords_in_file, " texture coordinates"},
                                                           {starts.normals_in_file, " normals"}};
    for (const auto& [count, what] : counts) {
        if (count >= std::int64_t(std::numeric_limits<std::uint32_t>::max())) {
            throw FileError(path + ": " + std::to_string(count) + what + "; expected fewer than 4294967295");
        }
    }
}

/// `out` (one per triangle of the file) from the chunks' tagged `vt` or `vn`
/// corners; chunks without any give kNoIndex corners.
void resolve_corner_indices(std::vector<Triangle>& out, const std::vector<ObjChunk>& chunks, const ChunkStarts& starts,
                            std::vector<std::array<TaggedCorner, 3>> ObjChunk::*per_corner,
                            const std::vector<std::int64_t>& before) {
    out.resize(starts.triangles_in_file);
    for_each_chunk(chunks.size(), [&](std::size_t i) {
        const auto& tagged = chunks[i].*per_corner;
        Triangle* first = out.data() + starts.triangles[i];
        if (tagged.empty()) {
            std::fill(first, first + chunks[i].triangles.size(), Triangle{kNoIndex, kNoIndex, kNoIndex});
            return;
        }
        for (const auto& triangle : tagged) {
            for (int k = 0; k < 3; ++k) {
                (*first)[k] = triangle[k] == kNoCorner
                                  ? kNoIndex
                                  : static_cast<std::uint32_t>(resolve_corner(triangle[k], before[i]) - 1);
            }
            ++first;
        }
    });
}

/// Texture coordinates and file normals, with their per-corner indices, when any face names them.
void assemble_corner_attributes(Mesh& mesh, const std::vector<ObjChunk>& chunks, const ChunkStarts& starts) {
    if (starts.any_texcoord_corner) {
        mesh.texcoords.reserve(static_cast<std::size_t>(starts.texcoords_in_file));
        for (const ObjChunk& chunk : chunks) mesh.texcoords.insert(mesh.texcoords.end(), chunk.texcoords.begin(), chunk.texcoords.end());
        resolve_corner_indices(mesh.texcoord_triangles, chunks, starts, &ObjChunk::texcoord_triangles, starts.texcoords);
    }
    if (starts.any_normal_corner) {
        mesh.file_normals.reserve(static_cast<std::size_t>(starts.normals_in_file));
        for (const ObjChunk& chunk : chunks) mesh.file_normals.insert(mesh.file_normals.end(), chunk.normals.begin(), chunk.normals.end());
        resolve_corner_indices(mesh.file_normal_triangles, chunks, starts, &ObjChunk::normal_triangles, starts.normals);
    }
}

Mesh assemble_mesh(const std::vector<ObjChunk>& chunks, const ChunkStarts& starts) {
    Mesh mesh;
    mesh.positions.resize(static_cast<std::size_t>(starts.vertices_in_file));
    mesh.colors.resize(mesh.positions.size());
    mesh.triangles.resize(starts.triangles_in_file);
    for_each_chunk(chunks.size(), [&](std::size_t i) {
        const ObjChunk& chunk = chunks[i];
        const auto vertex_start = static_cast<std::ptrdiff_t>(starts.vertices[i]);
        std::copy(chunk.positions.begin(), chunk.positions.end(), mesh.positions.begin() + vertex_start);
        std::copy(chunk.colors.begin(), chunk.colors.end(), mesh.colors.begin() + vertex_start);
        Triangle* out = mesh.triangles.data() + starts.triangles[i];
        for (const auto& triangle : chunk.triangles) {
            for (int k = 0; k < 3; ++k) {
                (*out)[k] = static_cast<std::uint32_t>(resolve_corner(triangle[k], starts.vertices[i]) - 1);
            }
            ++out;
        }
    });
    assemble_corner_attributes(mesh, chunks, starts);
    return mesh;
}

std::vector<ObjMaterialUse> material_uses(const std::vector<ObjChunk>& chunks, const ChunkStarts& starts) {
    std::vector<ObjMaterialUse> uses;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        for (const ObjMaterialStatement& statement : chunks[i].materials) {
            uses.push_back({statement.is_library, statement.argument, starts.lines[i] + statement.line,
                            starts.faces[i] + statement.faces_before,
                            starts.triangles[i] + statement.triangles_before});
        }
    }
    return uses;
}

}  // namespace

MeshFile parse_obj(std::string_view text, const std::string& path) {
    const std::vector<std::string_view> texts = split_into_chunks(text);
    std::vector<ObjChunk> chunks(texts.size());
    for_each_chunk(texts.size(), [&](std::size_t i) { chunks[i] = parse_obj_chunk(texts[i]); });
    const ChunkStarts starts = count_chunk_starts(chunks);
    throw_first_error(texts, chunks, starts, path);

    ObjFile result;
    result.mesh = assemble_mesh(chunks, starts);
    ObjMaterials materials = read_obj_materials(material_uses(chunks, starts), starts.triangles_in_file, path);
    result.mesh.materials = std::move(materials.materials);
    result.mesh.face_materials = std::move(materials.face_materials);
    result.material = materials.first;
    result.material_name = std::move(materials.first_name);
    result.warnings = std::move(materials.warnings);
    result.side_files = std::move(materials.side_files);
    warn_textured_faces_without_texcoords(result, path);
    check_mesh(result.mesh, path);
    return result;
}

ObjFile read_obj(const std::string& path) { return parse_obj(FileBytes::read(path, "mesh").view(), path); }

void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment,
               int significant_digits) {
    replace_file_atomically(path, [&](const std::string& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) throw FileError(path + ": cannot write: " + std::strerror(errno));
        std::istringstream comment_lines(comment);
        std::string line;
        while (std::getline(comment_lines, line)) std::fprintf(file, "# %s\n", line.c_str());
        const bool colored = mesh.colors.size() == mesh.positions.size();
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3& p = mesh.positions[i];
            if (colored) {
                const glm::vec3& c = mesh.colors[i];
                std::fprintf(file, "v %.*g %.*g %.*g %.4f %.4f %.4f\n", significant_digits, p.x,
                             significant_digits, p.y, significant_digits, p.z, double(c.r), double(c.g),
                             double(c.b));
            } else {
                std::fprintf(file, "v %.*g %.*g %.*g\n", significant_digits, p.x, significant_digits, p.y,
                             significant_digits, p.z);
            }
        }
        for (const Triangle& t : mesh.triangles) {
            std::fprintf(file, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        }
        const bool failed = std::ferror(file) != 0;
        if (std::fclose(file) != 0 || failed) throw FileError(path + ": write failed: " + std::strerror(errno));
    });
}

}  // namespace phongrast::io
