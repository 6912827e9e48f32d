// Tasks of the render's parallel loops (task_sizes.hpp): a small mesh on
// several threads is set up and transformed in smaller tasks than a large
// one, so that each thread gets several. Where tasks start must change
// nothing but the speed: the same image and counts at any number of threads.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "draw_span.hpp"
#include "phongrast/render.hpp"
#include "same_render_stats.hpp"
#include "support/scenes.hpp"
#include "task_sizes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using phongrast::detail::items_per_task;
using phongrast::detail::kTasksPerThread;
using test_render_modes::same_bits;

TEST_CASE("items_per_task: the largest tasks on one thread or for a large loop, else several per thread") {
    constexpr std::size_t kLargest = 4096, kSmallest = 512;
    CHECK(items_per_task(5856, 1, kLargest, kSmallest) == kLargest);
    CHECK(items_per_task(5856, 0, kLargest, kSmallest) == kLargest);
    CHECK(items_per_task(10'000'000, 2, kLargest, kSmallest) == kLargest);
    CHECK(items_per_task(100, 8, kLargest, kSmallest) == kSmallest);
    // spot's 5,856 triangles at 2 threads: 1,024 per task, 6 tasks, not 4,096 + 1,760.
    CHECK(items_per_task(5856, 2, kLargest, kSmallest) == 1024);
    for (std::size_t items : {0u, 1u, 511u, 513u, 4000u, 9680u, 32767u, 32768u, 32769u, 100000u}) {
        for (int threads : {2, 3, 4, 7, 64}) {
            const std::size_t size = items_per_task(items, threads, kLargest, kSmallest);
            INFO(items << " items, " << threads << " threads: " << size);
            CHECK(size >= kSmallest);
            CHECK(size <= kLargest);
            CHECK((size & (size - 1)) == 0);  // a power of two, so a whole number of smaller batches
            // Smaller than the largest only when the largest would leave a thread short of tasks,
            // and then no smaller than the nearest power of two above a thread's share.
            if (size < kLargest) {
                CHECK(items < kLargest * kTasksPerThread * static_cast<std::size_t>(threads));
                CHECK((size == kSmallest || size / 2 < items / (kTasksPerThread * static_cast<std::size_t>(threads))));
            }
        }
    }
}

TEST_CASE("a small mesh renders the same at any number of threads, whatever its set-up chunks and vertex blocks") {
    // 5,780 and fewer triangles: at 1 thread one or two chunks of kSetupChunk, at 2 to 4 chunks of 512-1,024.
    std::vector<support::NamedScene> scenes = {support::icosphere_scene("icosphere", 17, 192),
                                               support::floor_scene(160), support::sphere_scene(160)};
    REQUIRE(scenes[0].scene.mesh.triangles.size() < detail::kSetupChunk * 2);
    REQUIRE(items_per_task(scenes[0].scene.mesh.triangles.size(), 2, detail::kSetupChunk,
                           detail::kSmallestSetupChunk) < detail::kSetupChunk);
    for (support::NamedScene& named : scenes) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            for (bool seed : {false, true}) {
                named.scene.shader = shader;
                RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
                options.threads = 1;
                const RenderResult one = render(named.scene, options);
                for (int threads : {2, 3, 4}) {
                    INFO(named.name << ", shader " << static_cast<int>(shader) << (seed ? ", seed" : ", exact")
                                    << ", " << threads << " threads");
                    options.threads = threads;
                    // A new Renderer: render()'s memory kept from the call before would still hold
                    // that call's vertices and records, so a task that skipped some could go unseen.
                    Renderer renderer(options);
                    const RenderResult& several = renderer.render(named.scene);
                    CHECK(same_bits(one.image, several.image));
                    check_same_render_stats(one.stats, several.stats);
                    CHECK(several.stats.triangles_drawn > 0);
                }
            }
        }
    }
}
