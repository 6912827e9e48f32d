// The fill in mesh order (fill_in_mesh_order(), fill_driver.hpp): an
// ambient-only render sets up and fills each triangle in a walk of the mesh
// (one per thread, each over its own rows), keeping painter's order by a
// rank test per sample instead of a sort; with an even number of walks, the
// mesh in two halves whose ranks and colours are merged after. It must paint
// painter's picture bit for bit, with the same counts, whatever the shader, mode, precision,
// colours, materials, ties of equal depth, clipping, supersampling, mesh
// order, threads or walks; and it must be the path an ambient-only render takes.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_dispatch.hpp"
#include "fill_driver.hpp"
#include "mesh_order.hpp"
#include "shuffled_mesh.hpp"
#include "same_render_stats.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

/// Sets one of the fill's test switches (fill_driver.hpp) for one scope, then puts back what it was.
template <typename T>
class ScopedSwitch {
public:
    ScopedSwitch(T (*set)(T), T value) : set_(set), previous_(set(value)) {}
    ~ScopedSwitch() { set_(previous_); }
    ScopedSwitch(const ScopedSwitch&) = delete;
    ScopedSwitch& operator=(const ScopedSwitch&) = delete;

private:
    T (*set_)(T);
    T previous_;
};

/// When the fill in mesh order is taken (by triangle size, always, never).
struct MeshOrderFill : ScopedSwitch<detail::WalkChoice> {
    explicit MeshOrderFill(detail::WalkChoice choice)
        : ScopedSwitch<detail::WalkChoice>(detail::set_mesh_order_walk_choice, choice) {}
};

/// Splits the fill in mesh order into `walks` walks (0: one per thread).
struct MeshOrderWalks : ScopedSwitch<int> {
    explicit MeshOrderWalks(int walks) : ScopedSwitch<int>(detail::set_mesh_order_walks, walks) {}
};

/// A coloured sphere seen from outside: its back faces lie under its front
/// faces, so most samples are painted twice and painter's order decides.
Scene coloured_sphere_scene() {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(14, 26, 1.0);
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.3 + 0.2 * p.z));
    }
    scene.camera.eye = {0.4, 0.5, 4};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.4;
    scene.image = {56, 72, {0.1f, 0.2f, 0.3f}};
    scene.material.ka = glm::vec3(0.9f, 0.7f, 0.8f);
    scene.ambient = glm::vec3(0.8f);
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}};
    scene.lighting = Lighting::only_ambient();
    return scene;
}

/// Two squares of different colours in one plane facing the camera, the
/// second over half the first, each listed as two triangles: their
/// triangles' mean depths are equal, so painter's ties (mesh order) decide.
Scene tied_squares_scene() {
    Scene scene;
    const glm::dvec3 corners[8] = {{-1, -1, 0}, {0.5, -1, 0}, {0.5, 0.5, 0}, {-1, 0.5, 0},
                                   {-0.5, -0.5, 0}, {1, -0.5, 0}, {1, 1, 0}, {-0.5, 1, 0}};
    for (int i = 0; i < 8; ++i) {
        scene.mesh.positions.push_back(corners[i]);
        scene.mesh.colors.push_back(i < 4 ? glm::vec3(0.9f, 0.2f, 0.1f) : glm::vec3(0.1f, 0.3f, 0.9f));
    }
    scene.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    scene.camera.eye = {0, 0, 3};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.6;
    scene.image = {40, 40, {0, 0, 0}};
    scene.material.ka = glm::vec3(0.9f);
    scene.ambient = glm::vec3(0.8f);
    scene.lighting = Lighting::only_ambient();
    return scene;
}

/// The eye inside a coloured sphere near its wall: triangles cross the near
/// plane and run far past the image's borders (clipped into fans).
Scene inside_sphere_scene() {
    Scene scene = coloured_sphere_scene();
    scene.camera.eye = {0.1, 0.05, 0.9};
    scene.camera.lookat = {-0.2, -0.1, -0.5};  // the far wall; the walls beside the eye cross the near plane
    return scene;
}

