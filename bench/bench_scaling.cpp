// bench_scaling: how phongrast's render time grows with the triangle count and with
// the image size, Gouraud and Phong, 1 and 2 threads (RenderOptions::exact()).
//
// Two sweeps over the llvmpipe comparison's dented, coloured icosphere
// (tests/support/scenes.cpp, three lights):
//   * triangles: 20 f^2 triangles for f = 7 .. 447 (980 .. 3,996,180) at 1024 x 1024;
//   * pixels:    the 15,680-triangle sphere at 256^2 .. 4096^2;
// and two more at one size each:
//   * lighting:  the 15,680-triangle sphere at 1024^2, flat/Gouraud/Phong x
//                ambient, diffuse, specular and full lighting;
//   * meshes:    each mesh of ../shared/assets at 512^2, framed by io::frame_mesh
//                along the view its README suggests, Gouraud and Phong; skipped,
//                saying so, when the folder is absent.
// Each benchmark reports the counters `triangles` and `samples` (samples shaded)
// so bench/report.py scaling can fit time against both on log-log axes.
//
// Usage: bench_scaling [--quick] [Google Benchmark flags]
//   --quick: the triangle and pixel sweeps up to 256k triangles and 2048^2 (the lighting
//            and meshes sweeps run in full either way): a few minutes on 2 cores.
#include <benchmark/benchmark.h>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <cstdio>

#include "phongrast/render.hpp"
#include "support/scenes.hpp"
#include "support/shared_scenes.hpp"

namespace {

/// Scenes are generated once per (frequency, rows) and kept for every benchmark that uses them.
const phongrast::Scene& cached_scene(int frequency, int rows) {
    static std::map<std::pair<int, int>, std::unique_ptr<phongrast::support::NamedScene>> cache;
    auto& slot = cache[{frequency, rows}];
    if (!slot) {
        slot = std::make_unique<phongrast::support::NamedScene>(
            phongrast::support::icosphere_scene("icosphere", frequency, rows));
    }
    return slot->scene;
}

void render_case(benchmark::State& state, const phongrast::Scene& scene, int threads) {
    const int rows = scene.image.rows;
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = threads;
    phongrast::RenderStats stats;
    phongrast::Renderer renderer(options);  // frames after the first allocate nothing
    for (auto _ : state) {
        const phongrast::RenderResult& result = renderer.render(scene);
        stats = result.stats;
        benchmark::DoNotOptimize(result.image.pixels.data());
    }
    state.counters["triangles"] = static_cast<double>(scene.mesh.triangles.size());
    state.counters["samples"] = static_cast<double>(stats.samples_shaded);
    state.counters["pixels"] = static_cast<double>(rows) * scene.image.columns;
}

void register_case(const std::string& sweep, int frequency, int rows, phongrast::Shader shader, int threads) {
    const std::string name = sweep + "/" + phongrast::to_string(shader) + "/threads:" + std::to_string(threads) +
                             "/triangles:" + std::to_string(20 * frequency * frequency) +
                             "/rows:" + std::to_string(rows);
    benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
        phongrast::Scene scene = cached_scene(frequency, rows);  // a copy: the shader differs per case
        scene.shader = shader;
        render_case(state, scene, threads);
    })->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.2);
}

/// A case of the lighting or meshes sweep: a ready scene under its own name.
void register_scene(const std::string& name, const phongrast::Scene& scene, int threads) {
    benchmark::RegisterBenchmark(name.c_str(), [scene, threads](benchmark::State& state) {
        render_case(state, scene, threads);
    })->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.2);
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::vector<char*> arguments;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) {
            quick = true;
        } else {
            arguments.push_back(argv[i]);
        }
    }
    // 20 f^2 triangles: 980, 3,920, 15,680, 64,980, 255,380, 1,003,520, 3,996,180.
    const std::vector<int> frequencies =
        quick ? std::vector<int>{7, 28, 113} : std::vector<int>{7, 14, 28, 57, 113, 224, 447};
    const std::vector<int> sides = quick ? std::vector<int>{256, 512, 1024, 2048}
                                         : std::vector<int>{256, 512, 1024, 2048, 4096};
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        for (int threads : {1, 2}) {
            for (int frequency : frequencies) register_case("triangles", frequency, 1024, shader, threads);
            for (int rows : sides) register_case("pixels", 28, rows, shader, threads);
        }
    }
    const phongrast::Lighting lightings[] = {phongrast::Lighting::only_ambient(), phongrast::Lighting::only_diffuse(),
                                             phongrast::Lighting::only_specular(), phongrast::Lighting::full()};
    for (phongrast::Shader shader : {phongrast::Shader::flat, phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        for (const phongrast::Lighting& lighting : lightings) {
            for (int threads : {1, 2}) {
                phongrast::Scene scene = cached_scene(28, 1024);
                scene.shader = shader;
                scene.lighting = lighting;
                register_scene("lighting/" + std::string(phongrast::to_string(shader)) + "/threads:" +
                                   std::to_string(threads) + "/lighting:" + phongrast::to_string(lighting) +
                                   "/triangles:15680/rows:1024",
                               scene, threads);
            }
        }
    }
    std::vector<std::string> notes;
    for (phongrast::support::NamedScene& named : phongrast::support::comparison_scenes(512, notes)) {
        for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
            for (int threads : {1, 2}) {
                named.scene.shader = shader;
                register_scene("meshes/" + std::string(phongrast::to_string(shader)) + "/threads:" +
                                   std::to_string(threads) + "/mesh:" + named.name + "/triangles:" +
                                   std::to_string(named.scene.mesh.triangles.size()) + "/rows:512",
                               named.scene, threads);
            }
        }
    }
    for (const std::string& note : notes) std::fprintf(stderr, "bench_scaling: %s\n", note.c_str());
    int count = static_cast<int>(arguments.size());
    benchmark::Initialize(&count, arguments.data());
    if (benchmark::ReportUnrecognizedArguments(count, arguments.data())) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
