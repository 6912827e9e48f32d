// bench_effects: what each effect set costs, specialised kernel against
// the general one (RenderOptions::specialize_effects = false, the baseline,
// measured in the same process), Gouraud and Phong, 0 to 8 lights, and
// back-face culling on closed meshes, with 1 and 2 render threads.
//
// Every benchmark is named key=value/key=value/... so that
// bench/report.py effects can turn the JSON output into docs tables:
//   effects/mesh=icosphere/shader=phong/effect=full/lights=2/dark=0/kernel=special/cull=off/threads=1
// Times are wall-clock (the render runs on a oneTBB arena of `threads` workers).
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_meshes.hpp"
#include "bench_scenes.hpp"
#include "phongrast/render.hpp"
#include "support/scenes.hpp"

namespace {

using phongrast::Shader;
using namespace phongrast_bench;

/// Case::lights value meaning "keep the lights the scene file gives".
constexpr int kSceneLights = -1;

struct Case {
    const BenchMesh* mesh = nullptr;
    Shader shader = Shader::phong;
    EffectVariant effect;
    int lights = 2;       ///< lights with non-zero intensity; kSceneLights: the scene's own
    int dark_lights = 0;  ///< extra lights of zero intensity (should cost nothing)
    bool specialized = true;
    bool cull = false;
    int threads = 1;

    std::string name() const {
        return "effects/mesh=" + mesh->name + "/shader=" + phongrast::to_string(shader) + "/effect=" + effect.name +
               "/lights=" + (lights == kSceneLights ? std::string("scene") : std::to_string(lights)) + "/dark=" + std::to_string(dark_lights) +
               "/kernel=" + (specialized ? "special" : "general") + "/cull=" + (cull ? "on" : "off") +
               "/threads=" + std::to_string(threads);
    }
};

std::set<std::string> g_registered;

// The case's scene, built when its benchmark starts (not at registration, so
// only one copy of a large mesh exists at a time).
phongrast::Scene make_scene(const Case& c) {
    phongrast::Scene scene = with_effect(c.mesh->scene, c.effect);
    scene.shader = c.shader;
    if (c.lights != kSceneLights) scene.lights = phongrast::support::lights_around(scene, c.lights);
    const std::vector<phongrast::PointLight> extra = phongrast::support::lights_around(scene, c.dark_lights);
    for (phongrast::PointLight dark : extra) {
        dark.intensity = glm::vec3(0.0f);
        scene.lights.push_back(dark);
    }
    return scene;
}

phongrast::RenderOptions make_options(const Case& c) {
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.specialize_effects = c.specialized;
    options.back_faces = c.cull ? phongrast::BackFaces::cull_when_hidden : phongrast::BackFaces::draw;
    options.threads = c.threads;
    return options;
}

void render_case(benchmark::State& state, const Case& c) {
    const phongrast::Scene scene = make_scene(c);
    const phongrast::RenderOptions options = make_options(c);
    phongrast::RenderStats stats;
    for (auto _ : state) {
        phongrast::RenderResult result = phongrast::render(scene, options);
        benchmark::DoNotOptimize(result.image.pixels.data());
        stats = result.stats;
    }
    // What the last render did: the script checks these, and they explain the times.
    state.counters["samples"] = static_cast<double>(stats.samples_shaded);
    state.counters["drawn"] = static_cast<double>(stats.triangles_drawn);
    state.counters["culled"] = static_cast<double>(stats.triangles_culled);
    state.counters["ambient_evals"] = static_cast<double>(stats.ambient_evaluations);
    state.counters["diffuse_evals"] = static_cast<double>(stats.diffuse_evaluations);
    state.counters["specular_evals"] = static_cast<double>(stats.specular_evaluations);
    state.counters["normal_interps"] = static_cast<double>(stats.normal_interpolations);
    state.SetLabel(phongrast::to_string(stats.effects) + (stats.back_faces_culled ? ", back faces culled" : ""));
}

void register_case(const Case& c) {
    const std::string name = c.name();
    if (!g_registered.insert(name).second) return;  // the sweeps overlap; measure each case once
    benchmark::RegisterBenchmark(name.c_str(), render_case, c)->UseRealTime()->Unit(benchmark::kMillisecond);
}

EffectVariant find_effect(const std::string& name) {
    for (const EffectVariant& v : effect_variants()) {
        if (v.name == name) return v;
    }
    return effect_variants().front();
}

void register_mesh(const BenchMesh& mesh) {
    const EffectVariant full = find_effect("full");
    // The effect table and culling use the scene file's own lights when it has
    // them (the default scene), else two generated ones.
    const int table_lights = mesh.own_lights ? kSceneLights : 2;
    for (int threads : {1, 2}) {
        for (bool specialized : {true, false}) {
            // Each effect set, every shader, two lights.
            for (const EffectVariant& effect : effect_variants()) {
                for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
                    register_case({&mesh, shader, effect, table_lights, 0, specialized, false, threads});
                }
            }
            for (Shader shader : {Shader::gouraud, Shader::phong}) {
                // Cost against the number of lights (all terms on).
                for (int lights : {0, 1, 2, 4, 8}) {
                    register_case({&mesh, shader, full, lights, 0, specialized, false, threads});
                }
                // Two lights plus six of zero intensity: should cost what two cost.
                register_case({&mesh, shader, full, 2, 6, specialized, false, threads});
            }
        }
        for (Shader shader : {Shader::gouraud, Shader::phong}) {
            register_case({&mesh, shader, full, table_lights, 0, true, true, threads});
        }
    }
}

// Culling only: a closed mesh where painter's order shows back faces.
void register_culling_only(const BenchMesh& mesh) {
    const EffectVariant full = find_effect("full");
    for (int threads : {1, 2}) {
        for (Shader shader : {Shader::gouraud, Shader::phong}) {
            for (bool cull : {false, true}) register_case({&mesh, shader, full, 2, 0, true, cull, threads});
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    const std::vector<BenchMesh>& meshes = bench_meshes();
    for (const BenchMesh& mesh : meshes) {
        if (mesh.culling_only) {
            register_culling_only(mesh);
        } else {
            register_mesh(mesh);
        }
    }
    for (const std::string& note : bench_mesh_notes()) std::fprintf(stderr, "bench_effects: %s\n", note.c_str());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
