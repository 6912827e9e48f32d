#include "obj_chunk.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

#include <fast_float/fast_float.h>

namespace phongrast::io {
namespace {

constexpr bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// Indices beyond this are out of range in any file phongrast can hold
/// (at most 2^32 vertices); clamping keeps the tagged arithmetic from overflowing.
constexpr std::int64_t index_limit = std::int64_t(1) << 40;

/// The next word of [p, end): blanks skipped; empty at the end or at a '#' comment.
std::string_view next_word(const char*& p, const char* end) {
    while (p < end && is_blank(*p)) ++p;
    if (p == end || *p == '#') {
        p = end;
        return {};
    }
    const char* start = p;
    while (p < end && !is_blank(*p)) ++p;
    return {start, static_cast<std::size_t>(p - start)};
}

/// Exactly std::strtod's reading of the whole word (what the format has always
/// accepted), through fast_float's from_chars, which is correctly rounded,
/// inline and several times faster than strtod (and than libstdc++'s
/// from_chars); strtod only for what it does not take whole (a leading '+',
/// hexadecimal).
bool parse_double(std::string_view word, double& value) {
    const char* end = word.data() + word.size();
    const auto [stop, status] = fast_float::from_chars(word.data(), end, value);
    if (status == std::errc() && stop == end) return true;
    const std::string copy(word);
    char* copy_end = nullptr;
    value = std::strtod(copy.c_str(), &copy_end);
    return copy_end != copy.c_str() && *copy_end == '\0';
}

/// Exactly std::strtoll's reading of a whole corner index ("-3" of "-3/1/2"),
/// false for anything else or outside 64-bit range.
bool parse_index(std::string_view digits, std::int64_t& value) {
    std::size_t i = 0;
    const bool negative = !digits.empty() && digits[0] == '-';
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) ++i;
    if (i == digits.size()) return false;
    std::uint64_t magnitude = 0;
    const std::uint64_t limit = negative ? std::uint64_t(1) << 63 : (std::uint64_t(1) << 63) - 1;
    for (; i < digits.size(); ++i) {
        const unsigned digit = static_cast<unsigned char>(digits[i]) - unsigned('0');
        if (digit > 9 || magnitude > (limit - digit) / 10) return false;
        magnitude = magnitude * 10 + digit;
    }
    value = negative ? static_cast<std::int64_t>(0 - magnitude) : static_cast<std::int64_t>(magnitude);
    return true;
}

class ChunkParser {
public:
    explicit ChunkParser(const ObjIndexRange* range) : range_(range) {}

    ObjChunk& chunk() { return chunk_; }
    bool failed() const { return chunk_.error.has_value(); }

    void line(const char* p, const char* end, std::size_t number) {
        line_ = number;
        while (p < end && is_blank(*p)) ++p;
        const auto keyword = [&](const char* word, std::size_t length) {
            return static_cast<std::size_t>(end - p) >= length && std::memcmp(p, word, length) == 0 &&
                   (p + length == end || is_blank(p[length]));
        };
        if (keyword("v", 1)) {
            if (failed()) return count_vertex();
            vertex(p + 1, end);
        } else if (failed()) {
            return;
        } else if (keyword("f", 1)) {
            face(p + 1, end);
        } else if (keyword("usemtl", 6) || keyword("mtllib", 6)) {
            material(p[0] == 'm', p + 6, end);
        }
    }

private:
    void fail(std::string message) { chunk_.error = ObjChunkError{line_, std::move(message)}; }

    void count_vertex() {
        chunk_.positions.emplace_back(0.0);
        chunk_.colors.emplace_back(1.0f);
    }

    void vertex(const char* p, const char* end) {
        // v x y z [w] or v x y z r g b: 3, 4 or 6 numbers.
        std::string_view words[6];
        std::size_t count = 0;
        for (std::string_view word = next_word(p, end); !word.empty(); word = next_word(p, end)) {
            if (count < 6) words[count] = word;
            ++count;
        }
        count_vertex();
        if (count != 3 && count != 4 && count != 6) {
            return fail("expected 'v x y z' or 'v x y z r g b', got " + std::to_string(count) + " numbers");
        }
        static const char* const names[] = {"x", "y", "z", "r", "g", "b"};
        double values[6];
        for (std::size_t i = 0; i < count; ++i) {
            const std::string name = count == 4 && i == 3 ? "w" : names[i];
            if (!parse_double(words[i], values[i])) {
                return fail("vertex " + name + ": expected a number, got '" + std::string(words[i]) + "'");
            }
            if (!std::isfinite(values[i])) {
                return fail("vertex " + name + ": expected a finite number, got '" + std::string(words[i]) + "'");
            }
            if (count == 6 && i >= 3 && std::abs(values[i]) > std::numeric_limits<float>::max()) {
                return fail("vertex " + name + ": expected a colour within float range, got '" + std::string(words[i]) + "'");
            }
        }
        chunk_.positions.back() = {values[0], values[1], values[2]};
        if (count == 6) {
            chunk_.colors.back() = {static_cast<float>(values[3]), static_cast<float>(values[4]),
                                    static_cast<float>(values[5])};
        }
    }

