#include "phongrast/io/dataset_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "exr_file.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/text_file.hpp"
#include "png_bytes.hpp"
#include "png_encoder.hpp"

namespace phongrast::io {
namespace {

constexpr std::size_t kLargest16Bit = 65535;

struct FileKind {
    const char* name;
    bool DatasetFiles::*member;
    const char* suffix;
};
constexpr FileKind kFileKinds[] = {
    {"depth", &DatasetFiles::depth, ".depth.exr"},   {"depth16", &DatasetFiles::depth16, ".depth.png"},
    {"mask", &DatasetFiles::mask, ".mask.png"},      {"id", &DatasetFiles::id, ".id.png"},
    {"normal", &DatasetFiles::normal, ".normal.png"}, {"object", &DatasetFiles::object, ".object.png"},
    {"distance", &DatasetFiles::distance, ".distance.exr"},
};

std::string stem_path(const std::string& colour_path) {
    std::filesystem::path path(colour_path);
    return path.replace_extension().string();
}

void require_plane(bool present, const char* plane, const std::string& path) {
    if (!present) {
        throw FileError(path + ": the render has no " + plane +
                        " plane; request DatasetFiles::planes() in RenderOptions::aovs");
    }
}

void write_png_file(const std::string& path, const void* data, int rows, int columns, int channels, int bit_depth,
                    const DatasetFileOptions& options) {
    detail::PngPixels pixels;
    pixels.data = data;
    pixels.rows = rows;
    pixels.columns = columns;
    pixels.channels = channels;
    pixels.bit_depth = bit_depth;
    replace_file_atomically(path, [&](const std::string& temporary) {
        detail::write_png(temporary, path, pixels, detail::png_settings(options.png_compression));
    });
}

// One 32-bit float channel "Z": the depth file's layout, which the distance file shares (one reader reads both).
void write_float_exr(const std::string& path, const std::vector<float>& plane, int rows, int columns) {
    std::vector<float> values = plane;  // write_exr reads through a non-const pointer
    replace_file_atomically(path, [&](const std::string& temporary) {
        detail::write_exr(temporary, path, columns, rows,
                          {detail::ExrChannel{"Z", false, reinterpret_cast<char*>(values.data()), sizeof(float)}});
    });
}

// round(z / scale), at least 1 so that a covered pixel never reads as background.
std::vector<std::uint16_t> depth_steps(const std::vector<float>& depth, double scale, const std::string& path) {
    std::vector<std::uint16_t> steps(depth.size(), 0);
    double deepest = 0.0;
    for (std::size_t p = 0; p < depth.size(); ++p) {
        if (!std::isfinite(depth[p])) continue;  // background
        const double step = std::round(static_cast<double>(depth[p]) / scale);
        deepest = std::max(deepest, static_cast<double>(depth[p]));
        if (step > static_cast<double>(kLargest16Bit)) continue;  // reported below, before any file is written
        steps[p] = static_cast<std::uint16_t>(std::max(1.0, step));
    }
    if (std::round(deepest / scale) > static_cast<double>(kLargest16Bit)) {
        throw FileError(path + ": depth " + std::to_string(deepest) + " does not fit a 16-bit PNG at a depth scale of " +
                        std::to_string(scale) + " (at most " + std::to_string(kLargest16Bit * scale) +
                        "); give a depth scale of at least " + std::to_string(deepest / kLargest16Bit) +
                        ", or write depth as EXR");
    }
    return steps;
}

}  // namespace

AovRequest DatasetFiles::planes() const {
    AovRequest request;
    request.depth = depth || depth16;
    request.alpha = mask;
    request.id = id || object;
    request.normal = normal;
    request.distance = distance;
    return request;
}

void DatasetFiles::add_planes_to(AovRequest& aovs) const {
    const AovRequest needed = planes();
    aovs.depth = aovs.depth || needed.depth;
    aovs.normal = aovs.normal || needed.normal;
    aovs.id = aovs.id || needed.id;
    aovs.alpha = aovs.alpha || needed.alpha;
    aovs.distance = aovs.distance || needed.distance;
}

DatasetFiles parse_dataset_files(std::string_view text) {
    DatasetFiles files;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string_view entry = text.substr(start, comma - start);
        if (entry == "all") {
            files.depth = files.mask = files.id = files.normal = files.object = files.distance = true;
            start = comma + 1;
            continue;
        }
        const auto kind = std::find_if(std::begin(kFileKinds), std::end(kFileKinds),
                                       [&](const FileKind& k) { return entry == k.name; });
        if (kind == std::end(kFileKinds)) {
            throw std::invalid_argument("aov-files: unknown '" + std::string(entry) +
                                        "'; expected depth, depth16, mask, id, normal, object, distance (comma-separated) or all");
        }
        files.*(kind->member) = true;
        start = comma + 1;
    }
    return files;
}

std::string to_string(const DatasetFiles& files) {
    std::string text;
    for (const FileKind& kind : kFileKinds) {
        if (files.*(kind.member)) text += (text.empty() ? "" : ",") + std::string(kind.name);
    }
    return text;
}

std::vector<std::string> dataset_file_paths(const std::string& colour_path, const DatasetFiles& files) {
    const std::string stem = stem_path(colour_path);
    std::vector<std::string> paths;
    for (const FileKind& kind : kFileKinds) {
        if (files.*(kind.member)) paths.push_back(stem + kind.suffix);
    }
    return paths;
}

