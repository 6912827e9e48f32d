#include "texture_filters.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

#include "phongrast/render.hpp"
#include "support/image_compare.hpp"
#include "support/timing.hpp"

namespace phongrast_bench {
namespace {

using namespace phongrast;

/// 256 x 256 texels: 8 x 8-texel checks of two colours with a fine diagonal
/// ramp, so minification shows both aliasing (the checks) and blur (the ramp).
std::shared_ptr<const TextureImage> checker_texture() {
    auto image = std::make_shared<TextureImage>();
    image->rows = image->columns = 256;
    image->name = "checker";
    for (int i = 0; i < 256; ++i) {
        for (int j = 0; j < 256; ++j) {
            const bool dark = ((i / 8) + (j / 8)) % 2 == 0;
            const float ramp = float((i + j) % 16) / 15.0f;
            image->texels.push_back(dark ? glm::vec3(0.15f, 0.2f, 0.3f + 0.2f * ramp)
                                         : glm::vec3(0.95f, 0.85f - 0.3f * ramp, 0.6f));
        }
    }
    return image;
}

/// A grid of `cells` x `cells` quads spanning [x0, x1] x [z0, z1] at y = 0,
/// facing +y, with (s, t) = (x, -z) / repeat_every: the texture repeats.
Mesh textured_plane(double x0, double x1, double z0, double z1, int cells, double repeat_every) {
    Mesh mesh;
    for (int i = 0; i <= cells; ++i) {
        for (int j = 0; j <= cells; ++j) {
            const double x = x0 + (x1 - x0) * j / cells, z = z0 + (z1 - z0) * i / cells;
            mesh.positions.push_back({x, 0.0, z});
            mesh.texcoords.push_back(glm::vec2(float(x / repeat_every), float(-z / repeat_every)));
        }
    }
    const auto at = [cells](int i, int j) { return std::uint32_t(i * (cells + 1) + j); };
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            // Counter-clockwise seen from above (+y): normals point up.
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    mesh.texcoord_triangles = mesh.triangles;
    FaceMaterial material;
    material.name = "checker";
    material.texture = TextureMap{checker_texture(), TextureWrap::repeat, TextureWrap::repeat};
    mesh.materials = {material};
    mesh.face_materials.assign(mesh.triangles.size(), 0);
    mesh.normals = calculate_normals(mesh);
    return mesh;
}

Scene lit_scene(Mesh mesh, const glm::dvec3& eye, const glm::dvec3& lookat, int size) {
    Scene scene;
    scene.mesh = std::move(mesh);
    scene.camera = Camera::look_at(eye, lookat, {0.0, 1.0, 0.0}, 1.0, 1.0, 1.0);
    scene.image.rows = scene.image.columns = size;
    scene.image.background = glm::vec3(0.55f, 0.7f, 0.9f);
    scene.material = PhongMaterial{glm::vec3(0.3f), glm::vec3(0.8f), glm::vec3(0.2f), 12.0f};
    scene.ambient = glm::vec3(0.4f);
    scene.lights = {PointLight{lookat + glm::dvec3(2.0, 6.0, 3.0), glm::vec3(0.9f)}};
    scene.shader = Shader::phong;
    return scene;
}

struct FilterRow {
    const char* name;
    TextureFilter filter;
    int samples_per_axis;
};

RenderOptions options_for(const FilterRow& row, int threads) {
    RenderOptions options = RenderOptions::exact();
    options.texture_filter = row.filter;
    options.samples_per_axis = row.samples_per_axis;
    options.threads = threads;
    return options;
}

double median_ms(const Scene& scene, const RenderOptions& options, int runs) {
    Renderer renderer(options);
    renderer.render(scene);  // warm-up
    std::vector<double> times;
    for (int k = 0; k < runs; ++k) times.push_back(support::time_ms([&] { renderer.render(scene); }));
    return support::median(times);
}

std::string number(const char* format, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string table_for(const char* title, const Scene& scene, int runs) {
    RenderOptions reference_options = RenderOptions::exact();
    reference_options.samples_per_axis = 8;
    reference_options.precision = Precision::double_float;
    const Image reference = render(scene, reference_options).image;

    const FilterRow rows[] = {{"nearest", TextureFilter::nearest, 1},
                              {"bilinear (the contract)", TextureFilter::bilinear, 1},
                              {"trilinear", TextureFilter::trilinear, 1},
                              {"nearest, 4x4 samples", TextureFilter::nearest, 4},
                              {"bilinear, 4x4 samples", TextureFilter::bilinear, 4},
                              {"trilinear, 4x4 samples", TextureFilter::trilinear, 4}};
    std::ostringstream md;
    md << "#### " << title << "\n\n"
       << "| filter | RMSE | PSNR dB | max err | px > 1/255 | ms, 1 thread | ms, all threads |\n"
       << "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const FilterRow& row : rows) {
        const support::ErrorMetrics error = support::compare(render(scene, options_for(row, 1)).image, reference);
        md << "| " << row.name << " | " << number("%.3g", error.rmse) << " | " << number("%.1f", error.psnr_db)
           << " | " << number("%.3g", error.max_abs) << " | " << number("%.1f", 100.0 * error.share_off) << "% | "
           << number("%.2f", median_ms(scene, options_for(row, 1), runs)) << " | "
           << number("%.2f", median_ms(scene, options_for(row, 0), runs)) << " |\n";
    }
    md << "\n";
    return md.str();
}

}  // namespace

std::string texture_filter_section(int size, int runs) {
    // The floor: 400 x 400 units seen from 1.5 above it, the texture repeating
    // every 2 units: near the horizon hundreds of texels fall into one pixel.
    const Scene floor = lit_scene(textured_plane(-200.0, 200.0, -400.0, 0.0, 40, 2.0), {0.0, 1.5, 0.0},
                                  {0.0, 0.0, -8.0}, size);
    // The close-up: a plane under a camera looking straight down from 1.1
    // units; the view is 1.1 units wide and the texture repeats every 8, so
    // about 35 texels span 256 pixels: each texel magnified about 7 times.
    const Scene close_up =
        lit_scene(textured_plane(-1.0, 1.0, -1.0, 1.0, 4, 8.0), {0.0, 1.1, 0.0}, {0.0, 0.0, -1e-3}, size);
    std::ostringstream md;
    md << "### Texture filters\n\n"
       << "Phong, exact mode, " << size << "x" << size << " pixels, a 256 x 256 checker texture; the reference "
       << "is bilinear with 8 x 8 samples in double, the texture averaged over each pixel's area. Times are medians of "
       << runs << " runs after a warm-up.\n\n"
       << table_for("floor to the horizon (minified)", floor, runs)
       << table_for("close-up (magnified: about 7 x 7 pixels per texel at 256 x 256)", close_up, runs);
    return md.str();
}

}  // namespace phongrast_bench
