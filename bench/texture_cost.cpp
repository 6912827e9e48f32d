// bench_texture_cost [phong|gouraud|flat]: what a texture map costs. A
// 1024 x 1024 render with the shader given (Phong when none; exact mode, two
// lights, normals given) of a ~100k-triangle sphere textured with a
// 1024 x 1024 image (spherical (s, t), bilinear and nearest), against the same
// sphere untextured (a version-1 mesh), in interleaved rounds in one process
// so a change in the machine's load hits every contender alike. When OSMesa
// was found at configure time, Mesa's llvmpipe draws the same two scenes too
// (tests/support/llvmpipe_renderer: GL_LINEAR on level 0, T x A + S, its own
// painter's sort; Gouraud and Phong only), with LP_NUM_THREADS set to the
// cores phongrast uses. Prints one Markdown row per contender: median
// milliseconds, the ratio to phongrast untextured, and to llvmpipe on the
// same scene. `bench_texture_cost SHADER profile CONTENDER` (untextured,
// bilinear or nearest) renders that one contender 30 times, for a profiler
// (perf record -g) to see it alone, and prints a hash of its picture's bits,
// so that a change meant to keep every bit can be checked against the last.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "phongrast/render.hpp"
#include "support/meshes.hpp"
#include "support/timing.hpp"
#ifdef PHONGRAST_HAVE_LLVMPIPE
#include "support/llvmpipe_renderer.hpp"
#endif

namespace {

using namespace phongrast;

std::shared_ptr<const TextureImage> procedural_texture(int size) {
    auto image = std::make_shared<TextureImage>();
    image->rows = image->columns = size;
    image->name = "procedural";
    image->texels.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i) {
        for (int j = 0; j < size; ++j) {
            const bool check = ((i / 32) + (j / 32)) % 2 == 0;
            image->texels.push_back(glm::vec3(check ? 0.9f : 0.3f, float(i) / float(size), float(j) / float(size)));
        }
    }
    return image;
}

