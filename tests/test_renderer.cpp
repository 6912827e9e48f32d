// phongrast::Renderer: frame after frame, the pictures and statistics of
// render(), and no memory allocated once it has rendered a frame at least as
// large: no allocation per triangle, nor per frame after the first.
//
// Allocations are counted by replacing the global operator new (and, so that
// every new meets its own delete, the matching deletes and nothrow forms) in
// this test executable: every std::vector, std::string or make_unique of
// phongrast's code goes through it. (oneTBB's tasks come from its own
// allocator, not counted here.)
#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return operator new(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t& nothrow) noexcept { return operator new(size, nothrow); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, const std::nothrow_t&) noexcept { std::free(memory); }
void operator delete[](void* memory, const std::nothrow_t&) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

using namespace phongrast;

namespace {

/// Allocations made by one call of frame().
template <typename Frame>
long allocations_during(Frame&& frame) {
    allocations = 0;
    counting = true;
    frame();
    counting = false;
    return allocations.load();
}

void check_same_stats(const RenderStats& a, const RenderStats& b) {
    CHECK(a.triangles_in == b.triangles_in);
    CHECK(a.triangles_culled == b.triangles_culled);
    CHECK(a.triangles_degenerate == b.triangles_degenerate);
    CHECK(a.triangles_dropped == b.triangles_dropped);
    CHECK(a.triangles_clipped == b.triangles_clipped);
    CHECK(a.triangles_outside == b.triangles_outside);
    CHECK(a.triangles_between_samples == b.triangles_between_samples);
    CHECK(a.triangles_drawn == b.triangles_drawn);
    CHECK(a.samples_covered == b.samples_covered);
    CHECK(a.samples_shaded == b.samples_shaded);
    CHECK(a.ambient_evaluations == b.ambient_evaluations);
    CHECK(a.diffuse_evaluations == b.diffuse_evaluations);
    CHECK(a.specular_evaluations == b.specular_evaluations);
    CHECK(a.normal_interpolations == b.normal_interpolations);
}

/// A coloured sphere; `close` puts the eye near the surface so that
/// triangles are clipped by the image border and the near plane.
Scene sphere(int stacks, int rows, int columns, Shader shader, bool close) {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(stacks, 2 * stacks, 1.0);
    for (std::size_t v = 0; v < scene.mesh.positions.size(); ++v) {
        const glm::dvec3& p = scene.mesh.positions[v];
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p));
    }
    scene.camera.eye = close ? glm::dvec3(0.2, 0.3, 1.05) : glm::dvec3(0.4, 0.6, 3.0);
    scene.camera.focal = close ? 0.5 : 1.5;
    scene.image = {rows, columns, {0.1f, 0.1f, 0.2f}};
    scene.material = {glm::vec3(0.1f), glm::vec3(0.7f), glm::vec3(0.5f), 16.0f};
    scene.lights = {{{2.0, 2.0, 2.0}, {1.0f, 0.9f, 0.8f}}, {{-2.0, 1.0, 0.5}, {0.3f, 0.4f, 0.9f}}};
    scene.shader = shader;
    return scene;
}

struct Frame {
    Scene scene;
    RenderOptions options;
    std::string what;
};

/// Frames that exercise every buffer: shaders, presets, precisions,
/// clipping, supersampling, depth buffer, thread counts, growing and shrinking.
std::vector<Frame> varied_frames() {
    std::vector<Frame> frames;
    const RenderOptions exact = RenderOptions::exact(), seed = RenderOptions::seed();
    frames.push_back({sphere(16, 64, 80, Shader::phong, false), exact, "small Phong"});
    frames.push_back({sphere(40, 120, 100, Shader::gouraud, true), exact, "larger Gouraud close-up, clipped"});
    frames.push_back({sphere(12, 40, 40, Shader::flat, false), seed, "smaller flat, seed"});
    RenderOptions twice = exact;
    twice.precision = Precision::double_float;
    frames.push_back({sphere(30, 90, 90, Shader::phong, true), twice, "double precision close-up"});
    RenderOptions ordered = exact;
    ordered.samples_per_axis = 2;
    frames.push_back({sphere(20, 50, 60, Shader::phong, false), ordered, "2x2 ordered grid"});
    RenderOptions rotated = ordered;
    rotated.sample_pattern = SamplePattern::rotated_grid;
    rotated.threads = 1;
    frames.push_back({sphere(20, 50, 60, Shader::gouraud, false), rotated, "2x2 rotated grid, 1 thread"});
    RenderOptions depth = exact;
    depth.visibility = Visibility::depth_buffer;
    depth.threads = 2;
    frames.push_back({sphere(24, 70, 70, Shader::phong, false), depth, "depth buffer, 2 threads"});
    frames.push_back({sphere(16, 64, 80, Shader::phong, false), exact, "the first frame again"});
    return frames;
}

}  // namespace

TEST_CASE("a Renderer paints what render() paints, frame after frame, whatever came before") {
    Renderer renderer;
    for (const Frame& frame : varied_frames()) {
        INFO(frame.what);
        renderer.set_options(frame.options);
        const RenderResult& reused = renderer.render(frame.scene);
        const RenderResult fresh = render(frame.scene, frame.options);
        REQUIRE(fresh.stats.samples_shaded > 100);
        CHECK(test_render_modes::same_bits(reused.image, fresh.image));
        check_same_stats(reused.stats, fresh.stats);
    }
}

TEST_CASE("after its first frame a Renderer allocates nothing for frames no larger") {
    // Each frame once to size the buffers; then every one of them again, in a
    // different order, larger after smaller and back: not one allocation.
    const std::vector<Frame> frames = varied_frames();
    Renderer renderer;
    for (const Frame& frame : frames) {
        renderer.set_options(frame.options);
        renderer.render(frame.scene);
    }
    for (std::size_t k = frames.size(); k-- > 0;) {
        const Frame& frame = frames[k];
        INFO(frame.what);
        renderer.set_options(frame.options);
        const long made = allocations_during([&] { renderer.render(frame.scene); });
        CHECK(made == 0);
    }
}

TEST_CASE("render() allocates per frame, a Renderer only on its first (the counter works)") {
    const Scene scene = sphere(16, 64, 80, Shader::phong, true);
    const long one_shot = allocations_during([&] { render(scene); });
    CHECK(one_shot > 10);  // the vertex arrays, the sort, the draw list, the image ...
    Renderer renderer;
    const long first = allocations_during([&] { renderer.render(scene); });
    const long second = allocations_during([&] { renderer.render(scene); });
    CHECK(first > 10);
    CHECK(second == 0);
    // A larger frame may grow the buffers: allocations are allowed, then none again.
    const Scene larger = sphere(64, 160, 160, Shader::phong, true);
    allocations_during([&] { renderer.render(larger); });
    CHECK(allocations_during([&] { renderer.render(larger); }) == 0);
    CHECK(allocations_during([&] { renderer.render(scene); }) == 0);
}
