// The contract's texture lookup (docs/scene-format.md, "Texture maps") in
// double precision, and the text names of wrap modes and filters. The
// renderer's kernels have their own float lookups; this one is what tests
// hold them to.
#include "phongrast/texture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

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

namespace {

/// The contract's bilinear lookup on one level: `texels` rows x columns, row-major.
glm::dvec3 bilinear_on(const glm::vec3* texels, int image_rows, int image_columns, TextureWrap wrap_s,
                       TextureWrap wrap_t, double s, double t) {
    if (!std::isfinite(s) || !std::isfinite(t)) return glm::dvec3(1.0);
    const double x = s * image_columns - 0.5;
    const double y = (1.0 - t) * image_rows - 0.5;
    const double j_floor = std::floor(x), i_floor = std::floor(y);
    const double a = x - j_floor, b = y - i_floor;
    // Wrapping the floor first keeps huge coordinates from overflowing the index.
    const long long columns = image_columns, rows = image_rows;
    const auto reduce = [](double index, long long size) {
        return static_cast<long long>(std::fmod(index, 2.0 * static_cast<double>(size)));
    };
    const long long j0 = wrap_index(reduce(j_floor, columns), columns, wrap_s);
    const long long j1 = wrap_index(reduce(j_floor, columns) + 1, columns, wrap_s);
    const long long i0 = wrap_index(reduce(i_floor, rows), rows, wrap_t);
    const long long i1 = wrap_index(reduce(i_floor, rows) + 1, rows, wrap_t);
    const auto texel = [&](long long i, long long j) {
        return glm::dvec3(texels[static_cast<std::size_t>(i) * static_cast<std::size_t>(columns) +
                                 static_cast<std::size_t>(j)]);
    };
    return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0, j1) + (1 - a) * b * texel(i1, j0) +
           a * b * texel(i1, j1);
}

/// Bilinear on level `level` of the map's image (0: the image itself).
glm::dvec3 bilinear_on_level(const TextureMap& map, std::size_t level, double s, double t) {
    const TextureImage& image = *map.image;
    if (level == 0) {
        return bilinear_on(image.texels.data(), image.rows, image.columns, map.wrap_s, map.wrap_t, s, t);
    }
    const MipLevel& reduced = image.mip_levels()[level - 1];
    return bilinear_on(reduced.texels.data(), reduced.rows, reduced.columns, map.wrap_s, map.wrap_t, s, t);
}

/// For an axis of `size` texels halved to `half`: the texels of the finer
/// level under texel k of the coarser and their weights (summing to 1).
/// Texel k covers [k r, (k + 1) r) with r = size / half, in finer texels.
std::vector<std::pair<int, double>> box_weights(int size, int half, int k) {
    std::vector<std::pair<int, double>> weights;
    const double width = static_cast<double>(size) / static_cast<double>(half);
    const double begin = k * width, end = (k + 1) * width;
    for (int i = static_cast<int>(std::floor(begin)); i < size && i < end; ++i) {
        const double covered = std::min(end, i + 1.0) - std::max(begin, static_cast<double>(i));
        if (covered > 0.0) weights.emplace_back(i, covered / width);
    }
    return weights;
}

}  // namespace

glm::dvec3 sample_bilinear(const TextureMap& map, double s, double t) {
    if (!map.image || map.image->rows < 1 || map.image->columns < 1) return glm::dvec3(1.0);
    return bilinear_on_level(map, 0, s, t);
}

namespace {

/// The next level down from a level of rows x columns texels (next_mip_level()).
MipLevel halve(const glm::vec3* texels, int rows, int columns) {
    MipLevel next;
    next.rows = std::max(1, rows / 2);
    next.columns = std::max(1, columns / 2);
    next.texels.reserve(static_cast<std::size_t>(next.rows) * static_cast<std::size_t>(next.columns));
    std::vector<std::vector<std::pair<int, double>>> column_weights;
    for (int j = 0; j < next.columns; ++j) column_weights.push_back(box_weights(columns, next.columns, j));
    for (int i = 0; i < next.rows; ++i) {
        const std::vector<std::pair<int, double>> row_weights = box_weights(rows, next.rows, i);
        for (int j = 0; j < next.columns; ++j) {
            glm::dvec3 sum(0.0);
            for (const auto& [row, row_weight] : row_weights) {
                for (const auto& [column, column_weight] : column_weights[static_cast<std::size_t>(j)]) {
                    const glm::vec3& texel = texels[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                                                    static_cast<std::size_t>(column)];
                    sum += (row_weight * column_weight) * glm::dvec3(texel);
                }
            }
            next.texels.emplace_back(sum);
        }
    }
    return next;
}

}  // namespace

MipLevel next_mip_level(const MipLevel& level) { return halve(level.texels.data(), level.rows, level.columns); }

const std::vector<MipLevel>& TextureImage::mip_levels() const {
    MipPyramidCache::State& state = *mip_cache_.state_;
    std::call_once(state.built, [&] {
        if (rows < 1 || columns < 1 || texels.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns)) {
            return;  // no image: looked up as T = 1, no pyramid needed
        }
        // Level 0 is the image itself, not copied: levels 1, 2, ... down to 1 x 1.
        const glm::vec3* finer = texels.data();
        int finer_rows = rows, finer_columns = columns;
        while (finer_rows > 1 || finer_columns > 1) {
            state.levels.push_back(halve(finer, finer_rows, finer_columns));
            const MipLevel& level = state.levels.back();
            finer = level.texels.data();
            finer_rows = level.rows;
            finer_columns = level.columns;
        }
    });
    return state.levels;
}

double mip_lambda(double ds_dx, double dt_dx, double ds_dy, double dt_dy, int columns, int rows) {
    const double ux = ds_dx * columns, vx = dt_dx * rows, uy = ds_dy * columns, vy = dt_dy * rows;
    const double along_x = ux * ux + vx * vx, along_y = uy * uy + vy * vy;
    if (std::isnan(along_x) || std::isnan(along_y)) return std::numeric_limits<double>::infinity();
    return 0.5 * std::log2(std::max(along_x, along_y));  // log2(0) = -infinity: magnified
}

glm::dvec3 sample_trilinear(const TextureMap& map, double s, double t, double lambda) {
    if (!map.image || map.image->rows < 1 || map.image->columns < 1) return glm::dvec3(1.0);
    if (std::isnan(lambda)) lambda = std::numeric_limits<double>::infinity();
    if (lambda <= 0.0) return bilinear_on_level(map, 0, s, t);
    const std::size_t last = map.image->mip_levels().size();
    if (lambda >= static_cast<double>(last)) return bilinear_on_level(map, last, s, t);
    const double level = std::floor(lambda), fraction = lambda - level;
    const auto d = static_cast<std::size_t>(level);
    return (1.0 - fraction) * bilinear_on_level(map, d, s, t) + fraction * bilinear_on_level(map, d + 1, s, t);
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
