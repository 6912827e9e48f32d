#include "obj_materials.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "phongrast/io/error.hpp"
#include "phongrast/io/texture_file.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast::io {
namespace {

/// One `newmtl` entry of an MTL file, with only the fields it states.
struct MtlEntry {
    FaceMaterial material;
    std::string texture_path;  ///< map_Kd, relative to the MTL file's folder resolved; empty: none
    TextureWrap wrap = TextureWrap::repeat;
};

std::vector<std::string> split_words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> words;
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

bool parse_number(const std::string& word, double& value) {
    char* end = nullptr;
    value = std::strtod(word.c_str(), &end);
    return end != word.c_str() && *end == '\0';
}

/// Reads an MTL file's entries; strict about numbers (an error naming the
/// file and line), lenient about what phongrast does not use (ignored).
class MtlReader {
public:
    MtlReader(std::string path, std::vector<std::string>& warnings) : path_(std::move(path)), warnings_(warnings) {
        const std::filesystem::path folder = std::filesystem::path(path_).parent_path();
        folder_ = folder;
    }

    /// Adds the file's entries to `entries` (the first entry of a name wins).
    void read(std::istream& in, std::map<std::string, MtlEntry>& entries) {
        std::string text;
        MtlEntry* current = nullptr;
        MtlEntry ignored;
        for (line_ = 1; std::getline(in, text); ++line_) {
            if (!text.empty() && text.back() == '\r') text.pop_back();
            const std::size_t start = text.find_first_not_of(" \t");
            if (start == std::string::npos || text[start] == '#') continue;
            const std::size_t key_end = std::min(text.find_first_of(" \t", start), text.size());
            const std::string key = text.substr(start, key_end - start);
            std::string rest = text.substr(key_end);
            rest.erase(0, std::min(rest.find_first_not_of(" \t"), rest.size()));
            rest.erase(rest.find_last_not_of(" \t") + 1);
            if (key == "newmtl") {
                const auto inserted = entries.emplace(rest, MtlEntry{});
                current = inserted.second ? &inserted.first->second : &ignored;
                if (!inserted.second) warn("newmtl " + rest + ": a second material of this name, ignored");
                current->material.name = rest;
                continue;
            }
            if (current == nullptr) continue;  // before any newmtl: belongs to no material
            FaceMaterial& material = current->material;
            if (key == "Ka") material.coefficients.ka = color(key, rest);
            if (key == "Kd") material.coefficients.kd = color(key, rest);
            if (key == "Ks") material.coefficients.ks = color(key, rest);
            if (key == "Ns") material.coefficients.n = exponent(rest);
            if (key == "map_Kd") texture(rest, *current);
        }
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw FileError(path_ + ":" + std::to_string(line_) + ": " + what);
    }
    void warn(const std::string& what) const { warnings_.push_back(path_ + ":" + std::to_string(line_) + ": " + what); }

    /// `Ka r [g b]`; the `spectral` and `xyz` forms are ignored with a warning.
    std::optional<glm::vec3> color(const std::string& key, const std::string& rest) {
        const std::vector<std::string> words = split_words(rest);
        if (!words.empty() && (words[0] == "spectral" || words[0] == "xyz")) {
            warn(key + " " + words[0] + ": not supported, ignored");
            return std::nullopt;
        }
        double values[3] = {0, 0, 0};
        bool good = words.size() == 1 || words.size() == 3;
        for (std::size_t i = 0; good && i < words.size(); ++i) {
            good = parse_number(words[i], values[i]) && std::isfinite(values[i]) &&
                   std::abs(values[i]) <= std::numeric_limits<float>::max();
        }
        if (!good) fail(key + ": expected 1 or 3 finite numbers, got '" + rest + "'");
        if (words.size() == 1) values[1] = values[2] = values[0];
        return glm::vec3(static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2]));
    }

    float exponent(const std::string& rest) {
        double value = 0;
        if (!parse_number(rest, value) || !(value >= 0.0) || value > std::numeric_limits<float>::max()) {
            fail("Ns: expected a non-negative finite number, got '" + rest + "'");
        }
        return static_cast<float>(value);
    }

    /// `map_Kd [options] file`: `-clamp on|off` read, other options skipped
    /// with their arguments and a warning; the file is the rest of the line.
    void texture(const std::string& rest, MtlEntry& entry) {
        static const std::map<std::string, int> arguments = {
            {"-blendu", 1}, {"-blendv", 1}, {"-cc", 1},      {"-clamp", 1}, {"-boost", 1},     {"-texres", 1},
            {"-bm", 1},     {"-imfchan", 1}, {"-type", 1},   {"-mm", 2},    {"-colorspace", 1}, {"-o", 3},
            {"-s", 3},      {"-t", 3}};
        std::size_t at = 0;
        const auto next_word = [&]() {
            const std::size_t start = rest.find_first_not_of(" \t", at);
            if (start == std::string::npos) {
                at = rest.size();
                return std::string();
            }
            const std::size_t end = std::min(rest.find_first_of(" \t", start), rest.size());
            at = end;
            return rest.substr(start, end - start);
        };
        entry.wrap = TextureWrap::repeat;
        std::vector<std::string> ignored;
        while (true) {
            const std::size_t option_start = at;
            const std::string word = next_word();
            const auto option = arguments.find(word);
            if (option == arguments.end()) {
                at = option_start;
                break;
            }
            std::string shown = word;
            for (int k = 0; k < option->second; ++k) {
                const std::size_t before = at;
                const std::string argument = next_word();
                double number = 0;
                // -o, -s and -t take 1 to 3 numbers: stop at the first word that is not one.
                if (option->second == 3 && k > 0 && !parse_number(argument, number)) {
                    at = before;
                    break;
                }
                shown += " " + argument;
                if (word == "-clamp") entry.wrap = argument == "on" ? TextureWrap::clamp_to_edge : TextureWrap::repeat;
            }
            if (word != "-clamp") ignored.push_back(shown);
        }
        std::string file = rest.substr(std::min(rest.find_first_not_of(" \t", at), rest.size()));
        if (file.empty()) {
            warn("map_Kd: no file name; the material has no texture");
            return;
        }
        for (const std::string& option : ignored) {
            warn("map_Kd option '" + option + "' ignored (phongrast reads only -clamp)");
        }
        entry.texture_path = (folder_ / file).string();
    }

    std::string path_;
    std::filesystem::path folder_;
    std::vector<std::string>& warnings_;
    std::size_t line_ = 0;
};

