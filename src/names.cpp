// Text names of shaders and lighting selections, as scene files and the
// command line spell them (docs/scene-format.md, "shader" and "lighting").
#include <stdexcept>
#include <string>

#include "phongrast/lighting.hpp"
#include "phongrast/render.hpp"

namespace phongrast {

Lighting parse_lighting(std::string_view text) {
    Lighting result{false, false, false};
    if (text.empty()) {
        throw std::invalid_argument(
            "lighting: empty; expected ambient, diffuse, specular, full, or several joined with '+'");
    }
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t plus = text.find('+', start);
        const std::string_view part =
            text.substr(start, plus == std::string_view::npos ? std::string_view::npos : plus - start);
        if (part == "ambient") {
            result.ambient = true;
        } else if (part == "diffuse" || part == "diffusion") {
            result.diffuse = true;
        } else if (part == "specular") {
            result.specular = true;
        } else if (part == "full") {
            result = Lighting::full();
        } else {
            throw std::invalid_argument("lighting: unknown term '" + std::string(part) + "' in '" +
                                        std::string(text) +
                                        "'; expected ambient, diffuse (or diffusion), specular, "
                                        "full, or several joined with '+'");
        }
        if (plus == std::string_view::npos) break;
        start = plus + 1;
    }
    return result;
}

std::string to_string(const Lighting& lighting) {
    if (lighting == Lighting::full()) return "full";
    std::string name;
    const auto append = [&name](const char* term) {
        if (!name.empty()) name += '+';
        name += term;
    };
    if (lighting.ambient) append("ambient");
    if (lighting.diffuse) append("diffuse");
    if (lighting.specular) append("specular");
    return name.empty() ? "none" : name;
}

Shader parse_shader(std::string_view text) {
    if (text == "flat") return Shader::flat;
    if (text == "gouraud") return Shader::gouraud;
    if (text == "phong") return Shader::phong;
    throw std::invalid_argument("shader: unknown '" + std::string(text) +
                                "'; expected flat, gouraud or phong");
}

const char* to_string(Shader shader) {
    switch (shader) {
        case Shader::flat: return "flat";
        case Shader::gouraud: return "gouraud";
        case Shader::phong: return "phong";
    }
    return "unknown";
}

NormalSource parse_normal_source(std::string_view text) {
    if (text == "computed") return NormalSource::computed;
    if (text == "file") return NormalSource::file;
    throw std::invalid_argument("normals: unknown '" + std::string(text) + "'; expected computed or file");
}

const char* to_string(NormalSource source) {
    switch (source) {
        case NormalSource::computed: return "computed";
        case NormalSource::file: return "file";
    }
    return "unknown";
}

RenderOptions RenderOptions::seed() {
    RenderOptions options;
    options.light_vectors = LightVectors::triangle_centroid;
    options.interpolation = Interpolation::screen_affine;
    options.border = BorderPolicy::drop_triangle;
    return options;
}

RenderOptions RenderOptions::exact() { return RenderOptions{}; }

}  // namespace phongrast
