// The text names of the rendering options, in one table: the command line
// (render, sheet, batch), Python's keywords and the tests all read names
// through it, so one spelling is accepted everywhere (`depth-buffer` and
// `depth_buffer` alike) and one message lists the choices.
#ifndef PHONGRAST_OPTION_NAMES_HPP
#define PHONGRAST_OPTION_NAMES_HPP

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast {

/// One option that takes a name.
struct NamedOption {
    /// The key: Python's keyword and a batch manifest's field ("sample_pattern");
    /// the command line's flag is the same with '-' for '_' (--sample-pattern).
    std::string key;
    /// Accepted names, the spelling printed first: {"depth-buffer", "depth_buffer"}.
    std::vector<std::vector<std::string>> choices;
    /// The name used when none is given (first spelling of a choice).
    std::string default_name;
    std::string help;  ///< one line for --help and docstrings
};

/// Every named option: mode, visibility, overdraw, precision, sample_pattern,
/// back_faces, texture_filter. `mode` (exact or seed) chooses the preset the
/// others then change.
const std::vector<NamedOption>& named_options();

/// The entry for `key` ("visibility" or "--visibility" or "sample-pattern");
/// throws std::invalid_argument listing the keys otherwise.
const NamedOption& named_option(std::string_view key);

/// "--sample-pattern" for "sample_pattern".
std::string option_flag(const NamedOption& option);

/// Every accepted spelling of every choice (for a command-line validator).
std::vector<std::string> accepted_names(const NamedOption& option);

/// The options these names give: `mode` first (RenderOptions::exact() when
/// absent or empty), then the others over it. Keys as named_option() takes
/// them; an empty value means "not given". Throws std::invalid_argument
/// naming the key, the value and the choices ("visibility: unknown 'x';
/// expected 'painter' or 'depth-buffer'").
RenderOptions options_from_names(const std::map<std::string, std::string>& names);

/// Sets one named option on `options` (not `mode`: it replaces the preset; use
/// options_from_names). Throws like options_from_names.
void set_named_option(RenderOptions& options, std::string_view key, std::string_view name);

/// The printed name of `key`'s current value in `options` ("depth-buffer").
/// For `mode`: "seed" when the options equal the seed preset's three
/// simplifications, else "exact".
std::string option_name(const RenderOptions& options, std::string_view key);

}  // namespace phongrast

#endif  // PHONGRAST_OPTION_NAMES_HPP
