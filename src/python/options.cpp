// Rendering options from the keywords render_object, render and Renderer take.
// The names come from the library's one table (phongrast/option_names.hpp),
// the same the command line and batch manifests accept.
#include <algorithm>
#include <iterator>
#include <map>
#include <stdexcept>

#include "arrays.hpp"
#include "phongrast/option_names.hpp"

namespace phongrast::python {

const char* const option_keywords_doc = R"(Rendering keywords:
    mode: "seed" (the original method's three simplifications) or "exact" (none)
    samples: N for N x N samples per pixel, box filtered (1 to 16, default 1)
    threads: worker threads, 0 = all cores (default); the picture does not depend on it
    visibility: "painter" (default, the contract) or "depth-buffer" (also "depth_buffer")
    precision: "single" (default) or "double"
    sample_pattern: "ordered" (default) or "rotated"
    overdraw: "auto" (default), "all" or "visible" (speed only; the same picture)
    back_faces: "draw" (default, the contract) or "cull" (closed meshes seen from outside)
    texture_filter: "bilinear" (default, the contract), "nearest" or "trilinear"
    aovs: extra outputs, "depth,distance,normal,id,alpha" (any of them, or "all"); render and
        Renderer.render then return (image, stats, planes), planes a dict of arrays
        (distance: from the eye, z_c times the sample's ray length; = depth for the
        orthographic camera)
    progress: a callable taking the fraction done (0 to 1), called about every 20 ms
        from the rendering thread; returning False cancels (phongrast.RenderCancelled),
        an exception it raises stops the render and propagates. Ctrl-C stops any
        render, with or without it, raising KeyboardInterrupt)";

RenderOptions options_from_keywords(const py::kwargs& keywords, const std::string& default_mode) {
    std::map<std::string, std::string> names{{"mode", default_mode}};
    for (const auto& item : keywords) {
        const std::string key = py::str(item.first);
        if (key == "samples" || key == "threads" || key == "aovs" || key == "progress") continue;
        bool named = false;
        for (const NamedOption& option : named_options()) named = named || option.key == key;
        if (!named) throw py::type_error("unexpected keyword argument '" + key + "'; " + option_keywords_doc);
        if (!py::isinstance<py::str>(item.second)) throw py::type_error(key + ": expected a string");
        names[key] = item.second.cast<std::string>();
    }
    RenderOptions options;
    try {
        options = options_from_names(names);
    } catch (const std::invalid_argument& error) {
        throw py::value_error(error.what());
    }
    if (keywords.contains("samples")) options.samples_per_axis = read_int(keywords["samples"], "samples", 1, 16);
    if (keywords.contains("threads")) options.threads = read_int(keywords["threads"], "threads", 0, 4096);
    if (keywords.contains("aovs")) {
        const py::object value = keywords["aovs"];
        if (!py::isinstance<py::str>(value)) throw py::type_error("aovs: expected a string");
        try {
            options.aovs = parse_aovs(value.cast<std::string>());
        } catch (const std::invalid_argument& error) {
            throw py::value_error(std::string("aovs: ") + error.what());
        }
    }
    return options;
}

}  // namespace phongrast::python
