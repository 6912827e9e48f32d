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
#include "same_render_stats.hpp"
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
    // Ambient only, small triangles: filled in walks of the mesh (fill_driver.hpp), one per thread.
    for (int threads : {2, 1}) {
        Scene ambient = sphere(22, 66, 74, Shader::gouraud, threads == 2);
        ambient.lighting = Lighting::only_ambient();
        RenderOptions walked = exact;
        walked.threads = threads;
        frames.push_back({ambient, walked, "ambient only, filled in mesh order, " + std::to_string(threads) + " thread(s)"});
    }
    // Lit Gouraud and flat, small triangles, one thread: one walk of the mesh.
    for (Shader shader : {Shader::gouraud, Shader::flat}) {
        RenderOptions one_walk = exact;
        one_walk.threads = 1;
        frames.push_back({sphere(22, 66, 74, shader, false), one_walk, "lit, filled in mesh order, 1 thread"});
    }
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
        release_render_memory();  // render() from fresh memory
        const RenderResult fresh = render(frame.scene, frame.options);
        REQUIRE(fresh.stats.samples_shaded > 100);
        CHECK(test_render_modes::same_bits(reused.image, fresh.image));
        check_same_render_stats(reused.stats, fresh.stats);
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
    release_render_memory();
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

namespace {

/// render() with the memory the thread's earlier calls left, and render()
/// from fresh memory (released first): the same bits and statistics.
void check_warm_equals_fresh(const Scene& scene, const RenderOptions& options) {
    const RenderResult warm = render(scene, options);
    release_render_memory();
    const RenderResult fresh = render(scene, options);
    REQUIRE(fresh.stats.samples_shaded > 0);
    CHECK(test_render_modes::same_bits(warm.image, fresh.image));
    check_same_render_stats(warm.stats, fresh.stats);
}

/// Two objects (a sphere and a smaller one beside it): a version-2 scene, which render() assembles.
Scene objects_scene(const std::shared_ptr<const Mesh>& first, const std::shared_ptr<const Mesh>& second) {
    Scene scene = sphere(8, 60, 70, Shader::phong, false);
    scene.mesh = Mesh{};
    scene.objects.push_back(SceneObject{first, glm::dmat4(1.0), {}, {}, {}});
    glm::dmat4 beside(0.5);
    beside[3] = glm::dvec4(1.2, 0.0, 0.0, 1.0);
    scene.objects.push_back(SceneObject{second, beside, {}, {}, {}});
    return scene;
}

}  // namespace

TEST_CASE("render() reuses its thread's memory: the same pictures as fresh memory, whatever came before") {
    // Different meshes, sizes, shaders and options in sequence, each call
    // finding the memory of the one before (a fresh call's, of another frame).
    release_render_memory();
    for (const Frame& frame : varied_frames()) {
        INFO(frame.what);
        check_warm_equals_fresh(frame.scene, frame.options);
    }
    // Back down to tiny, and an extra output, after the large ones.
    RenderOptions with_depth = RenderOptions::exact();
    with_depth.aovs.depth = true;
    const Scene tiny = sphere(6, 7, 5, Shader::gouraud, false);
    const RenderResult warm = render(tiny, with_depth);
    release_render_memory();
    const RenderResult fresh = render(tiny, with_depth);
    CHECK(test_render_modes::same_bits(warm.image, fresh.image));
    CHECK(warm.aovs.depth == fresh.aovs.depth);
}

TEST_CASE("render() forgets the scene between calls: a mesh changed in place at the same address draws anew") {
    // A Renderer would take an objects scene whose meshes keep their address
    // and sizes for the same as before; render() must not.
    auto moving = std::make_shared<Mesh>(sphere(10, 8, 8, Shader::phong, false).mesh);
    const auto still = std::make_shared<const Mesh>(sphere(6, 8, 8, Shader::phong, false).mesh);
    const Scene scene = objects_scene(moving, still);
    release_render_memory();
    const RenderResult before = render(scene);
    for (glm::dvec3& p : moving->positions) p = glm::dvec3(0.6 * p.x, 1.3 * p.y, p.z + 0.2);  // same sizes, same address
    const RenderResult after = render(scene);
    release_render_memory();
    const RenderResult fresh = render(scene);
    CHECK_FALSE(test_render_modes::same_bits(before.image, after.image));
    CHECK(test_render_modes::same_bits(after.image, fresh.image));
    check_same_render_stats(after.stats, fresh.stats);
}

