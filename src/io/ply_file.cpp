// PLY bodies, ASCII or binary in either byte order: `vertex` x y z, optional
// red green blue (uchar /255, other integers by their maximum, floats as they
// are) and optional nx ny nz (the file's normals, per vertex), `face` vertex_indices (or vertex_index) lists fanned into triangles;
// every other element and property is read past.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include <fast_float/fast_float.h>

#include "mesh_readers.hpp"
#include "phongrast/io/error.hpp"
#include "ply_header.hpp"

namespace phongrast::io {
namespace {

/// Values of a binary body: bounds-checked, in the file's byte order.
class BinarySource {
public:
    BinarySource(std::string_view bytes, std::size_t offset, bool big_endian)
        : bytes_(bytes), offset_(offset), value_start_(offset), swap_(big_endian) {}

    /// Where the value last read (or failed) starts.
    std::string place() const { return "byte " + std::to_string(value_start_); }
    std::size_t remaining() const { return bytes_.size() - offset_; }
    /// The least a binary element takes.
    static std::size_t least_bytes(const PlyElement& element) { return element.least_bytes(); }

    /// False, with what went wrong, when the value cannot be read.
    bool read(PlyType type, double& value, std::string& problem) {
        value_start_ = offset_;
        const std::size_t size = size_of(type);
        if (size > remaining()) {
            problem = "the file ends at byte " + std::to_string(bytes_.size()) + "; expected " +
                      std::to_string(size) + " more bytes (a truncated file?)";
            return false;
        }
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + offset_, size);
        offset_ += size;
        if (swap_) std::reverse(raw, raw + size);
        value = decode(type, raw);
        return true;
    }

private:
    static double decode(PlyType type, const unsigned char* raw) {
        const auto as = [raw](auto value) {
            std::memcpy(&value, raw, sizeof value);
            return static_cast<double>(value);
        };
        switch (type) {
            case PlyType::int8: return as(std::int8_t{});
            case PlyType::uint8: return as(std::uint8_t{});
            case PlyType::int16: return as(std::int16_t{});
            case PlyType::uint16: return as(std::uint16_t{});
            case PlyType::int32: return as(std::int32_t{});
            case PlyType::uint32: return as(std::uint32_t{});
            case PlyType::float32: return as(float{});
            case PlyType::float64: return as(double{});
        }
        return 0.0;
    }

    std::string_view bytes_;
    std::size_t offset_;
    std::size_t value_start_;
    bool swap_;
};

/// Values of an ASCII body: whitespace-separated words, lines counted.
class AsciiSource {
public:
    AsciiSource(std::string_view bytes, std::size_t offset, std::size_t line)
        : bytes_(bytes), offset_(offset), line_(line) {}

    std::string place() const { return "line " + std::to_string(line_); }
    std::size_t remaining() const { return bytes_.size() - offset_; }
    /// The least an ASCII element takes: one character per value.
    static std::size_t least_bytes(const PlyElement& element) { return element.properties.size(); }

    bool read(PlyType type, double& value, std::string& problem) {
        while (offset_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[offset_]))) {
            if (bytes_[offset_++] == '\n') ++line_;
        }
        const std::size_t start = offset_;
        while (offset_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[offset_]))) ++offset_;
        const char* first = bytes_.data() + start;
        const char* last = bytes_.data() + offset_;
        if (first == last) {
            problem = "the file ends; expected a number (a truncated file?)";
            return false;
        }
        const bool integer = type != PlyType::float32 && type != PlyType::float64;
        const auto [stop, status] = fast_float::from_chars(first, last, value);
        if (status != std::errc() || stop != last || (integer && value != std::floor(value))) {
            problem = std::string("expected ") + (integer ? "an integer" : "a number") + ", got '" +
                      std::string(first, last) + "'";
            return false;
        }
        return true;
    }

private:
    std::string_view bytes_;
    std::size_t offset_;
    std::size_t line_;
};