/// Renders `scene` in mesh order on one thread and on two, and in 2, 3 and
/// 7 walks (rows split by where the triangles are: some walks get few
/// rows), then on one thread and on two through painter's sort and bins:
/// the same bits and counts; the mesh-order renders must have filled in
/// mesh order, the others not.
void check_painters_picture(const Scene& scene, RenderOptions options) {
    const std::uint64_t passes = options.samples_per_axis > 1 && options.sample_pattern == SamplePattern::rotated_grid
                                     ? std::uint64_t(options.samples_per_axis) * std::uint64_t(options.samples_per_axis)
                                     : 1;
    options.threads = 1;
    MeshOrderFill walk_any_size(detail::WalkChoice::always);  // the tied squares' triangles are large
    std::uint64_t before = detail::passes_filled_in_mesh_order();
    const RenderResult direct = render(scene, options);
    CHECK(detail::passes_filled_in_mesh_order() == before + passes);
    REQUIRE(direct.stats.triangles_drawn > 0);
    std::vector<RenderResult> walked;
    for (int threads : {1, 2}) {
        for (int walks : {0, 2, 3, 7}) {
            if (threads == 1 && walks == 0) continue;  // `direct`
            MeshOrderWalks split(walks);
            options.threads = threads;
            INFO(threads << " threads, " << walks << " walks");
            before = detail::passes_filled_in_mesh_order();
            walked.push_back(render(scene, options));
            CHECK(detail::passes_filled_in_mesh_order() == before + passes);
        }
    }
    before = detail::passes_filled_in_mesh_order();
    std::vector<RenderResult> sorted;
    {
        MeshOrderFill forbidden(detail::WalkChoice::never);
        for (int threads : {1, 2}) {
            options.threads = threads;
            sorted.push_back(render(scene, options));
        }
    }
    CHECK(detail::passes_filled_in_mesh_order() == before);
    for (const RenderResult& result : walked) {
        CHECK(same_bits(direct.image, result.image));
        check_same_render_stats(direct.stats, result.stats);
    }
    for (const RenderResult& result : sorted) {
        CHECK(same_bits(direct.image, result.image));
        check_same_render_stats(direct.stats, result.stats);
    }
}

}  // namespace

TEST_CASE("the fill in mesh order paints painter's picture: ambient only, and flat and Gouraud lit") {
    struct Case {
        const char* name;
        Scene scene;
    };
    std::vector<Case> cases = {{"coloured sphere", coloured_sphere_scene()},
                               {"tied squares", tied_squares_scene()},
                               {"eye inside the sphere (clipped)", inside_sphere_scene()}};
    {
        Scene uniform = coloured_sphere_scene();
        uniform.mesh.colors.assign(uniform.mesh.positions.size(), glm::vec3(0.3f, 0.6f, 0.9f));
        cases.push_back({"one colour (order free)", uniform});
        Scene materials = coloured_sphere_scene();
        FaceMaterial dark, light;
        dark.coefficients.ka = glm::vec3(0.1f, 0.2f, 0.3f);
        light.coefficients.ka = glm::vec3(0.9f, 0.8f, 0.7f);
        materials.mesh.materials = {dark, light};
        for (std::size_t t = 0; t < materials.mesh.triangles.size(); ++t) {
            materials.mesh.face_materials.push_back(t % 3 == 0 ? 1 : 0);
        }
        cases.push_back({"two materials", materials});
    }
    // The inside view clips in exact mode (near plane and image border).
    CHECK(render(inside_sphere_scene(), RenderOptions::exact()).stats.triangles_clipped > 0);
    for (const Case& c : cases) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            // Flat and Gouraud light per triangle or corner, never per sample: lit, they walk too.
            for (bool lit : {false, true}) {
                if (lit && shader == Shader::phong) continue;  // lights per sample: sorted (test below)
                for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                    if (!mode.options.specialize_effects && shader == Shader::phong) continue;  // batches
                    Scene scene = c.scene;
                    scene.shader = shader;
                    if (lit) scene.lighting = Lighting::full();
                    INFO(c.name << ", " << to_string(shader) << (lit ? ", full lighting, " : ", ambient, ")
                                << mode.name);
                    check_painters_picture(scene, mode.options);
                }
            }
        }
    }
}

