#include "resolve.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace phongrast::detail {
namespace {

/// Adds one pass's work to the total; the triangle counts are each pass's alike.
void add_pass_work(const RenderStats& pass, RenderStats& total) {
    for (const RenderCounter& counter : render_counters()) {
        if (!counter.counts_triangles) total.*counter.field += pass.*counter.field;
    }
}

void resize_like(Image& image, int rows, int columns) {
    image.rows = rows;
    image.columns = columns;
    image.pixels.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
}

// One render per sample at the final size, averaged like box_downsample() does.
void resolve_rotated_grid(const Scene& scene, int factor, PassRenderer& passes, ResolveImages& images,
                          RenderResult& result) {
    Image& sum = images.sum;
    resize_like(sum, scene.image.rows, scene.image.columns);
    std::fill(sum.pixels.begin(), sum.pixels.end(), glm::vec3(0.0f));
    const std::uint64_t triangles_in = result.stats.triangles_in;
    for (int i = 0; i < factor; ++i) {
        for (int j = 0; j < factor; ++j) {
            RenderStats pass_stats;
            pass_stats.triangles_in = triangles_in;
            passes.render_pass(sum.rows, sum.columns, rotated_grid_offset(i, j, factor), pass_stats, images.pass);
            for (std::size_t p = 0; p < sum.pixels.size(); ++p) sum.pixels[p] += images.pass.pixels[p];
            if (i == 0 && j == 0) {
                result.stats = pass_stats;
            } else {
                add_pass_work(pass_stats, result.stats);
            }
        }
    }
    const float weight = 1.0f / static_cast<float>(factor * factor);
    resize_like(result.image, sum.rows, sum.columns);
    for (std::size_t p = 0; p < sum.pixels.size(); ++p) result.image.pixels[p] = sum.pixels[p] * weight;
}

}  // namespace

void render_and_resolve(const Scene& scene, const RenderOptions& options, PassRenderer& passes,
                        ResolveImages& images, RenderResult& result) {
    const int factor = options.samples_per_axis;
    if (factor > 1 && options.sample_pattern == SamplePattern::rotated_grid) {
        resolve_rotated_grid(scene, factor, passes, images, result);
    } else if (factor == 1) {
        passes.render_pass(scene.image.rows, scene.image.columns, glm::dvec2(0.0), result.stats, result.image);
    } else {
        passes.render_pass(scene.image.rows * factor, scene.image.columns * factor, glm::dvec2(0.0), result.stats,
                           images.samples);
        box_downsample(images.samples, factor, scene.image.rows, scene.image.columns, result.image);
    }
}

// Sample k = i * s + j of an s x s set sits at
//   column offset (i s + j + 1/2) / s^2 - 1/2,  row offset (j s + (s - 1 - i) + 1/2) / s^2 - 1/2,
// a lattice whose s^2 samples all have distinct columns and distinct rows
// (for s = 2: (+-1/8, +-3/8) and (+-3/8, -+1/8), the classic rotated grid).
// The offsets are multiples of 1/(2 s^2) pixel, exact after 1/256 snapping for s <= 8.
glm::dvec2 rotated_grid_offset(int i, int j, int s) {
    const double cells = double(s) * double(s);
    return {(double(i * s + j) + 0.5) / cells - 0.5, (double(j * s + (s - 1 - i)) + 0.5) / cells - 0.5};
}

void box_downsample(const Image& samples, int factor, int rows, int columns, Image& pixels) {
    resize_like(pixels, rows, columns);
    const float weight = 1.0f / static_cast<float>(factor * factor);
    // Rows in parallel (each pixel's sum is the same as on one thread): on
    // one thread a 2048² sample image took 10 ms, and 150 ms under load,
    // after the fill's last progress report.
    tbb::parallel_for(0, rows, [&](int row) {
        for (int column = 0; column < columns; ++column) {
            glm::vec3 sum(0.0f);
            for (int dy = 0; dy < factor; ++dy) {
                for (int dx = 0; dx < factor; ++dx) sum += samples.at(row * factor + dy, column * factor + dx);
            }
            pixels.at(row, column) = sum * weight;
        }
    });
}

}  // namespace phongrast::detail
