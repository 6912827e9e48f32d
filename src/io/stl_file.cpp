// STL, binary (80-byte header, a triangle count, 50 bytes per triangle) or
// ASCII (solid / facet normal / outer loop / vertex x3 / endloop / endfacet).
// STL repeats every corner; corners at the same position are welded into one
// vertex, numbered in order of first appearance, so the renderer's vertex
// normals come out smooth.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <fast_float/fast_float.h>

#include "mesh_readers.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

constexpr std::size_t binary_header_bytes = 84;
constexpr std::size_t binary_triangle_bytes = 50;

std::vector<glm::dvec3> read_binary_corners(std::string_view bytes, const std::string& path) {
    if (bytes.size() < binary_header_bytes) {
        throw FileError(path + ": " + std::to_string(bytes.size()) +
                        " bytes; a binary STL needs at least 84 (header and triangle count)");
    }
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    const std::uint64_t needed = binary_header_bytes + std::uint64_t(count) * binary_triangle_bytes;
    if (needed > bytes.size()) {
        throw FileError(path + ": byte 80: the binary STL declares " + std::to_string(count) + " triangles (" +
                        std::to_string(needed) + " bytes), but the file has " + std::to_string(bytes.size()) +
                        " bytes (a truncated file?)");
    }
    std::vector<glm::dvec3> corners(std::size_t(count) * 3);
    for (std::size_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + binary_header_bytes + t * binary_triangle_bytes;
        float values[9];
        std::memcpy(values, record + 12, sizeof values);  // after the facet normal
        for (int k = 0; k < 9; ++k) {
            if (!std::isfinite(values[k])) {
                throw FileError(path + ": triangle " + std::to_string(t) + " (byte " +
                                std::to_string(binary_header_bytes + t * binary_triangle_bytes + 12 + 4 * k) +
                                "): coordinate is not a finite number");
            }
        }
        for (int c = 0; c < 3; ++c) corners[3 * t + c] = {values[3 * c], values[3 * c + 1], values[3 * c + 2]};
    }
    return corners;
}

/// ASCII STL read word by word: `vertex x y z` adds a corner; every `endloop`
/// must close exactly three. Other keywords (normals, names) are skipped.
class AsciiStl {
public:
    AsciiStl(std::string_view text, const std::string& path) : text_(text), path_(path) {}

    std::vector<glm::dvec3> corners() {
        std::vector<glm::dvec3> corners;
        std::size_t in_loop = 0;
        for (std::string_view word = next(); !word.empty(); word = next()) {
            if (word == "vertex") {
                glm::dvec3 p;
                for (int k = 0; k < 3; ++k) p[k] = number("xyz"[k]);
                corners.push_back(p);
                ++in_loop;
            } else if (word == "endloop") {
                if (in_loop != 3) fail("a facet with " + std::to_string(in_loop) + " vertices; expected 3");
                in_loop = 0;
            }
        }
        if (in_loop != 0) fail("the file ends inside a facet; expected 'endloop' (a truncated file?)");
        return corners;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw FileError(path_ + ":" + std::to_string(line_) + ": " + what);
    }

    std::string_view next() {
        while (offset_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[offset_]))) {
            if (text_[offset_++] == '\n') ++line_;
        }
        const std::size_t start = offset_;
        while (offset_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[offset_]))) ++offset_;
        return text_.substr(start, offset_ - start);
    }

    double number(char axis) {
        const std::string_view word = next();
        double value = 0.0;
        const auto [stop, status] = fast_float::from_chars(word.data(), word.data() + word.size(), value);
        if (word.empty() || status != std::errc() || stop != word.data() + word.size()) {
            fail(std::string("vertex ") + axis + ": expected a number, got '" + std::string(word) + "'");
        }
        if (!std::isfinite(value)) {
            fail(std::string("vertex ") + axis + ": expected a finite number, got '" + std::string(word) + "'");
        }
        return value;
    }

    std::string_view text_;
    const std::string& path_;
    std::size_t offset_ = 0;
    std::size_t line_ = 1;
};

bool looks_ascii(std::string_view bytes) {
    std::size_t start = 0;
    while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
    if (bytes.substr(start, 5) != "solid") return false;
    // A binary header may start with "solid" too: its size then matches its count.
    if (bytes.size() >= binary_header_bytes) {
        std::uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (binary_header_bytes + std::uint64_t(count) * binary_triangle_bytes == bytes.size()) return false;
    }
    return true;
}

}  // namespace

Mesh weld_corners(const std::vector<glm::dvec3>& corners) {
    // Open addressing over a power-of-two table at most half full: each corner
    // finds the first earlier corner at its position, or becomes a new vertex.
    std::size_t capacity = 16;
    while (capacity < 2 * corners.size()) capacity *= 2;
    constexpr std::uint32_t empty = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> slots(capacity, empty);  // vertex numbers
    const auto hash = [](const glm::dvec3& p) {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (int k = 0; k < 3; ++k) {
            const double value = p[k] + 0.0;  // -0 and +0 are one position
            std::uint64_t bits = 0;
            std::memcpy(&bits, &value, sizeof bits);
            h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
            h ^= h >> 32;
        }
        return h;
    };
    Mesh mesh;
    mesh.triangles.resize(corners.size() / 3);
    for (std::size_t c = 0; c < corners.size(); ++c) {
        std::size_t slot = hash(corners[c]) & (capacity - 1);
        while (slots[slot] != empty && mesh.positions[slots[slot]] != corners[c]) slot = (slot + 1) & (capacity - 1);
        if (slots[slot] == empty) {
            slots[slot] = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(corners[c]);
        }
        mesh.triangles[c / 3][c % 3] = slots[slot];
    }
    return mesh;
}

MeshFile parse_stl(std::string_view bytes, const std::string& path) {
    const std::vector<glm::dvec3> corners =
        looks_ascii(bytes) ? AsciiStl(bytes, path).corners() : read_binary_corners(bytes, path);
    if (corners.empty()) throw FileError(path + ": no triangles; expected a mesh with at least one");
    if (corners.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw FileError(path + ": more than 4294967295 corners");
    }
    MeshFile file;
    file.mesh = weld_corners(corners);
    check_mesh(file.mesh, path);
    return file;
}

}  // namespace phongrast::io