TEST_CASE("the fill in mesh order keeps painter's ties in mesh order") {
    Scene scene = tied_squares_scene();
    scene.shader = Shader::phong;
    RenderOptions options = RenderOptions::exact();
    options.threads = 1;
    // The second square is listed last: where the two overlap, its colour.
    const RenderResult later = render(scene, options);
    const glm::vec3 centre = later.image.pixels[20 * 40 + 20];
    CHECK(centre.z > centre.x);
    // Listed first, the first square paints over it.
    std::swap(scene.mesh.triangles[0], scene.mesh.triangles[2]);
    std::swap(scene.mesh.triangles[1], scene.mesh.triangles[3]);
    const RenderResult earlier = render(scene, options);
    const glm::vec3 swapped = earlier.image.pixels[20 * 40 + 20];
    CHECK(swapped.x > swapped.z);
    check_painters_picture(scene, options);
}

TEST_CASE("the fill in mesh order supersamples as painter's fill does") {
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            Scene scene = coloured_sphere_scene();
            scene.shader = shader;
            RenderOptions options = RenderOptions::exact();
            options.samples_per_axis = 2;
            options.sample_pattern = pattern;
            INFO(to_string(shader) << (pattern == SamplePattern::rotated_grid ? ", rotated grid" : ", ordered grid"));
            check_painters_picture(scene, options);
        }
    }
}

TEST_CASE("tiny triangles filled straight from the coverage screen paint painter's picture") {
    // A dense sphere on 48 x 40 pixels: most triangles' boxes hold at most 2 x 2
    // centres. The walk fills those the screen finds covered from its TinyDraw,
    // with no set-up (flat and Gouraud, lit or not, the seed's corners lit in
    // batches; Phong ambient with vertex colours, specialised): the same bits
    // and counts as set-up and its fill, in every walk split, precision, instruction set and camera model, with
    // one material or two (each tiny draw's own: Phong's ambient factor, flat's light).
    Scene scene = coloured_sphere_scene();
    scene.mesh = test_meshes::uv_sphere(90, 90, 1.0);
    scene.mesh.colors.clear();
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.3 + 0.2 * p.z));
    }
    scene.image = {40, 48, {0.1f, 0.2f, 0.3f}};
    const Camera pinhole = scene.camera;
    const Camera parallel = Camera::orthographic(pinhole.eye, pinhole.lookat, pinhole.up, 2.6, 2.6);
    const Lighting ambient = Lighting::only_ambient(), full = Lighting::full();
    FaceMaterial dark, light;
    dark.coefficients.ka = glm::vec3(0.1f, 0.2f, 0.3f);
    light.coefficients.ka = glm::vec3(0.9f, 0.8f, 0.7f);
    std::vector<std::uint32_t> alternating;
    for (std::size_t t = 0; t < scene.mesh.triangles.size(); ++t) alternating.push_back(t % 3 == 0 ? 1 : 0);
    for (const bool two_materials : {false, true}) {
        scene.mesh.materials = two_materials ? std::vector<FaceMaterial>{dark, light} : std::vector<FaceMaterial>{};
        scene.mesh.face_materials = two_materials ? alternating : std::vector<std::uint32_t>{};
        for (const Camera& camera : {pinhole, parallel}) {
            scene.camera = camera;
            for (const auto& [shader, lighting] : {std::pair{Shader::gouraud, full}, std::pair{Shader::gouraud, ambient},
                                                   std::pair{Shader::phong, ambient}, std::pair{Shader::flat, full},
                                                   std::pair{Shader::flat, ambient}}) {
                scene.shader = shader;
                scene.lighting = lighting;
                for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                    if (shader == Shader::phong && !mode.options.specialize_effects) continue;  // batches: sorted
                    // The seed's Gouraud lights corners per triangle: in the walk's batches
                    // (SeedCornerBatch) with a specialised shader of one material, else in set-up.
                    const bool seed_gouraud =
                        shader == Shader::gouraud && mode.options.light_vectors == LightVectors::triangle_centroid;
                    const bool tiny = !seed_gouraud || (mode.options.specialize_effects && !two_materials);
                    for (detail::KernelIsa isa : {detail::KernelIsa::baseline, detail::KernelIsa::avx2}) {
                        if (!detail::kernel_isa_available(isa)) continue;  // no AVX2: the baseline alone
                        detail::override_kernel_isa(isa);
                        INFO(to_string(shader) << (lighting.diffuse ? ", full lighting, " : ", ambient, ") << mode.name
                                               << (camera.model == CameraModel::orthographic ? ", orthographic" : "")
                                               << (two_materials ? ", two materials" : "")
                                               << ", ISA " << detail::to_string(isa));
                        const std::uint64_t before = detail::tiny_draws_filled();
                        check_painters_picture(scene, mode.options);
                        // Ten walked renders: each fills hundreds of tiny triangles, or none.
                        if (tiny) {
                            CHECK(detail::tiny_draws_filled() > before + 10 * 500);
                        } else {
                            CHECK(detail::tiny_draws_filled() == before);
                        }
                    }
                    detail::override_kernel_isa(std::nullopt);
                }
            }
        }
    }
}

