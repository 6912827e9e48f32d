// The previous OBJ path, verbatim in what it does (see legacy_obj_reader.hpp):
// the line check of the old obj_check.cpp, then tinyobjloader.
#include "legacy_obj_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "tiny_obj_loader_double.hpp"

namespace phongrast_bench {
namespace {

struct Line {
    std::size_t number = 0;
    std::string_view text;
};

std::vector<Line> split_lines(const std::string& text) {
    std::vector<Line> lines;
    std::size_t start = 0;
    std::size_t number = 1;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back({number++, line});
        start = end + 1;
    }
    return lines;
}

std::vector<std::string> split_words(std::string_view line) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (i >= line.size() || line[i] == '#') break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        words.emplace_back(line.substr(start, i - start));
    }
    return words;
}

class Checker {
public:
    explicit Checker(const std::string& path) : path_(path) {}

    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw std::runtime_error(path_ + ":" + std::to_string(line) + ": " + what);
    }

    glm::dvec3 check_vertex(const Line& line, const std::vector<std::string>& words) const {
        // v x y z [w] or v x y z r g b: 3, 4 or 6 numbers.
        const std::size_t count = words.size() - 1;
        if (count != 3 && count != 4 && count != 6) {
            fail(line.number, "expected 'v x y z' or 'v x y z r g b', got " + std::to_string(count) +
                                  " numbers");
        }
        static const char* const names[] = {"x", "y", "z", "r", "g", "b"};
        glm::dvec3 position(0.0);
        for (std::size_t i = 1; i < words.size(); ++i) {
            const std::string& word = words[i];
            char* end = nullptr;
            errno = 0;
            const double value = std::strtod(word.c_str(), &end);
            const char* name = count == 4 && i == 4 ? "w" : names[i - 1];
            if (end == word.c_str() || *end != '\0') {
                fail(line.number, "vertex " + std::string(name) + ": expected a number, got '" + word + "'");
            }
            if (!std::isfinite(value)) {
                fail(line.number, "vertex " + std::string(name) + ": expected a finite number, got '" + word + "'");
            }
            if (i <= 3) position[static_cast<int>(i - 1)] = value;
        }
        return position;
    }

    void check_face(const Line& line, const std::vector<std::string>& words,
                    std::int64_t vertices_so_far, std::int64_t vertices_in_file) const {
        const std::size_t corners = words.size() - 1;
        if (corners < 3) {
            fail(line.number, "face with " + std::to_string(corners) +
                                  " vertices; expected at least 3");
        }
        for (std::size_t i = 1; i < words.size(); ++i) {
            const std::string& word = words[i];
            const std::string vertex_part = word.substr(0, word.find('/'));
            char* end = nullptr;
            errno = 0;
            const long long index = std::strtoll(vertex_part.c_str(), &end, 10);
            if (vertex_part.empty() || *end != '\0' || errno == ERANGE) {
                fail(line.number, "face vertex '" + word + "': expected an integer vertex index");
            }
            if (index == 0) {
                fail(line.number, "face vertex index 0: OBJ indices start at 1 (or are negative, counting back)");
            }
            // Negative indices count back from the vertices read so far; positive
            // ones may name any vertex of the file (tinyobjloader allows forward references).
            const std::int64_t resolved = index > 0 ? index : vertices_so_far + index + 1;
            const std::int64_t limit = index > 0 ? vertices_in_file : vertices_so_far;
            if (resolved < 1 || resolved > limit) {
                std::ostringstream message;
                message << "face vertex index " << index << " is out of range: ";
                if (index > 0) {
                    message << "the file has " << vertices_in_file << " vertices";
                } else {
                    message << "only " << vertices_so_far << " vertices precede this line";
                }
                fail(line.number, message.str());
            }
        }
    }

private:
    std::string path_;
};

bool starts_with_keyword(const std::vector<std::string>& words, const char* keyword) {
    return !words.empty() && words.front() == keyword;
}

}  // namespace

std::vector<glm::dvec3> check_obj_text(const std::string& text, const std::string& path) {
    const std::vector<Line> lines = split_lines(text);
    std::int64_t vertices_in_file = 0;
    for (const Line& line : lines) {
        if (starts_with_keyword(split_words(line.text), "v")) ++vertices_in_file;
    }
    const Checker checker(path);
    std::int64_t vertices_so_far = 0;
    std::int64_t faces = 0;
    std::vector<glm::dvec3> positions;
    positions.reserve(static_cast<std::size_t>(vertices_in_file));
    for (const Line& line : lines) {
        const std::vector<std::string> words = split_words(line.text);
        if (starts_with_keyword(words, "v")) {
            positions.push_back(checker.check_vertex(line, words));
            ++vertices_so_far;
        } else if (starts_with_keyword(words, "f")) {
            checker.check_face(line, words, vertices_so_far, vertices_in_file);
            ++faces;
        }
    }
    if (faces == 0) {
        throw std::runtime_error(path + ": no faces ('f' lines); expected a mesh with at least one triangle");
    }
    return positions;
}


phongrast::Mesh legacy_read_obj(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream contents;
    contents << in.rdbuf();
    const std::string text = contents.str();
    std::vector<glm::dvec3> exact_positions = check_obj_text(text, path);

    tinyobj::attrib_t attributes;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings;
    std::string errors;
    std::istringstream stream(text);
    tinyobj::MaterialFileReader material_reader("./");
    if (!tinyobj::LoadObj(&attributes, &shapes, &materials, &warnings, &errors, &stream, &material_reader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/true)) {
        throw std::runtime_error(path + ": cannot parse OBJ: " + errors);
    }
    phongrast::Mesh mesh;
    const std::size_t vertex_count = attributes.vertices.size() / 3;
    mesh.positions = std::move(exact_positions);
    if (attributes.colors.size() == attributes.vertices.size()) {
        mesh.colors.reserve(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i) {
            mesh.colors.emplace_back(static_cast<float>(attributes.colors[3 * i]),
                                     static_cast<float>(attributes.colors[3 * i + 1]),
                                     static_cast<float>(attributes.colors[3 * i + 2]));
        }
    }
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t corner = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            const auto vertex = [&](std::size_t k) {
                return static_cast<std::uint32_t>(shape.mesh.indices[corner + k].vertex_index);
            };
            for (std::size_t k = 1; k + 1 < corners; ++k) mesh.triangles.push_back({vertex(0), vertex(k), vertex(k + 1)});
            corner += corners;
        }
    }
    phongrast::validate_mesh(mesh);
    return mesh;
}

}  // namespace phongrast_bench
