#include "ply_header.hpp"

#include <charconv>
#include <sstream>

#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

constexpr const char* known_types =
    "char, uchar, short, ushort, int, uint, float, double (or int8, uint8, int16, uint16, int32, uint32, "
    "float32, float64)";

bool parse_type(const std::string& word, PlyType& type) {
    static const struct {
        const char* names[2];
        PlyType type;
    } table[] = {{{"char", "int8"}, PlyType::int8},       {{"uchar", "uint8"}, PlyType::uint8},
                 {{"short", "int16"}, PlyType::int16},    {{"ushort", "uint16"}, PlyType::uint16},
                 {{"int", "int32"}, PlyType::int32},      {{"uint", "uint32"}, PlyType::uint32},
                 {{"float", "float32"}, PlyType::float32}, {{"double", "float64"}, PlyType::float64}};
    for (const auto& entry : table) {
        if (word == entry.names[0] || word == entry.names[1]) {
            type = entry.type;
            return true;
        }
    }
    return false;
}

class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw FileError(path_ + ":" + std::to_string(line_) + ": " + what);
    }

    /// The next header line split into words; false at the end of the file.
    bool next_line(std::vector<std::string>& words) {
        if (offset_ >= bytes_.size()) return false;
        std::size_t end = bytes_.find('\n', offset_);
        if (end == std::string_view::npos) end = bytes_.size();
        std::istringstream line(std::string(bytes_.substr(offset_, end - offset_)));
        words.clear();
        for (std::string word; line >> word;) words.push_back(word);
        offset_ = end + 1;
        ++line_;
        return true;
    }

    PlyHeader parse() {
        std::vector<std::string> words;
        if (!next_line(words) || words != std::vector<std::string>{"ply"}) fail("expected 'ply' as the first line");
        PlyHeader header;
        bool format_seen = false;
        for (;;) {
            if (!next_line(words)) fail("the file ends inside the header; expected 'end_header'");
            if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
            if (words[0] == "end_header") break;
            if (words[0] == "format") {
                header.format = parse_format(words);
                format_seen = true;
            } else if (words[0] == "element") {
                header.elements.push_back(parse_element(words));
            } else if (words[0] == "property") {
                if (header.elements.empty()) fail("'property' before any 'element'");
                header.elements.back().properties.push_back(parse_property(words));
            } else {
                fail("unknown header keyword '" + words[0] + "'; expected format, element, property, comment or end_header");
            }
        }
        if (!format_seen) fail("no 'format' line before 'end_header'");
        header.body_offset = std::min(offset_, bytes_.size());
        header.body_line = line_ + 1;
        return header;
    }

private:
    PlyFormat parse_format(const std::vector<std::string>& words) const {
        if (words.size() != 3 || words[2] != "1.0") fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
        if (words[1] == "ascii") return PlyFormat::ascii;
        if (words[1] == "binary_little_endian") return PlyFormat::binary_little_endian;
        if (words[1] == "binary_big_endian") return PlyFormat::binary_big_endian;
        fail("unknown format '" + words[1] + "'; expected ascii, binary_little_endian or binary_big_endian");
    }

    PlyElement parse_element(const std::vector<std::string>& words) const {
        PlyElement element;
        if (words.size() != 3) fail("expected 'element NAME COUNT'");
        element.name = words[1];
        const std::string& count = words[2];
        const auto [stop, status] = std::from_chars(count.data(), count.data() + count.size(), element.count);
        if (status != std::errc() || stop != count.data() + count.size()) {
            fail("element '" + element.name + "': expected a whole number of elements, got '" + count + "'");
        }
        return element;
    }

    PlyProperty parse_property(const std::vector<std::string>& words) const {
        PlyProperty property;
        const auto type = [&](const std::string& word, PlyType& into) {
            if (!parse_type(word, into)) fail("unknown property type '" + word + "'; expected " + known_types);
        };
        if (words.size() == 5 && words[1] == "list") {
            property.is_list = true;
            type(words[2], property.count_type);
            type(words[3], property.type);
            if (property.count_type == PlyType::float32 || property.count_type == PlyType::float64) {
                fail("list '" + words[4] + "': expected an integer count type, got '" + words[2] + "'");
            }
            property.name = words[4];
        } else if (words.size() == 3) {
            type(words[1], property.type);
            property.name = words[2];
        } else {
            fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
        }
        return property;
    }

    std::string_view bytes_;
    const std::string& path_;
    std::size_t offset_ = 0;
    std::size_t line_ = 0;
};

}  // namespace

std::size_t size_of(PlyType type) {
    switch (type) {
        case PlyType::int8:
        case PlyType::uint8: return 1;
        case PlyType::int16:
        case PlyType::uint16: return 2;
        case PlyType::int32:
        case PlyType::uint32:
        case PlyType::float32: return 4;
        case PlyType::float64: return 8;
    }
    return 1;
}

std::size_t PlyElement::least_bytes() const {
    std::size_t bytes = 0;
    for (const PlyProperty& property : properties) {
        bytes += property.is_list ? size_of(property.count_type) : size_of(property.type);
    }
    return bytes;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& path) {
    return HeaderParser(bytes, path).parse();
}

}  // namespace phongrast::io
