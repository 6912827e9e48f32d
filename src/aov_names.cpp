// Text names of the extra outputs, as the command line spells them (--aov).
#include <stdexcept>
#include <string>

#include "phongrast/aov.hpp"

namespace phongrast {

AovRequest parse_aovs(std::string_view text) {
    AovRequest request;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string_view part =
            text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (part == "depth") {
            request.depth = true;
        } else if (part == "normal") {
            request.normal = true;
        } else if (part == "id") {
            request.id = true;
        } else if (part == "alpha") {
            request.alpha = true;
        } else if (part == "uv") {
            request.uv = true;
        } else if (part == "distance") {
            request.distance = true;
        } else if (part == "all") {
            request = AovRequest::all();
        } else {
            throw std::invalid_argument("aov: unknown output '" + std::string(part) + "' in '" + std::string(text) +
                                        "'; expected depth, normal, id, alpha, uv, distance or all, joined with ','");
        }
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return request;
}

std::string to_string(const AovRequest& request) {
    std::string names;
    const auto append = [&names](bool on, const char* name) {
        if (!on) return;
        if (!names.empty()) names += ',';
        names += name;
    };
    append(request.depth, "depth");
    append(request.normal, "normal");
    append(request.id, "id");
    append(request.alpha, "alpha");
    append(request.uv, "uv");
    append(request.distance, "distance");
    return names.empty() ? "none" : names;
}

}  // namespace phongrast
