#include "obj_chunk.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <algorithm>
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
        // `v` and `f` first: nearly every line of a large file is one of them.
        if (keyword("v", 1)) {
            if (failed()) return count_vertex();
            vertex(p + 1, end);
        } else if (keyword("f", 1)) {
            if (!failed()) face(p + 1, end);
        } else if (keyword("vt", 2)) {
            if (failed()) return void(chunk_.texcoords.emplace_back(0.0f));
            texcoord(p + 2, end);
        } else if (keyword("vn", 2)) {
            if (failed()) return void(chunk_.normals.emplace_back(0.0f));
            normal(p + 2, end);
        } else if (failed()) {
            return;
        } else if (keyword("usemtl", 6) || keyword("mtllib", 6)) {
            material(p[0] == 'm', p + 6, end);
        }
    }

    /// Pads the per-corner index lists to one entry per triangle.
    void finish() {
        pad(chunk_.texcoord_triangles);
        pad(chunk_.normal_triangles);
    }

private:
    void fail(std::string message) { chunk_.error = ObjChunkError{line_, std::move(message)}; }

    void count_vertex() {
        chunk_.positions.emplace_back(0.0);
        chunk_.colors.emplace_back(1.0f);
    }

    // Flattened: the hot path of every `v` line keeps fast_float inline (with
    // `vt` and `vn` lines parsing numbers too, the compiler would otherwise
    // call it out of line for every coordinate).
    [[gnu::flatten]] void vertex(const char* p, const char* end) {
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

    /// Up to `most` numbers of [p, end) into `values`; returns how many there
    /// were, or -1 after failing with a message naming `names[i]` (the line's
    /// `what`).
    int numbers(const char* p, const char* end, const char* what, const char* const* names, int most,
                double* values) {
        // `most` + 1 words are kept so that "more than most" can be told.
        std::string_view* words = words_;
        int count = 0;
        for (std::string_view word = next_word(p, end); !word.empty(); word = next_word(p, end)) {
            if (count < 4) words[count] = word;
            ++count;
        }
        if (count > most) count = most + 1;
        for (int i = 0; i < std::min(count, most); ++i) {
            if (!parse_double(words[i], values[i])) {
                fail(std::string(what) + " " + names[i] + ": expected a number, got '" + std::string(words[i]) + "'");
                return -1;
            }
        }
        return count;
    }

    void texcoord(const char* p, const char* end) {
        // vt u [v [w]]: (s, t) = (u, v), v defaults to 0 as in the format.
        static const char* const names[] = {"u", "v", "w"};
        double values[3] = {0, 0, 0};
        chunk_.texcoords.emplace_back(0.0f);
        const int count = numbers(p, end, "texture coordinate", names, 3, values);
        if (count < 0) return;
        if (count < 1 || count > 3) {
            return fail("expected 'vt u [v [w]]', got " + std::string(count < 1 ? "no numbers" : "more than 3 numbers"));
        }
        for (int i = 0; i < 2; ++i) {
            if (!std::isfinite(values[i]) || std::abs(values[i]) > std::numeric_limits<float>::max()) {
                return fail(std::string("texture coordinate ") + names[i] + ": expected a finite number, got '" +
                            std::string(words_[i]) + "'");
            }
        }
        chunk_.texcoords.back() = {static_cast<float>(values[0]), static_cast<float>(values[1])};
    }

    void normal(const char* p, const char* end) {
        static const char* const names[] = {"x", "y", "z"};
        double values[3] = {0, 0, 0};
        chunk_.normals.emplace_back(0.0f);
        const int count = numbers(p, end, "normal", names, 3, values);
        if (count < 0) return;
        if (count != 3) return fail("expected 'vn x y z', got " + std::to_string(count) + " numbers");
        const glm::vec3 n(static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2]));
        // The contract: a non-finite normal takes the computed one, as a zero one does.
        if (std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) chunk_.normals.back() = n;
    }

    /// What a corner's index names: its noun in messages, and how many there are.
    struct IndexKind {
        const char* noun;     ///< "vertex", "texture coordinate", "normal"
        const char* plural;   ///< "vertices", "texture coordinates ('vt' lines)", ...
        std::int64_t so_far;  ///< read in this chunk so far
        std::int64_t before;  ///< in the chunks before (with a range)
        std::int64_t in_file;
    };

    /// Checks one index of a corner; returns the problem's message, or an empty string.
    std::string index(std::string_view word, std::string_view digits, const IndexKind& kind,
                      TaggedCorner& tagged) const {
        std::int64_t value = 0;
        if (!parse_index(digits, value)) {
            return "face vertex '" + std::string(word) + "': expected an integer " + kind.noun + " index";
        }
        if (value == 0) {
            return std::string("face ") + kind.noun + " index 0: OBJ indices start at 1 (or are negative, counting back)";
        }
        if (range_ != nullptr) {
            // Negative indices count back from the lines read so far; positive
            // ones may name any of the file (forward references are allowed).
            const std::int64_t so_far = kind.before + kind.so_far;
            const std::int64_t resolved = value > 0 ? value : so_far + value + 1;
            const std::int64_t limit = value > 0 ? kind.in_file : so_far;
            if (resolved < 1 || resolved > limit) {
                std::ostringstream message;
                message << "face " << kind.noun << " index " << value << " is out of range: ";
                if (value > 0) {
                    message << "the file has " << kind.in_file << " " << kind.plural;
                } else {
                    message << "only " << so_far << " " << kind.plural << " precede this line";
                }
                return message.str();
            }
        }
        tagged = value > 0 ? 2 * std::min(value, index_limit)
                           : 2 * (kind.so_far + std::max(value, -index_limit) + 1) + 1;
        return {};
    }

    /// Checks one corner (`v`, `v/vt`, `v//vn` or `v/vt/vn`); returns the
    /// problem's message, or an empty string. Absent `vt`/`vn` stay kNoCorner.
    std::string corner(std::string_view word, TaggedCorner& vertex, TaggedCorner& texcoord,
                       TaggedCorner& normal) const {
        const std::size_t slash = word.find('/');
        const IndexKind vertices{"vertex", "vertices", static_cast<std::int64_t>(chunk_.positions.size()),
                                 range_ ? range_->vertices_before : 0, range_ ? range_->vertices_in_file : 0};
        if (slash == std::string_view::npos) return index(word, word, vertices, vertex);  // a plain OBJ's corner
        std::string problem = index(word, word.substr(0, slash), vertices, vertex);
        if (!problem.empty()) return problem;
        const std::string_view rest = word.substr(slash + 1);
        const std::size_t second = rest.find('/');
        const std::string_view texcoord_digits = rest.substr(0, second);
        const std::string_view normal_digits =
            second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
        if (normal_digits.find('/') != std::string_view::npos) {
            return "face vertex '" + std::string(word) + "': expected v, v/vt, v//vn or v/vt/vn";
        }
        if (!texcoord_digits.empty()) {
            const IndexKind texcoords{"texture coordinate", "texture coordinates ('vt' lines)",
                                      static_cast<std::int64_t>(chunk_.texcoords.size()),
                                      range_ ? range_->texcoords_before : 0, range_ ? range_->texcoords_in_file : 0};
            problem = index(word, texcoord_digits, texcoords, texcoord);
            if (!problem.empty()) return problem;
        }
        if (!normal_digits.empty()) {
            const IndexKind normals{"normal", "normals ('vn' lines)", static_cast<std::int64_t>(chunk_.normals.size()),
                                    range_ ? range_->normals_before : 0, range_ ? range_->normals_in_file : 0};
            problem = index(word, normal_digits, normals, normal);
        }
        return problem;
    }

    void pad(std::vector<std::array<TaggedCorner, 3>>& per_corner) const {
        if (!per_corner.empty()) per_corner.resize(chunk_.triangles.size(), {kNoCorner, kNoCorner, kNoCorner});
    }

    /// The fan of `corners` appended to `out`, after padding `out` to the
    /// triangles before this face (only faces with such indices fill it).
    void add_fan(const std::vector<TaggedCorner>& corners, std::vector<std::array<TaggedCorner, 3>>& out,
                 std::size_t triangles_before) const {
        out.resize(triangles_before, {kNoCorner, kNoCorner, kNoCorner});
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) out.push_back({corners[0], corners[k], corners[k + 1]});
    }

    // Flattened like vertex(): the index parsing of every corner stays inline.
    [[gnu::flatten]] void face(const char* p, const char* end) {
        corners_.clear();
        // The vt/vn lists stay empty until a corner has one (then padded with
        // kNoCorner for the corners before it): a plain face only fills corners_.
        texcoord_corners_.clear();
        normal_corners_.clear();
        std::string problem;
        for (std::string_view word = next_word(p, end); !word.empty(); word = next_word(p, end)) {
            TaggedCorner vertex = 0, texcoord = kNoCorner, normal = kNoCorner;
            if (problem.empty()) problem = corner(word, vertex, texcoord, normal);
            if (texcoord != kNoCorner) {
                texcoord_corners_.resize(corners_.size(), kNoCorner);
                texcoord_corners_.push_back(texcoord);
            }
            if (normal != kNoCorner) {
                normal_corners_.resize(corners_.size(), kNoCorner);
                normal_corners_.push_back(normal);
            }
            corners_.push_back(vertex);
        }
        if (corners_.size() < 3) {
            return fail("face with " + std::to_string(corners_.size()) + " vertices; expected at least 3");
        }
        if (!problem.empty()) return fail(std::move(problem));
        const std::size_t triangles_before = chunk_.triangles.size();
        for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {  // the contract's fan: v0 v_k v_k+1
            chunk_.triangles.push_back({corners_[0], corners_[k], corners_[k + 1]});
        }
        if (!texcoord_corners_.empty()) {
            texcoord_corners_.resize(corners_.size(), kNoCorner);
            add_fan(texcoord_corners_, chunk_.texcoord_triangles, triangles_before);
        }
        if (!normal_corners_.empty()) {
            normal_corners_.resize(corners_.size(), kNoCorner);
            add_fan(normal_corners_, chunk_.normal_triangles, triangles_before);
        }
        ++chunk_.faces;
    }

    void material(bool is_library, const char* p, const char* end) {
        ObjMaterialStatement statement;
        statement.is_library = is_library;
        statement.line = line_;
        statement.faces_before = chunk_.faces;
        statement.triangles_before = chunk_.triangles.size();
        // The rest of the line, trimmed: names and file names may hold blanks.
        while (p < end && is_blank(*p)) ++p;
        while (end > p && is_blank(end[-1])) --end;
        statement.argument.assign(p, end);
        chunk_.materials.push_back(std::move(statement));
    }

    const ObjIndexRange* range_;
    ObjChunk chunk_;
    // Reused by every face: no allocation per line.
    std::vector<TaggedCorner> corners_, texcoord_corners_, normal_corners_;
    std::string_view words_[4];  // the numbers' words of the last `vt`/`vn` line
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
    parser.finish();
    ObjChunk& chunk = parser.chunk();
    chunk.newlines = line - 1;
    return std::move(chunk);
}

}  // namespace phongrast::io