TEST_CASE("tiny triangles of one colour, whose order is free, are written without a rank test") {
    // One colour and no light per sample: every triangle paints the same bits,
    // so the walk keeps no ranks (FillPlan::order_free) and a tiny draw writes
    // its samples as they are (fill_tiny_samples()' unranked path; flat's span
    // writer in the AVX2 float kernels). Painter's picture all the same. A
    // plane of 100 x 100 quads, half of it over 40 x 48 pixels, each sample
    // covered once, so a sample the path skipped would keep the background.
    Scene scene = coloured_sphere_scene();
    scene.mesh = test_meshes::grid_plane(100, 0.3, 0.0);
    scene.camera = Camera::look_at({0.0, 0.0, 2.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0, 0.5, 0.5);
    scene.image = {40, 48, {0.1f, 0.2f, 0.3f}};
    scene.shader = Shader::flat;
    scene.lighting = Lighting::only_ambient();
    for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
        if (!mode.options.specialize_effects) continue;  // the general kernel is never order free
        for (detail::KernelIsa isa : {detail::KernelIsa::baseline, detail::KernelIsa::avx2}) {
            if (!detail::kernel_isa_available(isa)) continue;
            detail::override_kernel_isa(isa);
            INFO(mode.name << ", ISA " << detail::to_string(isa));
            const std::uint64_t before = detail::tiny_draws_filled();
            check_painters_picture(scene, mode.options);
            // Ten walked renders, each filling a few hundred tiny triangles.
            CHECK(detail::tiny_draws_filled() > before + 10 * 200);
            // Clipped at the border, the plane fills the picture: no sample keeps the
            // background. (The seed's border policy drops the triangles that cross it.)
            if (mode.options.border == BorderPolicy::clip) {
                const RenderResult result = render(scene, mode.options);
                CHECK(result.stats.samples_shaded == std::uint64_t(40) * 48);
                CHECK(std::none_of(result.image.pixels.begin(), result.image.pixels.end(),
                                   [&](const glm::vec3& p) { return p == scene.image.background; }));
            }
        }
        detail::override_kernel_isa(std::nullopt);
    }
}

