#include "phongrast/option_names.hpp"

#include <cstddef>
#include <functional>
#include <stdexcept>

namespace phongrast {
namespace {

/// A named option with how it reads and writes RenderOptions: `set` takes the
/// index of a choice, `get` gives the index of the current value.
struct Entry {
    NamedOption option;
    std::function<void(RenderOptions&, std::size_t)> set;
    std::function<std::size_t(const RenderOptions&)> get;
};

/// An option whose choices map one to one onto an enum's values, in order.
template <typename Value>
Entry enum_entry(NamedOption option, Value RenderOptions::*field, std::vector<Value> values) {
    Entry entry;
    entry.option = std::move(option);
    entry.set = [field, values](RenderOptions& options, std::size_t choice) { options.*field = values.at(choice); };
    entry.get = [field, values](const RenderOptions& options) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (values[i] == options.*field) return i;
        }
        return std::size_t{0};
    };
    return entry;
}

std::vector<Entry> make_entries() {
    std::vector<Entry> entries;
    {
        // The mode is the preset's three simplifications, together.
        Entry mode;
        mode.option = {"mode", {{"exact"}, {"seed"}}, "exact",
                       "exact: the contract's rendering; seed: the original method's three simplifications"};
        mode.set = [](RenderOptions& options, std::size_t choice) {
            const RenderOptions preset = choice == 1 ? RenderOptions::seed() : RenderOptions::exact();
            options.light_vectors = preset.light_vectors;
            options.interpolation = preset.interpolation;
            options.border = preset.border;
        };
        mode.get = [](const RenderOptions& options) {
            const RenderOptions seed = RenderOptions::seed();
            return std::size_t(options.light_vectors == seed.light_vectors &&
                               options.interpolation == seed.interpolation && options.border == seed.border);
        };
        entries.push_back(std::move(mode));
    }
    entries.push_back(enum_entry<Visibility>(
        {"visibility", {{"painter"}, {"depth-buffer", "depth_buffer"}}, "painter",
         "painter: the contract's order, farthest first; depth-buffer: nearest sample wins (not the contract; "
         "for comparison)"},
        &RenderOptions::visibility, {Visibility::painter, Visibility::depth_buffer}));
    entries.push_back(enum_entry<Overdraw>(
        {"overdraw", {{"auto"}, {"all"}, {"visible"}}, "auto",
         "Painter's order: all shades every sample of every triangle; visible shades only the samples left "
         "visible; auto picks visible for per-pixel lighting and textured scenes (the picture does not change)"},
        &RenderOptions::overdraw, {Overdraw::automatic, Overdraw::shade_all, Overdraw::shade_visible}));
    entries.push_back(enum_entry<Precision>(
        {"precision", {{"single"}, {"double"}}, "single", "Arithmetic of the fill: single or double precision"},
        &RenderOptions::precision, {Precision::single_float, Precision::double_float}));
    entries.push_back(enum_entry<SamplePattern>(
        {"sample_pattern", {{"ordered"}, {"rotated"}}, "ordered",
         "Where a pixel's samples lie with --samples above 1: an ordered grid or a rotated grid"},
        &RenderOptions::sample_pattern, {SamplePattern::ordered_grid, SamplePattern::rotated_grid}));
    entries.push_back(enum_entry<BackFaces>(
        {"back_faces", {{"draw"}, {"cull"}}, "draw",
         "draw: every triangle (the contract); cull: skip back faces of a closed mesh seen from outside"},
        &RenderOptions::back_faces, {BackFaces::draw, BackFaces::cull_when_hidden}));
    entries.push_back(enum_entry<TextureFilter>(
        {"texture_filter", {{"bilinear"}, {"nearest"}, {"trilinear"}}, "bilinear",
         "How textures are sampled: bilinear (the contract), nearest, or trilinear on a mip pyramid"},
        &RenderOptions::texture_filter, {TextureFilter::bilinear, TextureFilter::nearest, TextureFilter::trilinear}));
    return entries;
}

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = make_entries();
    return table;
}

/// "visibility", "--visibility" and "sample-pattern" all name sample_pattern's style of key.
std::string normalized_key(std::string_view key) {
    while (!key.empty() && key.front() == '-') key.remove_prefix(1);
    std::string result(key);
    for (char& c : result) {
        if (c == '-') c = '_';
    }
    return result;
}

const Entry& entry_for(std::string_view key) {
    const std::string wanted = normalized_key(key);
    for (const Entry& entry : entries()) {
        if (entry.option.key == wanted) return entry;
    }
    std::string keys;
    for (const Entry& entry : entries()) keys += (keys.empty() ? "" : ", ") + entry.option.key;
    throw std::invalid_argument("unknown option '" + std::string(key) + "'; expected one of " + keys);
}

/// "'a', 'b' or 'c'".
std::string listed(const NamedOption& option) {
    std::string text;
    for (std::size_t i = 0; i < option.choices.size(); ++i) {
        if (i > 0) text += i + 1 == option.choices.size() ? " or " : ", ";
        text += "'" + option.choices[i].front() + "'";
    }
    return text;
}

std::size_t choice_index(const NamedOption& option, std::string_view name) {
    for (std::size_t i = 0; i < option.choices.size(); ++i) {
        for (const std::string& spelling : option.choices[i]) {
            if (spelling == name) return i;
        }
    }
    throw std::invalid_argument(option.key + ": unknown '" + std::string(name) + "'; expected " + listed(option));
}

}  // namespace

const std::vector<NamedOption>& named_options() {
    static const std::vector<NamedOption> options = [] {
        std::vector<NamedOption> result;
        for (const Entry& entry : entries()) result.push_back(entry.option);
        return result;
    }();
    return options;
}

const NamedOption& named_option(std::string_view key) { return entry_for(key).option; }

std::string option_flag(const NamedOption& option) {
    std::string flag = "--" + option.key;
    for (char& c : flag) {
        if (c == '_') c = '-';
    }
    return flag;
}

std::vector<std::string> accepted_names(const NamedOption& option) {
    std::vector<std::string> names;
    for (const auto& choice : option.choices) names.insert(names.end(), choice.begin(), choice.end());
    return names;
}

void set_named_option(RenderOptions& options, std::string_view key, std::string_view name) {
    const Entry& entry = entry_for(key);
    entry.set(options, choice_index(entry.option, name));
}

RenderOptions options_from_names(const std::map<std::string, std::string>& names) {
    for (const auto& [key, name] : names) entry_for(key);  // an unknown key is an error even when empty
    RenderOptions options = RenderOptions::exact();
    // In table order: mode, the preset, comes first.
    for (const Entry& entry : entries()) {
        for (const auto& [key, name] : names) {
            if (!name.empty() && normalized_key(key) == entry.option.key) {
                entry.set(options, choice_index(entry.option, name));
            }
        }
    }
    return options;
}

std::string option_name(const RenderOptions& options, std::string_view key) {
    const Entry& entry = entry_for(key);
    return entry.option.choices.at(entry.get(options)).front();
}

}  // namespace phongrast