Scene sphere_scene(const Mesh& mesh, Shader shader) {
    Scene scene;
    scene.mesh = mesh;
    scene.camera.eye = glm::dvec3(0.0, 0.0, 2.6);
    scene.camera.lookat = glm::dvec3(0.0);
    scene.image.rows = scene.image.columns = 1024;
    scene.material = PhongMaterial{glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(0.5f), 16.0f};
    scene.lights = {PointLight{glm::dvec3(3.0, 4.0, 5.0), glm::vec3(1.0f)},
                    PointLight{glm::dvec3(-4.0, 1.0, 3.0), glm::vec3(0.4f, 0.5f, 0.7f)}};
    scene.shader = shader;
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    Shader shader = Shader::phong;
    std::string profiled;  // a contender rendered alone, for a profiler
    if (argc == 4 && std::string(argv[2]) == "profile") {
        profiled = argv[3];
        if (profiled != "untextured" && profiled != "bilinear" && profiled != "nearest") {
            std::fprintf(stderr, "bench_texture_cost: unknown contender '%s' (expected untextured, bilinear or nearest)\n",
                         argv[3]);
            return 2;
        }
    } else if (argc > 2) {
        std::fprintf(stderr, "usage: bench_texture_cost [phong|gouraud|flat] [profile untextured|bilinear|nearest]\n");
        return 2;
    }
    if (argc > 1) {
        const std::string name = argv[1];
        if (name == "gouraud") {
            shader = Shader::gouraud;
        } else if (name == "flat") {
            shader = Shader::flat;
        } else if (name != "phong") {
            std::fprintf(stderr, "bench_texture_cost: unknown shader '%s' (expected phong, gouraud or flat)\n", argv[1]);
            return 2;
        }
    }
    // Normals given, as llvmpipe needs them: neither renderer computes them per frame.
    Mesh sphere = support::icosphere(71);  // 100,820 triangles
    sphere.normals = calculate_normals(sphere);
    Mesh textured = sphere;
    constexpr double kPi = 3.14159265358979323846;
    for (const glm::dvec3& p : sphere.positions) {
        const glm::dvec3 n = glm::normalize(p);
        textured.texcoords.push_back(
            glm::vec2(float(0.5 + std::atan2(n.z, n.x) / (2.0 * kPi)), float(0.5 + std::asin(n.y) / kPi)));
    }
    textured.texcoord_triangles = sphere.triangles;
    FaceMaterial material;
    material.name = "procedural";
    material.texture = TextureMap{procedural_texture(1024), TextureWrap::repeat, TextureWrap::repeat};
    textured.materials = {material};
    textured.face_materials.assign(sphere.triangles.size(), 0);

    const Scene plain = sphere_scene(sphere, shader), with_texture = sphere_scene(textured, shader);
    RenderOptions bilinear = RenderOptions::exact(), nearest = RenderOptions::exact();
    nearest.texture_filter = TextureFilter::nearest;
    Renderer untextured_renderer(bilinear), bilinear_renderer(bilinear), nearest_renderer(nearest);
    const auto timed = [](Renderer& renderer, const Scene& scene) {
        return [&renderer, &scene] { return support::time_ms([&] { renderer.render(scene); }); };
    };
    if (!profiled.empty()) {
        Renderer& renderer = profiled == "untextured" ? untextured_renderer
                             : profiled == "bilinear" ? bilinear_renderer
                                                      : nearest_renderer;
        const Scene& scene = profiled == "untextured" ? plain : with_texture;
        const RenderResult* result = nullptr;
        for (int i = 0; i < 30; ++i) result = &renderer.render(scene);
        std::uint64_t hash = 14695981039346656037ull;  // FNV-1a over the pixels' bytes
        const auto* bytes = reinterpret_cast<const unsigned char*>(result->image.pixels.data());
        for (std::size_t i = 0; i < result->image.pixels.size() * sizeof(glm::vec3); ++i) {
            hash = (hash ^ bytes[i]) * 1099511628211ull;
        }
        std::printf("%s %s: picture hash %016llx, %llu samples covered, %llu shaded\n", argv[1], argv[3],
                    static_cast<unsigned long long>(hash), static_cast<unsigned long long>(result->stats.samples_covered),
                    static_cast<unsigned long long>(result->stats.samples_shaded));
        return 0;
    }
    std::vector<std::string> names = {"phongrast untextured", "phongrast textured, bilinear",
                                      "phongrast textured, nearest"};
    std::vector<std::function<double()>> contenders = {timed(untextured_renderer, plain),
                                                       timed(bilinear_renderer, with_texture),
                                                       timed(nearest_renderer, with_texture)};
#ifdef PHONGRAST_HAVE_LLVMPIPE
    // Two contexts, each holding one scene, drawn in the same interleaved rounds.
    // LP_NUM_THREADS is read when the first context is created.
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    setenv("LP_NUM_THREADS", std::to_string(cores).c_str(), 1);
    support::LlvmpipeRenderer llvmpipe_plain, llvmpipe_textured;
    if (shader != Shader::flat) {
        llvmpipe_plain.load(plain);
        llvmpipe_textured.load(with_texture);
        names.insert(names.end(), {"llvmpipe untextured", "llvmpipe textured"});
        contenders.push_back([&] { return 1e3 * llvmpipe_plain.draw().total; });
        contenders.push_back([&] { return 1e3 * llvmpipe_textured.draw().total; });
    }
    std::printf("llvmpipe: %s, LP_NUM_THREADS=%u\n\n", llvmpipe_plain.description().c_str(), cores);
#endif
    const std::vector<double> medians = support::interleaved_medians(9, 1, contenders);
    const bool with_llvmpipe = medians.size() == 5;
    std::printf("| render (1024 x 1024, %s, exact, %zu triangles, all cores) | median ms | / phongrast untextured | / llvmpipe, same scene |\n",
                to_string(shader), sphere.triangles.size());
    std::printf("|---|---|---|---|\n");
    for (std::size_t i = 0; i < medians.size(); ++i) {
        const bool is_textured = i == 1 || i == 2 || i == 4;
        std::string versus_llvmpipe = "";
        if (with_llvmpipe && i < 3) {
            char ratio[32];  // rounded like the other columns (not cut off)
            std::snprintf(ratio, sizeof ratio, "%.2f", medians[i] / medians[is_textured ? 4 : 3]);
            versus_llvmpipe = ratio;
        }
        std::printf("| %s | %.1f | %.2f | %s |\n", names[i].c_str(), medians[i], medians[i] / medians[0],
                    versus_llvmpipe.c_str());
    }
    return 0;
}