TEST_CASE("the fill in mesh order breaks a reordered mesh's ties in the caller's order") {
    // A shuffled icosphere, reordered by the Renderer (mesh_order.hpp): the
    // walk is in the copy's order, the ties must stay the caller's.
    const std::size_t previous_min = detail::set_reorder_min_triangles(0);
    const bool previous_always = detail::set_reorder_always(true);
    Scene scene = coloured_sphere_scene();
    scene.mesh = test_meshes::icosphere(8, 0.05);
    std::mt19937 random(7);
    test_meshes_order::shuffle_faces_and_vertices(scene.mesh, random);
    scene.mesh.colors.clear();
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.5 + 0.5 * p.z));
    }
    // Twice each triangle, the copy a different colour: equal depths everywhere, ties decide.
    const std::size_t count = scene.mesh.triangles.size();
    const std::size_t vertices = scene.mesh.positions.size();
    for (std::size_t v = 0; v < vertices; ++v) {
        scene.mesh.positions.push_back(scene.mesh.positions[v]);
        scene.mesh.colors.push_back(glm::vec3(1.0f) - scene.mesh.colors[v]);
    }
    for (std::size_t t = 0; t < count; ++t) {
        Triangle copy = scene.mesh.triangles[t];
        for (std::uint32_t& index : copy) index += static_cast<std::uint32_t>(vertices);
        scene.mesh.triangles.push_back(copy);
    }
    std::shuffle(scene.mesh.triangles.begin(), scene.mesh.triangles.end(), random);
    MeshOrderFill walk_any_size(detail::WalkChoice::always);
    // The larger image's spans are long: shaded in batches, then ranked (fill_ranked_span_lanes()).
    const Lighting ambient = Lighting::only_ambient(), full = Lighting::full();
    for (const auto& [shader, side, lighting] :
         {std::tuple{Shader::flat, 0, ambient}, std::tuple{Shader::gouraud, 0, ambient},
          std::tuple{Shader::phong, 0, ambient}, std::tuple{Shader::gouraud, 0, full},
          std::tuple{Shader::gouraud, 320, ambient}, std::tuple{Shader::phong, 320, ambient},
          std::tuple{Shader::gouraud, 320, full}}) {
        scene.shader = shader;
        scene.lighting = lighting;
        if (side > 0) scene.image.rows = scene.image.columns = side;
        INFO(to_string(shader) << ", image " << scene.image.columns << " x " << scene.image.rows);
        RenderOptions options = RenderOptions::exact();
        options.threads = 1;
        Renderer direct_renderer(options);
        const std::uint64_t before = detail::passes_filled_in_mesh_order();
        const RenderResult direct = direct_renderer.render(scene);
        CHECK(detail::passes_filled_in_mesh_order() == before + 1);
        RenderResult sorted;
        {
            MeshOrderFill forbidden(detail::WalkChoice::never);
            Renderer sorted_renderer(options);
            sorted = sorted_renderer.render(scene);
        }
        RenderResult walked;
        {
            MeshOrderWalks split(3);  // ties compared across the walks' shared ranks
            walked = direct_renderer.render(scene);
        }
        detail::set_reorder_min_triangles(std::numeric_limits<std::size_t>::max());
        detail::set_reorder_always(false);
        Renderer plain_renderer(options);
        const RenderResult plain = plain_renderer.render(scene);  // the caller's order, not reordered
        detail::set_reorder_min_triangles(0);
        detail::set_reorder_always(true);
        CHECK(same_bits(direct.image, sorted.image));
        CHECK(same_bits(direct.image, plain.image));
        CHECK(same_bits(direct.image, walked.image));
        check_same_render_stats(direct.stats, sorted.stats);
        check_same_render_stats(direct.stats, walked.stats);
    }
    detail::set_reorder_min_triangles(previous_min);
    detail::set_reorder_always(previous_always);
}

