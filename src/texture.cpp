// The contract's texture lookup (docs/scene-format.md, "Texture maps") in
// double precision, and the text names of wrap modes and filters. The
// renderer's kernels have their own float lookups; this one is what tests
// hold them to.
#include "phongrast/texture.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace phongrast {
namespace {

/// `index` brought into [0, size) by `wrap`, as OpenGL does.
long long wrap_index(long long index, long long size, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::clamp_to_edge:
            return index < 0 ? 0 : (index >= size ? size - 1 : index);
        case TextureWrap::mirrored_repeat: {
            // OpenGL: mirror(a) = a >= 0 ? a : -(1 + a); then
            // (size - 1) - mirror((index mod 2 size) - size).
            long long period = index % (2 * size);
            if (period < 0) period += 2 * size;
            const long long a = period - size;
            const long long mirrored = a >= 0 ? a : -(1 + a);
            return (size - 1) - mirrored;
        }
        case TextureWrap::repeat:
        default: {
            long long wrapped = index % size;
            return wrapped < 0 ? wrapped + size : wrapped;
        }
    }
}

}  // namespace

glm::dvec3 sample_bilinear(const TextureMap& map, double s, double t) {
    if (!map.image || map.image->rows < 1 || map.image->columns < 1) return glm::dvec3(1.0);
    const TextureImage& image = *map.image;
    if (!std::isfinite(s) || !std::isfinite(t)) return glm::dvec3(1.0);
    const double x = s * image.columns - 0.5;
    const double y = (1.0 - t) * image.rows - 0.5;
    const double j_floor = std::floor(x), i_floor = std::floor(y);
    const double a = x - j_floor, b = y - i_floor;
    // Wrapping the floor first keeps huge coordinates from overflowing the index.
    const long long columns = image.columns, rows = image.rows;
    const auto reduce = [](double index, long long size) {
        return static_cast<long long>(std::fmod(index, 2.0 * static_cast<double>(size)));
    };
    const long long j0 = wrap_index(reduce(j_floor, columns), columns, map.wrap_s);
    const long long j1 = wrap_index(reduce(j_floor, columns) + 1, columns, map.wrap_s);
    const long long i0 = wrap_index(reduce(i_floor, rows), rows, map.wrap_t);
    const long long i1 = wrap_index(reduce(i_floor, rows) + 1, rows, map.wrap_t);
    const auto texel = [&](long long i, long long j) {
        return glm::dvec3(image.at(static_cast<int>(i), static_cast<int>(j)));
    };
    return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0, j1) + (1 - a) * b * texel(i1, j0) +
           a * b * texel(i1, j1);
}

TextureWrap parse_texture_wrap(std::string_view text) {
    if (text == "repeat") return TextureWrap::repeat;
    if (text == "clamp_to_edge") return TextureWrap::clamp_to_edge;
    if (text == "mirrored_repeat") return TextureWrap::mirrored_repeat;
    throw std::invalid_argument("texture wrap: unknown '" + std::string(text) +
                                "'; expected repeat, clamp_to_edge or mirrored_repeat");
}

const char* to_string(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::repeat: return "repeat";
        case TextureWrap::clamp_to_edge: return "clamp_to_edge";
        case TextureWrap::mirrored_repeat: return "mirrored_repeat";
    }
    return "unknown";
}

TextureFilter parse_texture_filter(std::string_view text) {
    if (text == "nearest") return TextureFilter::nearest;
    if (text == "bilinear") return TextureFilter::bilinear;
    if (text == "trilinear") return TextureFilter::trilinear;
    throw std::invalid_argument("texture filter: unknown '" + std::string(text) +
                                "'; expected nearest, bilinear or trilinear");
}

const char* to_string(TextureFilter filter) {
    switch (filter) {
        case TextureFilter::nearest: return "nearest";
        case TextureFilter::bilinear: return "bilinear";
        case TextureFilter::trilinear: return "trilinear";
    }
    return "unknown";
}

}  // namespace phongrast