double color_scale(PlyType type) {
    switch (type) {
        case PlyType::uint8: return 1.0 / 255.0;
        case PlyType::uint16: return 1.0 / 65535.0;
        case PlyType::int8: return 1.0 / 127.0;
        case PlyType::int16: return 1.0 / 32767.0;
        case PlyType::int32: return 1.0 / 2147483647.0;
        case PlyType::uint32: return 1.0 / 4294967295.0;
        default: return 1.0;
    }
}

template <class Source>
class PlyBody {
public:
    PlyBody(const PlyHeader& header, Source& source, const std::string& path)
        : header_(header), source_(source), path_(path) {}

    MeshFile read() {
        const PlyElement* vertices = find("vertex");
        if (vertices == nullptr) throw FileError(path_ + ": no 'vertex' element in the header; expected one");
        vertex_count_ = vertices->count;
        for (const PlyElement& element : header_.elements) {
            element_ = &element;
            check_count(element);
            if (element.name == "vertex") {
                read_vertices(element);
            } else if (element.name == "face") {
                read_faces(element);
            } else {
                for (index_ = 0; index_ < element.count; ++index_) {
                    for (const PlyProperty& property : element.properties) skip(property);
                }
            }
        }
        if (file_.mesh.triangles.empty()) {
            throw FileError(path_ + ": no faces ('face' element with vertex_indices); expected at least one triangle");
        }
        return std::move(file_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw FileError(path_ + ": " + element_->name + " " + std::to_string(index_) + " (" + source_.place() +
                        "): " + what);
    }

    const PlyElement* find(const char* name) const {
        for (const PlyElement& element : header_.elements) {
            if (element.name == name) return &element;
        }
        return nullptr;
    }

    /// Counts that the rest of the file cannot hold are errors before anything is allocated.
    void check_count(const PlyElement& element) const {
        const std::size_t least = std::max<std::size_t>(Source::least_bytes(element), 1);
        if (element.count > source_.remaining() / least) {
            throw FileError(path_ + ": element '" + element.name + "' (" + source_.place() + "): the header declares " +
                            std::to_string(element.count) + " elements of at least " + std::to_string(least) +
                            " bytes, but only " + std::to_string(source_.remaining()) + " bytes remain");
        }
    }

    double value(PlyType type) {
        double result = 0.0;
        std::string problem;
        if (!source_.read(type, result, problem)) fail(problem);
        return result;
    }

    void skip(const PlyProperty& property) {
        const double count = property.is_list ? value(property.count_type) : 1.0;
        if (count < 0) fail("list '" + property.name + "' has a negative length");
        for (double i = 0; i < count; ++i) value(property.type);
    }

    void read_vertices(const PlyElement& element) {
        static const char* const names[] = {"x", "y", "z", "red", "green", "blue", "nx", "ny", "nz"};
        std::vector<int> slots;
        bool colored = false;
        bool has_normals = false;
        for (const PlyProperty& property : element.properties) {
            int slot = -1;
            for (int i = 0; i < 9; ++i) {
                if (!property.is_list && property.name == names[i]) slot = i;
            }
            colored = colored || (slot >= 3 && slot < 6);
            has_normals = has_normals || slot >= 6;
            slots.push_back(slot);
        }
        for (int i = 0; i < 3; ++i) {
            if (std::find(slots.begin(), slots.end(), i) == slots.end()) {
                throw FileError(path_ + ": element 'vertex' has no property '" + names[i] + "'; expected x, y and z");
            }
        }
        Mesh& mesh = file_.mesh;
        mesh.positions.reserve(element.count);
        mesh.colors.reserve(element.count);
        if (has_normals) mesh.file_normals.reserve(element.count);
        for (index_ = 0; index_ < element.count; ++index_) {
            double v[9] = {0, 0, 0, 1, 1, 1, 0, 0, 0};
            for (std::size_t p = 0; p < slots.size(); ++p) {
                const PlyProperty& property = element.properties[p];
                if (slots[p] < 0) {
                    skip(property);
                    continue;
                }
                const double read = value(property.type);
                if (slots[p] >= 6) {  // a normal: a non-finite one takes the computed normal (the contract)
                    v[slots[p]] = read;
                    continue;
                }
                v[slots[p]] = slots[p] >= 3 ? read * color_scale(property.type) : read;
                if (!std::isfinite(v[slots[p]])) fail(std::string(names[slots[p]]) + " is not a finite number");
                if (slots[p] >= 3 && std::abs(v[slots[p]]) > std::numeric_limits<float>::max()) {
                    fail(std::string(names[slots[p]]) + " is beyond the range of a float colour");
                }
            }
            mesh.positions.emplace_back(v[0], v[1], v[2]);
            mesh.colors.emplace_back(static_cast<float>(v[3]), static_cast<float>(v[4]), static_cast<float>(v[5]));
            if (has_normals) {
                const glm::vec3 n(static_cast<float>(v[6]), static_cast<float>(v[7]), static_cast<float>(v[8]));
                const bool finite = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
                mesh.file_normals.push_back(finite ? n : glm::vec3(0.0f));
            }
        }
        if (!colored) mesh.colors.clear();
    }

    void read_faces(const PlyElement& element) {
        std::size_t list = element.properties.size();
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const PlyProperty& property = element.properties[p];
            if (property.is_list && (property.name == "vertex_indices" || property.name == "vertex_index")) list = p;
        }
        if (list == element.properties.size()) {
            throw FileError(path_ + ": element 'face' has no list property 'vertex_indices'; expected one");
        }
        file_.mesh.triangles.reserve(element.count);
        for (index_ = 0; index_ < element.count; ++index_) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                if (p == list) {
                    read_polygon(element.properties[p]);
                } else {
                    skip(element.properties[p]);
                }
            }
        }
    }

    void read_polygon(const PlyProperty& property) {
        const double count = value(property.count_type);
        if (count < 3) fail(std::to_string(static_cast<long long>(count)) + " vertices; expected at least 3");
        corners_.clear();
        for (double i = 0; i < count; ++i) {
            const double index = value(property.type);  // a float list type may hold anything
            if (!(index >= 0 && index < static_cast<double>(vertex_count_) && index == std::floor(index))) {
                char shown[32];
                std::snprintf(shown, sizeof shown, "%.17g", index);
                fail(std::string("vertex index ") + shown + " is out of range: the file has " +
                     std::to_string(vertex_count_) + " vertices");
            }
            corners_.push_back(static_cast<std::uint32_t>(index));
        }
        for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {
            file_.mesh.triangles.push_back({corners_[0], corners_[k], corners_[k + 1]});
        }
    }

    const PlyHeader& header_;
    Source& source_;
    const std::string& path_;
    const PlyElement* element_ = nullptr;
    std::uint64_t index_ = 0;
    std::uint64_t vertex_count_ = 0;
    std::vector<std::uint32_t> corners_;
    MeshFile file_;
};

}  // namespace

MeshFile parse_ply(std::string_view bytes, const std::string& path) {
    const PlyHeader header = parse_ply_header(bytes, path);
    MeshFile file;
    if (header.format == PlyFormat::ascii) {
        AsciiSource source(bytes, header.body_offset, header.body_line);
        file = PlyBody<AsciiSource>(header, source, path).read();
    } else {
        BinarySource source(bytes, header.body_offset, header.format == PlyFormat::binary_big_endian);
        file = PlyBody<BinarySource>(header, source, path).read();
    }
    if (file.mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw FileError(path + ": more than 4294967295 vertices");
    }
    // Normals per vertex: each corner takes its vertex's.
    if (!file.mesh.file_normals.empty()) file.mesh.file_normal_triangles = file.mesh.triangles;
    check_mesh(file.mesh, path);
    return file;
}

}  // namespace phongrast::io