TEST_CASE("the mesh's two halves merge as one walk: ties across the halves in the caller's order") {
    // Two overlapping grids in one plane facing the camera (every triangle's
    // mean depth equal: ties decide every sample), 6,400 triangles (two
    // chunks: an even number of walks take the mesh in halves), shuffled. A
    // Renderer reorders it (ties from the caller's order, not the walk's),
    // render() does not (ties in mesh order).
    const std::size_t previous_min = detail::set_reorder_min_triangles(0);
    const bool previous_always = detail::set_reorder_always(true);
    Scene scene = tied_squares_scene();
    scene.mesh = Mesh{};
    constexpr int kCells = 40;
    for (int grid = 0; grid < 2; ++grid) {
        const double shift = grid == 0 ? -1.0 : -0.8;  // the second grid over most of the first
        const std::uint32_t first = static_cast<std::uint32_t>(scene.mesh.positions.size());
        for (int y = 0; y <= kCells; ++y) {
            for (int x = 0; x <= kCells; ++x) {
                scene.mesh.positions.push_back({shift + 1.8 * x / kCells, shift + 1.8 * y / kCells, 0.0});
                scene.mesh.colors.push_back(grid == 0 ? glm::vec3(0.9f, 0.1f + 0.02f * x, 0.1f)
                                                      : glm::vec3(0.1f, 0.2f, 0.1f + 0.02f * y));
            }
        }
        for (int y = 0; y < kCells; ++y) {
            for (int x = 0; x < kCells; ++x) {
                const std::uint32_t v = first + static_cast<std::uint32_t>(y * (kCells + 1) + x);
                scene.mesh.triangles.push_back({v, v + 1, v + kCells + 2});
                scene.mesh.triangles.push_back({v, v + kCells + 2, v + kCells + 1});
            }
        }
    }
    std::mt19937 random(11);
    std::shuffle(scene.mesh.triangles.begin(), scene.mesh.triangles.end(), random);
    REQUIRE(scene.mesh.triangles.size() > detail::kSetupChunk);
    scene.image.rows = scene.image.columns = 96;
    MeshOrderFill walk_any_size(detail::WalkChoice::always);
    for (const Shader shader : {Shader::gouraud, Shader::flat}) {
        scene.shader = shader;
        INFO(to_string(shader));
        RenderOptions options = RenderOptions::exact();
        options.threads = 1;
        RenderResult sorted;
        {
            MeshOrderFill forbidden(detail::WalkChoice::never);
            sorted = render(scene, options);
        }
        for (const bool reordered : {true, false}) {
            INFO((reordered ? "reordered by a Renderer" : "render()"));
            Renderer renderer(options);
            const auto render_once = [&] { return reordered ? renderer.render(scene) : render(scene, options); };
            const RenderResult one_walk = render_once();
            for (int walks : {2, 4}) {
                MeshOrderWalks split(walks);
                INFO(walks << " walks");
                const std::uint64_t before = detail::passes_filled_in_mesh_order();
                const RenderResult walked = render_once();
                CHECK(detail::passes_filled_in_mesh_order() == before + 1);
                CHECK(same_bits(sorted.image, walked.image));
                check_same_render_stats(one_walk.stats, walked.stats);
            }
            CHECK(same_bits(sorted.image, one_walk.image));
        }
    }
    detail::set_reorder_min_triangles(previous_min);
    detail::set_reorder_always(previous_always);
}

TEST_CASE("Phong lit per sample, extra outputs and the depth buffer do not fill in mesh order") {
    Scene scene = coloured_sphere_scene();
    RenderOptions options = RenderOptions::exact();
    options.threads = 1;
    MeshOrderFill walk_any_size(detail::WalkChoice::always);
    const std::uint64_t before = detail::passes_filled_in_mesh_order();
    scene.shader = Shader::phong;
    scene.lighting = Lighting::full();
    render(scene, options);
    scene.shader = Shader::gouraud;
    scene.lighting = Lighting::only_ambient();
    RenderOptions with_id = options;
    with_id.aovs.id = true;
    render(scene, with_id);
    RenderOptions depth_buffer = options;
    depth_buffer.visibility = Visibility::depth_buffer;
    render(scene, depth_buffer);
    CHECK(detail::passes_filled_in_mesh_order() == before);
}