TEST_CASE("computed normals are reused only while the mesh's positions and triangles are unchanged") {
    // A mesh without normals: the vertex stage computes them, and keeps them
    // for the next frame of the same positions and triangles (compared in
    // full). Each edit in place (same sizes and addresses) changes the
    // normals; every frame must be what a fresh render of the mesh as it is
    // now paints, in a Renderer and through render()'s kept memory.
    Scene scene = sphere(14, 60, 60, Shader::phong, false);
    REQUIRE(scene.mesh.normals.empty());
    Renderer renderer(RenderOptions::exact());
    const auto fresh = [&scene] {
        release_render_memory();
        const RenderResult result = render(scene);
        release_render_memory();
        return result;
    };
    const auto check_frames = [&](const char* what) {
        INFO(what);
        const RenderResult expected = fresh();
        (void)render(scene);  // kept memory holds this mesh's normals for the next call
        CHECK(test_render_modes::same_bits(render(scene).image, expected.image));
        CHECK(test_render_modes::same_bits(renderer.render(scene).image, expected.image));
        CHECK(test_render_modes::same_bits(renderer.render(scene).image, expected.image));
        return expected;
    };
    const RenderResult first = check_frames("as made");
    // The vertex facing the eye most squarely: its neighbourhood is in view.
    const glm::dvec3 towards_eye = glm::normalize(scene.camera.eye);
    std::uint32_t facing = 0;
    for (std::uint32_t v = 0; v < scene.mesh.positions.size(); ++v) {
        if (glm::dot(scene.mesh.positions[v], towards_eye) > glm::dot(scene.mesh.positions[facing], towards_eye)) facing = v;
    }
    // Moved outwards: its neighbours' normals turn.
    scene.mesh.positions[facing] *= 1.2;
    const RenderResult moved = check_frames("a vertex moved");
    CHECK_FALSE(test_render_modes::same_bits(moved.image, first.image));
    // The triangles around it wound the other way: the positions stay, their
    // faces (and so the normals they sum into) turn round.
    for (Triangle& triangle : scene.mesh.triangles) {
        if (triangle[0] == facing || triangle[1] == facing || triangle[2] == facing) std::swap(triangle[1], triangle[2]);
    }
    const RenderResult rewound = check_frames("triangles wound the other way");
    CHECK_FALSE(test_render_modes::same_bits(rewound.image, moved.image));
}

TEST_CASE("render(scene, options, out) paints render()'s picture in out's buffer when it is large enough, else trades, never copies") {
    const Scene scene = sphere(16, 64, 80, Shader::phong, false);
    const RenderOptions options = RenderOptions::exact();
    release_render_memory();
    const RenderResult expected = render(scene, options);
    RenderResult out;
    out.image = Image(3, 5, glm::vec3(7.0f));  // another size and contents: overwritten
    render(scene, options, out);
    CHECK(test_render_modes::same_bits(out.image, expected.image));
    check_same_render_stats(out.stats, expected.stats);
    // out's 3 x 5 buffer was too small: the frame was drawn in the thread's
    // kept image and traded for it. From now on out's buffer holds the frame,
    // which is drawn in it call after call: one buffer, never a copy.
    const glm::vec3* first = out.image.pixels.data();
    render(scene, options, out);
    CHECK(out.image.pixels.data() == first);
    render(scene, options, out);
    CHECK(out.image.pixels.data() == first);
    CHECK(test_render_modes::same_bits(out.image, expected.image));
    // Any buffer large enough is drawn in, whatever it held.
    out.image = Image(80, 64, glm::vec3(-3.0f));
    const glm::vec3* given = out.image.pixels.data();
    render(scene, options, out);
    CHECK(out.image.pixels.data() == given);
    CHECK(test_render_modes::same_bits(out.image, expected.image));
    // Extra outputs come with it; another scene draws what render() draws.
    RenderOptions with_depth = options;
    with_depth.aovs.depth = true;
    const Scene other = sphere(10, 40, 30, Shader::gouraud, true);
    render(other, with_depth, out);
    const RenderResult other_expected = render(other, with_depth);
    CHECK(test_render_modes::same_bits(out.image, other_expected.image));
    CHECK(out.aovs.depth == other_expected.aovs.depth);
    // A frame too large to keep (over 2048 x 2048 samples) is moved out whole.
    RenderOptions supersampled = options;
    supersampled.samples_per_axis = 3;
    const Scene large = sphere(8, 700, 700, Shader::flat, false);
    render(large, supersampled, out);
    CHECK(test_render_modes::same_bits(out.image, render(large, supersampled).image));
    release_render_memory();
}

