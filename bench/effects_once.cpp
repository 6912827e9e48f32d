// Renders one effect-benchmark case once, on one thread, for instruction
// counting under valgrind --tool=callgrind (bench/report.py callgrind).
// Instruction counts do not depend on what else the machine is doing, so they
// back up the wall-clock tables of bench_effects on a shared machine.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "bench_scenes.hpp"
#include "phongrast/render.hpp"
#include "support/meshes.hpp"
#include "support/scenes.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Render one bench_effects case once (icosphere, 512 x 512, RenderOptions::exact(), 1 thread)"};
    int levels = 3;
    std::string shader = "phong", lighting = "full";
    int lights = 2, dark_lights = 0;
    bool general = false, cull = false;
    std::string aovs;
    app.add_option("--levels", levels, "icosphere of 20 x 4^levels triangles: 3 = 1,280, 6 = 81,920")->check(CLI::Range(0, 7));
    app.add_option("--shader", shader, "flat, gouraud or phong");
    app.add_option("--lighting", lighting, "ambient, diffuse, specular, full or a '+' list");
    app.add_option("--lights", lights, "lights of non-zero intensity")->check(CLI::Range(0, 64));
    app.add_option("--dark", dark_lights, "extra lights of zero intensity")->check(CLI::Range(0, 64));
    app.add_flag("--general", general, "the general kernel (RenderOptions::specialize_effects = false)");
    app.add_flag("--cull", cull, "BackFaces::cull_when_hidden");
    app.add_option("--aovs", aovs, "extra outputs to fill too: depth,normal,id,alpha or all (default none)");
    CLI11_PARSE(app, argc, argv);
    try {
        phongrast::Scene scene = phongrast_bench::effect_scene(phongrast::support::icosphere(1 << levels), 512, 512);
        scene.shader = phongrast::parse_shader(shader);
        scene.lighting = phongrast::parse_lighting(lighting);
        scene.lights = phongrast::support::lights_around(scene, lights);
        for (phongrast::PointLight dark : phongrast::support::lights_around(scene, dark_lights)) {
            dark.intensity = glm::vec3(0.0f);
            scene.lights.push_back(dark);
        }
        phongrast::RenderOptions options = phongrast::RenderOptions::exact();
        options.threads = 1;
        options.specialize_effects = !general;
        options.back_faces = cull ? phongrast::BackFaces::cull_when_hidden : phongrast::BackFaces::draw;
        if (!aovs.empty()) options.aovs = phongrast::parse_aovs(aovs);
        const phongrast::RenderStats stats = phongrast::render(scene, options).stats;
        std::printf("%llu triangles drawn, %llu culled, %llu samples shaded; %s\n",
                    static_cast<unsigned long long>(stats.triangles_drawn),
                    static_cast<unsigned long long>(stats.triangles_culled),
                    static_cast<unsigned long long>(stats.samples_shaded), phongrast::to_string(stats.effects).c_str());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_effects_once: %s\n", error.what());
        return 1;
    }
    return 0;
}