    /// Checks one corner; returns the problem's message, or an empty string.
    std::string corner(std::string_view word, TaggedCorner& tagged) const {
        const std::string_view vertex_part = word.substr(0, word.find('/'));
        std::int64_t index = 0;
        if (!parse_index(vertex_part, index)) {
            return "face vertex '" + std::string(word) + "': expected an integer vertex index";
        }
        if (index == 0) return "face vertex index 0: OBJ indices start at 1 (or are negative, counting back)";
        const auto vertices_so_far = static_cast<std::int64_t>(chunk_.positions.size());
        if (range_ != nullptr) {
            // Negative indices count back from the vertices read so far; positive
            // ones may name any vertex of the file (forward references are allowed).
            const std::int64_t so_far = range_->vertices_before + vertices_so_far;
            const std::int64_t resolved = index > 0 ? index : so_far + index + 1;
            const std::int64_t limit = index > 0 ? range_->vertices_in_file : so_far;
            if (resolved < 1 || resolved > limit) {
                std::ostringstream message;
                message << "face vertex index " << index << " is out of range: ";
                if (index > 0) {
                    message << "the file has " << range_->vertices_in_file << " vertices";
                } else {
                    message << "only " << so_far << " vertices precede this line";
                }
                return message.str();
            }
        }
        tagged = index > 0 ? 2 * std::min(index, index_limit)
                           : 2 * (vertices_so_far + std::max(index, -index_limit) + 1) + 1;
        return {};
    }

    void face(const char* p, const char* end) {
        corners_.clear();
        std::string problem;
        for (std::string_view word = next_word(p, end); !word.empty(); word = next_word(p, end)) {
            TaggedCorner tagged = 0;
            if (problem.empty()) problem = corner(word, tagged);
            corners_.push_back(tagged);
        }
        if (corners_.size() < 3) {
            return fail("face with " + std::to_string(corners_.size()) + " vertices; expected at least 3");
        }
        if (!problem.empty()) return fail(std::move(problem));
        for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {  // the contract's fan: v0 v_k v_k+1
            chunk_.triangles.push_back({corners_[0], corners_[k], corners_[k + 1]});
        }
        ++chunk_.faces;
    }

    void material(bool is_library, const char* p, const char* end) {
        ObjMaterialStatement statement;
        statement.is_library = is_library;
        statement.line = line_;
        statement.faces_before = chunk_.faces;
        if (is_library) {
            while (p < end && is_blank(*p)) ++p;
            statement.argument.assign(p, end);
        } else {
            statement.argument = std::string(next_word(p, end));
        }
        chunk_.materials.push_back(std::move(statement));
    }

    const ObjIndexRange* range_;
    ObjChunk chunk_;
    std::vector<TaggedCorner> corners_;  // reused by every face: no allocation per line
    std::size_t line_ = 0;
};

}  // namespace

ObjChunk parse_obj_chunk(std::string_view text, const ObjIndexRange* range) {
    ChunkParser parser(range);
    // Room for the most a chunk can hold ("v 0 0 0" and "f 1 2 3" take 8 bytes
    // each; polygons may still grow the triangles): no regrowth copies, and pages
    // never written are never touched.
    const std::size_t most = text.size() / 8 + 1;
    parser.chunk().positions.reserve(most);
    parser.chunk().colors.reserve(most);
    parser.chunk().triangles.reserve(most);
    const char* p = text.data();
    const char* const end = p + text.size();
    std::size_t line = 1;
    while (p < end) {
        const auto* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        const char* line_end = newline != nullptr ? newline : end;
        const char* text_end = line_end;
        if (text_end > p && text_end[-1] == '\r') --text_end;
        parser.line(p, text_end, line);
        if (newline == nullptr) break;
        ++line;
        p = newline + 1;
    }
    // After the first error the chunk still counts its `v` lines: the file's
    // vertex count appears in the messages of later chunks' index errors.
    ObjChunk& chunk = parser.chunk();
    chunk.newlines = line - 1;
    return std::move(chunk);
}

}  // namespace phongrast::io