TEST_CASE("render() from a progress callback gets its own memory, and a failed call leaves none behind") {
    const Scene outer = sphere(20, 60, 60, Shader::phong, false);
    const Scene inner = sphere(9, 30, 40, Shader::gouraud, true);
    release_render_memory();
    const RenderResult inner_alone = render(inner);
    release_render_memory();
    const RenderResult outer_alone = render(outer);
    RenderOptions nested = RenderOptions::exact();
    std::vector<Image> inner_images;
    nested.progress = [&](double) {
        if (inner_images.size() < 2) inner_images.push_back(render(inner).image);
        return true;
    };
    const RenderResult with_nested = render(outer, nested);
    REQUIRE_FALSE(inner_images.empty());  // a small frame reports at least once, from inside the call
    for (const Image& image : inner_images) CHECK(test_render_modes::same_bits(image, inner_alone.image));
    CHECK(test_render_modes::same_bits(with_nested.image, outer_alone.image));

    RenderOptions cancelling = RenderOptions::exact();
    cancelling.progress = [](double) { return false; };
    CHECK_THROWS_AS(render(outer, cancelling), RenderCancelled);
    // A call drawing in the caller's buffer that fails leaves `out` whole and usable.
    RenderResult out;
    out.image = Image(60, 60, glm::vec3(5.0f));
    CHECK_THROWS_AS(render(outer, cancelling, out), RenderCancelled);
    render(outer, RenderOptions::exact(), out);
    CHECK(test_render_modes::same_bits(out.image, outer_alone.image));
    Scene bad = inner;
    bad.camera.focal = -1.0;
    CHECK_THROWS_AS(render(bad), std::invalid_argument);
    check_warm_equals_fresh(outer, RenderOptions::exact());
}

TEST_CASE("render() keeps memory for small frames only, and a repeated small call allocates little") {
    const Scene small = sphere(16, 64, 80, Shader::phong, false);
    release_render_memory();
    const long first = allocations_during([&] { render(small); });
    const long again = allocations_during([&] { render(small); });
    CHECK(first > 10);
    // The returned image and statistics are new each time; the working memory is not.
    CHECK(again <= 4);
    // Past 262,144 triangles nothing is kept: every call allocates as the first did.
    const Scene large = sphere(260, 40, 40, Shader::flat, false);  // 520 x 518 = 269,360 triangles
    REQUIRE(large.mesh.triangles.size() > (std::size_t{1} << 18));
    release_render_memory();
    const long large_first = allocations_during([&] { render(large); });
    const long large_again = allocations_during([&] { render(large); });
    CHECK(large_again > 10);
    CHECK(large_again >= large_first / 2);
    // The large frames' memory went with them: the next small call starts afresh, then keeps again.
    CHECK(allocations_during([&] { render(small); }) > 10);
    CHECK(allocations_during([&] { render(small); }) <= 4);
}