class MaterialLibrary {
public:
    explicit MaterialLibrary(const std::string& path) : path_(path), folder_(std::filesystem::path(path).parent_path()) {}

    /// `mtllib a.mtl b.mtl` (or one name holding blanks, when such a file exists).
    void load(const std::string& argument, std::size_t line) {
        if (argument.empty()) return warn(line, "mtllib without a file name");
        const bool whole = std::filesystem::is_regular_file(folder_ / argument);
        for (const std::string& name : whole ? std::vector<std::string>{argument} : split_words(argument)) {
            if (!loaded_.insert(name).second) continue;
            const std::string file = (folder_ / name).string();
            side_files_.push_back(file);  // even when missing: a file that appears later changes the mesh
            std::ifstream in(file, std::ios::binary);
            if (!in) {
                warn(line, "MTL file " + file + " not found; faces using its materials have no material of their own");
                continue;
            }
            MtlReader(file, warnings_).read(in, entries_);
        }
    }

    /// `usemtl name`: the index of its material in `materials`, or kNoIndex with a warning (once per name).
    std::uint32_t use(const std::string& name, std::size_t line, std::vector<FaceMaterial>& materials) {
        const auto known = used_.find(name);
        if (known != used_.end()) return known->second;
        const auto entry = entries_.find(name);
        std::uint32_t index = kNoIndex;
        if (entry == entries_.end()) {
            warn(line, "usemtl " + name + ": no such material in the MTL files read; its faces have no material of their own");
        } else {
            index = static_cast<std::uint32_t>(materials.size());
            materials.push_back(with_texture(entry->second));
        }
        used_.emplace(name, index);
        return index;
    }

    std::vector<std::string>& warnings() { return warnings_; }
    std::vector<std::string>& side_files() { return side_files_; }

private:
    void warn(std::size_t line, const std::string& what) {
        warnings_.push_back(path_ + ":" + std::to_string(line) + ": " + what);
    }

    FaceMaterial with_texture(const MtlEntry& entry) {
        FaceMaterial material = entry.material;
        if (entry.texture_path.empty()) return material;
        TextureMap map;
        map.wrap_s = map.wrap_t = entry.wrap;
        std::string why;
        side_files_.push_back(entry.texture_path);
        map.image = load_texture(entry.texture_path, &why);
        if (!map.image) {
            warnings_.push_back(path_ + ": material " + material.name + ": texture " + entry.texture_path +
                                " cannot be read (" + why + "); its faces draw with T = 1");
        }
        material.texture = map;
        return material;
    }

    std::string path_;
    std::filesystem::path folder_;
    std::map<std::string, MtlEntry> entries_;
    std::map<std::string, std::uint32_t> used_;
    std::set<std::string> loaded_;
    std::vector<std::string> warnings_;
    std::vector<std::string> side_files_;
};

/// Version 1's reading of an MTL entry: absent Ka, Kd, Ks as 0, Ns as 1.
PhongMaterial version_1_material(const MaterialFields& fields) {
    PhongMaterial absent;
    absent.ka = absent.kd = absent.ks = glm::vec3(0.0f);
    absent.n = 1.0f;
    return fields.over(absent);
}

}  // namespace

ObjMaterials read_obj_materials(const std::vector<ObjMaterialUse>& uses, std::size_t triangles_in_file,
                                const std::string& path) {
    ObjMaterials result;
    if (uses.empty()) return result;
    MaterialLibrary library(path);
    std::uint32_t current = kNoIndex;
    std::size_t current_from = 0;
    bool any_use = false;
    const auto assign_until = [&](std::size_t end) {
        if (current != kNoIndex && result.face_materials.empty()) result.face_materials.assign(triangles_in_file, kNoIndex);
        if (current == kNoIndex) return;
        for (std::size_t t = current_from; t < end; ++t) result.face_materials[t] = current;
    };
    for (const ObjMaterialUse& use : uses) {
        if (use.is_library) {
            library.load(use.argument, use.line);
            continue;
        }
        any_use = true;
        assign_until(use.triangles_before);
        current = library.use(use.argument, use.line, result.materials);
        current_from = use.triangles_before;
    }
    if (any_use) assign_until(triangles_in_file);
    for (const std::uint32_t material : result.face_materials) {
        if (material == kNoIndex) continue;
        result.first = version_1_material(result.materials[material].coefficients);
        result.first_name = result.materials[material].name;
        break;
    }
    result.warnings = std::move(library.warnings());
    result.side_files = std::move(library.side_files());
    return result;
}

}  // namespace phongrast::io