TEST_CASE("the fill in mesh order is taken for small triangles, lit seed Gouraud on one thread or tiny ones") {
    for (const RenderOptions& mode : {RenderOptions::exact(), RenderOptions::seed()}) {
        for (Shader shader : {Shader::flat, Shader::gouraud}) {
            for (Lighting lighting : {Lighting::only_ambient(), Lighting::full()}) {
                RenderOptions options = mode;
                const bool lit = lighting.diffuse;
                const bool seed = options.light_vectors == LightVectors::triangle_centroid;
                INFO(to_string(shader) << (lit ? ", full lighting" : ", ambient") << (seed ? ", seed" : ", exact"));
                options.threads = 1;
                // The sphere's triangles cover a few samples each: walked.
                Scene small = coloured_sphere_scene();
                small.shader = shader;
                small.lighting = lighting;
                std::uint64_t before = detail::passes_filled_in_mesh_order();
                render(small, options);
                CHECK(detail::passes_filled_in_mesh_order() == before + 1);
                // The same sphere at 8 x 8 times the pixels: its triangles cover 64 times the samples, sorted.
                Scene large = small;
                large.image.rows *= 8;
                large.image.columns *= 8;
                before = detail::passes_filled_in_mesh_order();
                render(large, options);
                CHECK(detail::passes_filled_in_mesh_order() == before);
                // Two walks: ambient only, or flat and exact Gouraud (their tiny triangles filled with no set-up: TinyDraw).
                options.threads = 2;
                MeshOrderWalks two(2);
                before = detail::passes_filled_in_mesh_order();
                render(small, options);
                const bool walks = !lit || shader == Shader::flat || !seed;
                CHECK(detail::passes_filled_in_mesh_order() == before + (walks ? 1 : 0));
                // Lit seed Gouraud too where its triangles are tinier still (at most
                // kSeedWalkMaxSamplesPerTriangle samples): the sphere on a third of the rows and columns.
                Scene tinier = small;
                tinier.image.rows /= 3;
                tinier.image.columns /= 3;
                before = detail::passes_filled_in_mesh_order();
                render(tinier, options);
                CHECK(detail::passes_filled_in_mesh_order() == before + 1);
            }
        }
    }
}

TEST_CASE("the triangles' sampled mean area counts those on the image, each at most the image") {
    detail::FrameVector<detail::ScreenVertex> screen;
    std::vector<Triangle> triangles;
    const auto add = [&](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
        const auto first = static_cast<std::uint32_t>(screen.size());
        for (glm::dvec2 p : {a, b, c}) screen.push_back({p.x, p.y, 1.0});
        triangles.push_back({first, first + 1, first + 2});
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // 100 x 50 image (columns x rows): right triangles of area 2 and 8 on it, clockwise or not.
    add({10, 10}, {12, 10}, {10, 12});
    add({20, 20}, {20, 24}, {24, 20});
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) == Approx(5.0));
    // Off the image, behind the eye (NaN): left out.
    add({200, 10}, {210, 10}, {200, 20});
    add({10, -30}, {20, -30}, {10, -20});
    add({10, 10}, {20, nan}, {10, 20});
    add({nan, 10}, {20, 10}, {10, 20});
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) == Approx(5.0));
    // Huge, or too large to measure: counted as the image's 5,000 samples.
    add({-1e300, -1e300}, {1e300, -1e300}, {0, 1e300});
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) == Approx((2.0 + 8.0 + 5000.0) / 3.0));
    // A degenerate triangle on the image: area 0, counted.
    add({30, 30}, {31, 31}, {32, 32});
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) == Approx((2.0 + 8.0 + 5000.0) / 4.0));
    // None on the image: 0.
    const std::vector<Triangle> off(triangles.begin() + 2, triangles.begin() + 5);
    CHECK(detail::sampled_samples_per_triangle(off, screen, 50, 100) == 0.0);
    CHECK(detail::sampled_samples_per_triangle({}, screen, 50, 100) == 0.0);
}