void check_dataset_files(const DatasetFiles& files, const DatasetFileOptions& options, std::size_t triangles,
                         std::size_t objects) {
    if (files.depth16 && !(options.depth_scale > 0.0 && std::isfinite(options.depth_scale))) {
        throw std::invalid_argument("depth-scale: expected a positive number of scene units per step, got " +
                                    std::to_string(options.depth_scale));
    }
    if (files.id && triangles > kLargest16Bit - 1) {
        throw std::invalid_argument("aov-files: id: the scene has " + std::to_string(triangles) +
                                    " triangles; a 16-bit id.png holds at most " + std::to_string(kLargest16Bit - 1) +
                                    " (the EXR's id channel holds them all: --aov id -o NAME.exr)");
    }
    if (files.object && objects > kLargest16Bit - 1) {
        throw std::invalid_argument("aov-files: object: the scene has " + std::to_string(objects) +
                                    " objects; a 16-bit object.png holds at most " + std::to_string(kLargest16Bit - 1));
    }
}

std::vector<std::size_t> object_first_triangles(const Scene& scene) {
    if (scene.objects.empty()) return {0};
    std::vector<std::size_t> first;
    std::size_t triangles = 0;
    for (const SceneObject& object : scene.objects) {
        first.push_back(triangles);
        triangles += object.mesh ? object.mesh->triangles.size() : 0;
    }
    return first;
}

void check_dataset_files(const DatasetFiles& files, const DatasetFileOptions& options, const Scene& scene) {
    std::size_t triangles = scene.mesh.triangles.size();
    for (const SceneObject& object : scene.objects) triangles += object.mesh ? object.mesh->triangles.size() : 0;
    check_dataset_files(files, options, triangles, object_first_triangles(scene).size());
}

void write_dataset_files(const AovPlanes& planes, const std::vector<std::size_t>& object_first_triangles,
                         const std::string& colour_path, const DatasetFiles& files, const DatasetFileOptions& options) {
    const std::string stem = stem_path(colour_path);
    const std::size_t pixels = static_cast<std::size_t>(planes.rows) * static_cast<std::size_t>(planes.columns);
    // Everything is converted (and checked) first, so that a bad value leaves no file written.
    std::vector<std::uint16_t> depth16, id16, object16;
    std::vector<std::uint8_t> mask8, normal8;
    if (files.depth) require_plane(planes.depth.size() == pixels, "depth", stem + ".depth.exr");
    if (files.distance) require_plane(planes.distance.size() == pixels, "distance", stem + ".distance.exr");
    if (files.depth16) {
        require_plane(planes.depth.size() == pixels, "depth", stem + ".depth.png");
        depth16 = depth_steps(planes.depth, options.depth_scale, stem + ".depth.png");
    }
    if (files.mask) {
        require_plane(planes.alpha.size() == pixels, "alpha", stem + ".mask.png");
        mask8.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) mask8[p] = detail::to_8_bit(planes.alpha[p]);
    }
    if (files.id || files.object) require_plane(planes.id.size() == pixels, "id", stem + ".id.png");
    if (files.id) {
        id16.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) {
            const std::int32_t id = planes.id[p];
            if (static_cast<std::int64_t>(id) + 1 > static_cast<std::int64_t>(kLargest16Bit)) {
                throw FileError(stem + ".id.png: triangle " + std::to_string(id) + " does not fit a 16-bit PNG");
            }
            id16[p] = static_cast<std::uint16_t>(id < 0 ? 0 : id + 1);
        }
    }
    if (files.object) {
        if (object_first_triangles.empty() || object_first_triangles.size() > kLargest16Bit - 1) {
            throw FileError(stem + ".object.png: needs the scene's objects (1 to 65534 of them), got " +
                            std::to_string(object_first_triangles.size()));
        }
        object16.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) {
            const std::int32_t id = planes.id[p];
            if (id < 0) continue;
            // The object whose range of triangles holds `id`: the last one starting at or before it.
            const auto after = std::upper_bound(object_first_triangles.begin(), object_first_triangles.end(),
                                                static_cast<std::size_t>(id));
            object16[p] = static_cast<std::uint16_t>(after - object_first_triangles.begin());
        }
    }
    if (files.normal) {
        require_plane(planes.normal.size() == pixels, "normal", stem + ".normal.png");
        normal8.resize(3 * pixels);
        for (std::size_t p = 0; p < pixels; ++p) {
            const glm::vec3& n = planes.normal[p];
            const bool background = n.x == 0.0f && n.y == 0.0f && n.z == 0.0f;
            for (int c = 0; c < 3; ++c) {
                normal8[3 * p + static_cast<std::size_t>(c)] = background ? 0 : detail::to_8_bit((n[c] + 1.0f) * 0.5f);
            }
        }
    }

    if (files.depth) write_float_exr(stem + ".depth.exr", planes.depth, planes.rows, planes.columns);
    const int rows = planes.rows, columns = planes.columns;
    if (files.depth16) write_png_file(stem + ".depth.png", depth16.data(), rows, columns, 1, 16, options);
    if (files.mask) write_png_file(stem + ".mask.png", mask8.data(), rows, columns, 1, 8, options);
    if (files.id) write_png_file(stem + ".id.png", id16.data(), rows, columns, 1, 16, options);
    if (files.normal) write_png_file(stem + ".normal.png", normal8.data(), rows, columns, 3, 8, options);
    if (files.object) write_png_file(stem + ".object.png", object16.data(), rows, columns, 1, 16, options);
    if (files.distance) write_float_exr(stem + ".distance.exr", planes.distance, rows, columns);
}

}  // namespace phongrast::io
