// Rendering options from the keywords render_object, render and Renderer take.
#include <algorithm>
#include <iterator>
#include <map>

#include "arrays.hpp"

namespace phongrast::python {
namespace {

/// The value `text` names in `choices`, or ValueError naming the keyword and every choice.
template <typename Value>
Value choose(const std::string& keyword, const std::string& text, const std::map<std::string, Value>& choices) {
    const auto found = choices.find(text);
    if (found != choices.end()) return found->second;
    std::string names;
    for (const auto& choice : choices) names += (names.empty() ? "'" : ", '") + choice.first + "'";
    throw py::value_error(keyword + ": unknown '" + text + "'; expected one of " + names);
}

}  // namespace

const char* const option_keywords_doc = R"(Rendering keywords:
    mode: "seed" (the original method's three simplifications) or "exact" (none)
    samples: N for N x N samples per pixel, box filtered (1 to 16, default 1)
    threads: worker threads, 0 = all cores (default); the picture does not depend on it
    visibility: "painter" (default, the contract) or "depth-buffer"
    precision: "single" (default) or "double"
    sample_pattern: "ordered" (default) or "rotated"
    overdraw: "auto" (default), "all" or "visible" (speed only; the same picture)
    back_faces: "draw" (default, the contract) or "cull" (closed meshes seen from outside)
    aovs: extra outputs, "depth,normal,id,alpha" (any of them, or "all"); render and
        Renderer.render then return (image, stats, planes), planes a dict of arrays
    progress: a callable taking the fraction done (0 to 1), called about every 20 ms
        from the rendering thread; returning False cancels (phongrast.RenderCancelled),
        an exception it raises stops the render and propagates. Ctrl-C stops any
        render, with or without it, raising KeyboardInterrupt)";

static std::string keyword_text(const py::kwargs& keywords, const char* keyword, const std::string& fallback) {
    if (!keywords.contains(keyword)) return fallback;
    const py::object value = keywords[keyword];
    if (!py::isinstance<py::str>(value)) throw py::type_error(std::string(keyword) + ": expected a string");
    return value.cast<std::string>();
}

RenderOptions options_from_keywords(const py::kwargs& keywords, const std::string& default_mode) {
    static const char* const known[] = {"mode",     "samples",    "threads", "visibility", "precision",
                                        "sample_pattern", "overdraw", "back_faces", "aovs", "progress"};
    for (const auto& item : keywords) {
        const std::string key = py::str(item.first);
        if (std::find(std::begin(known), std::end(known), key) == std::end(known)) {
            throw py::type_error("unexpected keyword argument '" + key + "'; " + option_keywords_doc);
        }
    }
    RenderOptions options = choose<RenderOptions>(
        "mode", keyword_text(keywords, "mode", default_mode),
        {{"seed", RenderOptions::seed()}, {"exact", RenderOptions::exact()}});
    if (keywords.contains("samples")) options.samples_per_axis = read_int(keywords["samples"], "samples", 1, 16);
    if (keywords.contains("threads")) options.threads = read_int(keywords["threads"], "threads", 0, 4096);
    options.visibility = choose<Visibility>(
        "visibility", keyword_text(keywords, "visibility", "painter"),
        {{"painter", Visibility::painter}, {"depth-buffer", Visibility::depth_buffer},
         {"depth_buffer", Visibility::depth_buffer}});
    options.precision = choose<Precision>(
        "precision", keyword_text(keywords, "precision", "single"),
        {{"single", Precision::single_float}, {"double", Precision::double_float}});
    options.sample_pattern = choose<SamplePattern>(
        "sample_pattern", keyword_text(keywords, "sample_pattern", "ordered"),
        {{"ordered", SamplePattern::ordered_grid}, {"rotated", SamplePattern::rotated_grid}});
    options.overdraw = choose<Overdraw>(
        "overdraw", keyword_text(keywords, "overdraw", "auto"),
        {{"auto", Overdraw::automatic}, {"all", Overdraw::shade_all}, {"visible", Overdraw::shade_visible}});
    options.back_faces = choose<BackFaces>(
        "back_faces", keyword_text(keywords, "back_faces", "draw"), {{"draw", BackFaces::draw}, {"cull", BackFaces::cull_when_hidden}});
    if (keywords.contains("aovs")) {
        try {
            options.aovs = parse_aovs(keyword_text(keywords, "aovs", ""));
        } catch (const std::invalid_argument& error) {
            throw py::value_error(std::string("aovs: ") + error.what());
        }
    }
    return options;
}

}  // namespace phongrast::python