TEST_CASE("the triangles' mean area is sampled from every size() / kTrianglesSampledForSize-th triangle") {
    // Triangles of area 2 at multiples of 3 (the sample's stride below), 8 elsewhere: the sample sees only the 2s.
    detail::FrameVector<detail::ScreenVertex> screen;
    for (glm::dvec2 p : {glm::dvec2{10, 10}, glm::dvec2{12, 10}, glm::dvec2{10, 12}, glm::dvec2{20, 20},
                         glm::dvec2{20, 24}, glm::dvec2{24, 20}}) {
        screen.push_back({p.x, p.y, 1.0});
    }
    constexpr std::size_t kStride = 3;
    std::vector<Triangle> triangles;
    for (std::size_t t = 0; t < kStride * detail::kTrianglesSampledForSize; ++t) {
        triangles.push_back(t % kStride == 0 ? Triangle{0, 1, 2} : Triangle{3, 4, 5});
    }
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) == Approx(2.0));
    // One triangle fewer: a stride of 2, which meets the 8s too (a third of the even triangles are 2s).
    triangles.pop_back();
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) > 2.5);
    // Under kTrianglesSampledForSize triangles, each is read: the exact mean.
    triangles.resize(detail::kTrianglesSampledForSize - 1);
    const double twos = double((triangles.size() + kStride - 1) / kStride);
    CHECK(detail::sampled_samples_per_triangle(triangles, screen, 50, 100) ==
          Approx((2.0 * twos + 8.0 * (double(triangles.size()) - twos)) / double(triangles.size())));
}

TEST_CASE("the rows are split into parts of at least one row each, in order, whatever the triangles") {
    // Triangles anywhere: on the image, off it, behind the eye (NaN rows), huge.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> place(-50.0, 150.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    detail::FrameVector<detail::ScreenVertex> screen;
    std::vector<Triangle> triangles;
    for (std::uint32_t k = 0; k < 900; ++k) {
        const double row = k % 7 == 0 ? nan : k % 11 == 0 ? 1e300 : place(random);
        screen.push_back({place(random), row, 1.0});
        if (k >= 2) triangles.push_back({k - 2, k - 1, k});
    }
    std::vector<double> work;
    detail::RowSplit split;
    for (int rows : {1, 2, 3, 7, 100, 1000}) {
        for (int parts : {1, 2, 3, 7, 16}) {
            INFO(rows << " rows, " << parts << " parts");
            detail::split_rows_by_triangles(triangles, screen, rows, parts, work, split);
            REQUIRE(split.parts() >= 1);
            CHECK(split.parts() <= std::min(rows, parts));
            CHECK(split.starts.front() == 0);
            CHECK(split.starts.back() == rows);
            for (int p = 0; p < split.parts(); ++p) CHECK(split.starts[p] < split.starts[p + 1]);
            // Every row has one owner, and NaN (a corner not in front of the eye) the first part.
            CHECK(split.owner(nan) == 0);
            for (int row = 0; row < rows; ++row) {
                const int owner = split.owner(row + 0.5);
                REQUIRE(owner >= 0);
                REQUIRE(owner < split.parts());
                CHECK(split.starts[owner] <= row);
                CHECK(row < split.starts[owner + 1]);
            }
        }
    }
    // No triangle on the image: equal parts.
    std::vector<Triangle> none;
    detail::split_rows_by_triangles(none, screen, 100, 4, work, split);
    CHECK(split.starts == std::vector<int>{0, 25, 50, 75, 100});
}
