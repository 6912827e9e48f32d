// Mesh order (src/mesh_order.cpp): a mesh rendered reordered gives the same
// bits as the same mesh rendered in its own order (the path every mesh below
// the threshold takes), in every shader and mode, with the depth buffer, and
// in every extra output; painter's ties keep the caller's order; a Renderer
// never draws a mesh edited in place from a stale copy, and makes the copy's
// triangles again only after such an edit.
#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "mesh_order.hpp"
#include "test_meshes.hpp"
#include "same_render_stats.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;
using test_render_modes::same_bits;

namespace {

constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

/// Sets the reordering threshold for one scope: 0 reorders every mesh,
/// whatever its order (the locality test off), kNever none.
class ReorderThreshold {
public:
    explicit ReorderThreshold(std::size_t triangles)
        : previous_(detail::set_reorder_min_triangles(triangles)),
          previous_always_(detail::set_reorder_always(triangles != kNever)) {}
    ~ReorderThreshold() {
        detail::set_reorder_min_triangles(previous_);
        detail::set_reorder_always(previous_always_);
    }
    ReorderThreshold(const ReorderThreshold&) = delete;
    ReorderThreshold& operator=(const ReorderThreshold&) = delete;

private:
    std::size_t previous_;
    bool previous_always_;
};

bool same_aovs(const AovPlanes& a, const AovPlanes& b) {
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    return same(a.depth, b.depth) && same(a.normal, b.normal) && same(a.id, b.id) && same(a.alpha, b.alpha);
}

/// One render of `scene` in the caller's order (never reordered) and one reordered (always).
struct RenderedBothWays {
    RenderResult today, reordered;
};

RenderedBothWays render_both_ways(const Scene& scene, const RenderOptions& options) {
    RenderedBothWays both;
    {
        ReorderThreshold never(kNever);
        both.today = render(scene, options);
    }
    {
        ReorderThreshold always(0);
        both.reordered = render(scene, options);
    }
    return both;
}

/// The mesh with its faces listed in a random order.
Mesh shuffled_faces(Mesh mesh, unsigned seed) {
    std::mt19937 random(seed);
    std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), random);
    return mesh;
}

/// The mesh with its vertices renumbered at random (positions, colours and normals move with them).
Mesh shuffled_vertices(Mesh mesh, unsigned seed) {
    std::vector<std::uint32_t> target(mesh.positions.size());
    std::iota(target.begin(), target.end(), 0u);
    std::mt19937 random(seed);
    std::shuffle(target.begin(), target.end(), random);
    Mesh out = mesh;
    for (std::size_t v = 0; v < target.size(); ++v) {
        out.positions[target[v]] = mesh.positions[v];
        if (!mesh.colors.empty()) out.colors[target[v]] = mesh.colors[v];
        if (!mesh.normals.empty()) out.normals[target[v]] = mesh.normals[v];
    }
    for (Triangle& tri : out.triangles) {
        for (std::uint32_t& index : tri) index = target[index];
    }
    return out;
}

/// Seen from above the plane z = 0, straight down the z axis: every point
/// of that plane has the same camera depth.
constexpr glm::dvec3 kHeadOn{0.0, 0.0, 3.2};

/// The mesh framed (about to the image's border: some triangles are
/// clipped), two lights, no normals (computed).
Scene sphere_scene(const Mesh& mesh, const glm::dvec3& eye = {0.3, 0.4, 3.2}) {
    Scene scene;
    scene.mesh = mesh;
    scene.camera.eye = eye;
    scene.camera.lookat = {0.0, 0.0, 0.0};
    scene.camera.focal = 1.9;
    scene.image.rows = scene.image.columns = 96;
    scene.lights = {{{2.0, 3.0, 4.0}, {0.8f, 0.7f, 0.6f}}, {{-3.0, 1.0, 2.0}, {0.3f, 0.4f, 0.5f}}};
    return scene;
}

/// Painter's ties decide this picture: 600 small squares of different
/// colours, all in one plane facing the camera (every triangle's mean depth
/// is the same), overlapping at random; the square listed last wins each pixel.
Mesh coplanar_squares() {
    Mesh mesh;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> place(-0.9, 0.7), hue(0.0, 1.0);
    for (int k = 0; k < 600; ++k) {
        const double x = place(random), y = place(random), side = 0.2;
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back({x, y, 0.0});
        mesh.positions.push_back({x + side, y, 0.0});
        mesh.positions.push_back({x + side, y + side, 0.0});
        mesh.positions.push_back({x, y + side, 0.0});
        const glm::vec3 color(float(hue(random)), float(hue(random)), float(hue(random)));
        for (int i = 0; i < 4; ++i) mesh.colors.push_back(color);
        mesh.triangles.push_back({first, first + 1, first + 2});
        mesh.triangles.push_back({first, first + 2, first + 3});
    }
    return mesh;
}

struct Case {
    std::string name;
    Mesh mesh;
    glm::dvec3 eye{0.3, 0.4, 3.2};
};

std::vector<Case> cases() {
    const Mesh sphere = test_meshes::icosphere(11, 0.08);
    const Mesh squares = coplanar_squares();
    return {
        {"icosphere, generator's order", sphere},
        {"icosphere, faces shuffled", shuffled_faces(sphere, 1)},
        {"icosphere, vertices shuffled", shuffled_vertices(sphere, 2)},
        {"icosphere, both shuffled", shuffled_vertices(shuffled_faces(sphere, 3), 4)},
        {"coplanar squares (painter's ties)", squares, kHeadOn},
        {"coplanar squares, faces shuffled", shuffled_faces(squares, 5), kHeadOn},
        {"coplanar squares, vertices shuffled", shuffled_vertices(squares, 6), kHeadOn},
    };
}

}  // namespace

TEST_CASE("the permutation is a real one: a shuffled mesh is renumbered") {
    const Mesh mesh = shuffled_vertices(shuffled_faces(test_meshes::icosphere(11, 0.08), 1), 2);
    detail::MeshOrder order;
    detail::compute_mesh_order(mesh, order);
    REQUIRE(order.triangle_source.size() == mesh.triangles.size());
    const std::vector<std::uint32_t> target = detail::vertex_targets(order);
    REQUIRE(target.size() == mesh.positions.size());
    std::vector<std::uint32_t> sorted = order.triangle_source;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t t = 0; t < sorted.size(); ++t) REQUIRE(sorted[t] == t);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) REQUIRE(order.vertex_source[target[v]] == v);
    std::size_t moved = 0;
    for (std::size_t t = 0; t < sorted.size(); ++t) moved += order.triangle_source[t] != t;
    CHECK(moved > mesh.triangles.size() / 2);
    // The first triangle's vertices are the first three (numbered by first use).
    const Triangle& first = mesh.triangles[order.triangle_source[0]];
    for (std::uint32_t index : first) CHECK(target[index] < 3);
}

TEST_CASE("the locality test tells a generator's order and the spatial one from a shuffled one") {
    const Mesh sphere = test_meshes::icosphere(60, 0.08);  // 72,000 triangles
    const double generator = detail::local_order_misses(sphere);
    const double shuffled = detail::local_order_misses(shuffled_vertices(shuffled_faces(sphere, 11), 12));
    const double faces_shuffled = detail::local_order_misses(shuffled_faces(sphere, 13));
    INFO("misses per triangle: generator " << generator << ", shuffled " << shuffled << ", faces shuffled "
                                           << faces_shuffled);
    CHECK(generator < detail::kReorderMinMissesPerTriangle);
    CHECK(shuffled > detail::kReorderMinMissesPerTriangle);
    CHECK(faces_shuffled > detail::kReorderMinMissesPerTriangle);
    // The renderer's own order of the shuffled mesh is local again.
    const Mesh mixed = shuffled_vertices(shuffled_faces(sphere, 11), 12);
    detail::MeshOrder order;
    detail::compute_mesh_order(mixed, order);
    Mesh spatial = mixed;
    const std::vector<std::uint32_t> target = detail::vertex_targets(order);
    for (std::size_t k = 0; k < mixed.triangles.size(); ++k) {
        const Triangle& tri = mixed.triangles[order.triangle_source[k]];
        spatial.triangles[k] = {target[tri[0]], target[tri[1]], target[tri[2]]};
    }
    const double reordered = detail::local_order_misses(spatial);
    INFO("reordered: " << reordered);
    CHECK(reordered < detail::kReorderMinMissesPerTriangle);
    CHECK(detail::local_order_misses(Mesh{}) == 0.0);
}

TEST_CASE("a Renderer's order lists the triangles alike whatever order the mesh comes in, render()'s need not") {
    // 72,000 triangles: about 50 in each occupied cell of the 64^3 grid, far
    // fewer per cell of the 1024^3 one (ties there keep the caller's order).
    const Mesh sphere = test_meshes::icosphere(60, 0.08);
    const Mesh shuffled = shuffled_faces(sphere, 21);
    // sphere_index_of[k]: the index in `sphere` of shuffled's triangle k, found by sorting both lists by corners.
    std::vector<std::uint32_t> sphere_index_of(sphere.triangles.size());
    {
        std::vector<std::uint32_t> by_corners(sphere.triangles.size());
        std::iota(by_corners.begin(), by_corners.end(), 0u);
        const auto less = [&](const Mesh& mesh) {
            return [&mesh](std::uint32_t a, std::uint32_t b) { return mesh.triangles[a] < mesh.triangles[b]; };
        };
        std::vector<std::uint32_t> shuffled_by_corners = by_corners;
        std::sort(by_corners.begin(), by_corners.end(), less(sphere));
        std::sort(shuffled_by_corners.begin(), shuffled_by_corners.end(), less(shuffled));
        for (std::size_t k = 0; k < by_corners.size(); ++k) sphere_index_of[shuffled_by_corners[k]] = by_corners[k];
    }
    const auto same_places = [&](detail::WithinCells within) {
        detail::MeshOrder from_sphere, from_shuffled;
        detail::compute_mesh_order(sphere, from_sphere, nullptr, within);
        detail::compute_mesh_order(shuffled, from_shuffled, nullptr, within);
        std::size_t same = 0;
        for (std::size_t k = 0; k < sphere.triangles.size(); ++k) {
            same += from_sphere.triangle_source[k] == sphere_index_of[from_shuffled.triangle_source[k]];
        }
        return double(same) / double(sphere.triangles.size());
    };
    const double by_finer_grid = same_places(detail::WithinCells::by_finer_grid);
    const double callers_order = same_places(detail::WithinCells::callers_order);
    INFO("triangles in the same place: finer grid " << by_finer_grid << ", caller's order " << callers_order);
    CHECK(by_finer_grid > 0.99);  // 1 when measured
    CHECK(callers_order < 0.5);  // random within each cell: 0.23 when measured
}

TEST_CASE("a Renderer's reordering orders each cell by the finer grid, a one-off render by the caller's order") {
    const Scene scene = sphere_scene(shuffled_faces(test_meshes::icosphere(60, 0.08), 22));
    const RenderOptions options = RenderOptions::exact();
    ReorderThreshold always(0);
    for (const bool one_off : {false, true}) {
        INFO((one_off ? "render()" : "Renderer"));
        detail::MeshOrder kept, expected;
        const Scene& rendered = detail::scene_in_render_order(scene, options, one_off, kept);
        REQUIRE(&rendered != &scene);  // reordered
        detail::compute_mesh_order(scene.mesh, expected, nullptr,
                                   one_off ? detail::WithinCells::callers_order : detail::WithinCells::by_finer_grid);
        CHECK(kept.triangle_source == expected.triangle_source);
    }
}

TEST_CASE("a reordered mesh renders the same bits in every shader, mode and extra output") {
    for (const Case& c : cases()) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
                    Scene scene = sphere_scene(c.mesh, c.eye);
                    scene.shader = shader;
                    RenderOptions options = mode.options;
                    options.visibility = visibility;
                    options.aovs = AovRequest::all();
                    options.threads = 2;
                    const auto [today, reordered] = render_both_ways(scene, options);
                    INFO(c.name << ", " << to_string(shader) << ", " << mode.name
                                << (visibility == Visibility::depth_buffer ? ", depth buffer" : ", painter"));
                    REQUIRE(today.stats.triangles_drawn > 0);
                    CHECK(same_bits(today.image, reordered.image));
                    CHECK(same_aovs(today.aovs, reordered.aovs));
                    CHECK(today.stats.triangles_drawn == reordered.stats.triangles_drawn);
                    CHECK(today.stats.samples_shaded == reordered.stats.samples_shaded);
                }
            }
        }
    }
}

TEST_CASE("a reordered mesh's ids and alpha alone (no weights computed) name the caller's triangles") {
    AovRequest id_and_alpha;
    id_and_alpha.id = id_and_alpha.alpha = true;
    for (const Case& c : cases()) {
        for (int threads : {1, 2}) {
            Scene scene = sphere_scene(c.mesh, c.eye);
            RenderOptions options;
            options.aovs = id_and_alpha;
            options.threads = threads;
            const auto [today, reordered] = render_both_ways(scene, options);
            INFO(c.name << ", " << threads << " thread(s)");
            REQUIRE(today.stats.triangles_drawn > 0);
            REQUIRE(today.aovs.id.size() == today.aovs.alpha.size());
            CHECK(same_aovs(today.aovs, reordered.aovs));
        }
    }
}

TEST_CASE("a copy holding only triangles (the caller's vertex arrays read through the permutation) renders the same bits") {
    // Normals given, or not needed (ambient only, no normal output): nothing
    // is computed from the copy's positions, so the copy keeps no vertex
    // array and the vertex stage gathers the caller's (CallerVertices).
    struct Variant {
        const char* name;
        bool given_normals;
        Lighting lighting;
        AovRequest aovs;
    };
    AovRequest no_normal = AovRequest::all();
    no_normal.normal = false;
    const Variant variants[] = {{"normals given, full lighting, every output", true, Lighting::full(), AovRequest::all()},
                                {"no normals, ambient only", false, Lighting::only_ambient(), no_normal},
                                {"normals given, ambient only", true, Lighting::only_ambient(), AovRequest{}}};
    for (const Case& c : cases()) {
        for (const Variant& variant : variants) {
            Scene scene = sphere_scene(c.mesh, c.eye);
            if (variant.given_normals) scene.mesh.normals = calculate_normals(scene.mesh);
            scene.lighting = variant.lighting;
            {
                ReorderThreshold always(0);
                detail::MeshOrder order;
                RenderOptions options;
                options.aovs = variant.aovs;
                const Scene& drawn = detail::scene_in_render_order(scene, options, false, order);
                INFO(c.name << ", " << variant.name);
                REQUIRE(&drawn == &order.scene);
                CHECK(drawn.mesh.positions.empty());
                CHECK(drawn.mesh.colors.empty());
                CHECK(drawn.mesh.normals.empty());
                CHECK(order.caller_vertices().mesh == &scene.mesh);
                CHECK(order.caller_vertices().source == order.vertex_source.data());
            }
            for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
                for (const test_render_modes::RenderMode& mode : test_render_modes::preset_precision_kernel_modes()) {
                    for (int threads : {1, 2}) {
                        scene.shader = shader;
                        RenderOptions options = mode.options;
                        options.aovs = variant.aovs;
                        options.threads = threads;
                        const auto [today, reordered] = render_both_ways(scene, options);
                        INFO(c.name << ", " << variant.name << ", " << to_string(shader) << ", " << mode.name << ", "
                                    << threads << " thread(s)");
                        REQUIRE(today.stats.triangles_drawn > 0);
                        CHECK(same_bits(today.image, reordered.image));
                        CHECK(same_aovs(today.aovs, reordered.aovs));
                        check_same_render_stats(today.stats, reordered.stats);
                    }
                }
            }
        }
    }
}

TEST_CASE("a Renderer switching between a copy with and without vertex arrays draws what a fresh render draws") {
    // Full lighting without normals computes them from a copy of the vertex
    // arrays; ambient only, or given normals, reads the caller's: frame
    // after frame in one Renderer, each way after the other.
    ReorderThreshold always(0);
    Scene scene = sphere_scene(shuffled_vertices(shuffled_faces(test_meshes::icosphere(11, 0.08), 16), 17));
    scene.shader = Shader::phong;
    Renderer renderer;
    const std::vector<glm::vec3> normals = calculate_normals(scene.mesh);
    for (int frame = 0; frame < 6; ++frame) {
        scene.lighting = frame % 3 == 1 ? Lighting::only_ambient() : Lighting::full();
        if (frame % 3 == 2) {
            scene.mesh.normals = normals;
        } else {
            scene.mesh.normals.clear();
        }
        for (glm::vec3& colour : scene.mesh.colors) colour = glm::vec3(1.0f) - colour;
        RenderResult expected;
        {
            ReorderThreshold never(kNever);
            expected = render(scene);
        }
        INFO("frame " << frame);
        CHECK(same_bits(renderer.render(scene).image, expected.image));
    }
}

TEST_CASE("supersampled and rotated-grid renders of a reordered mesh are the same bits") {
    const Mesh mesh = shuffled_vertices(shuffled_faces(coplanar_squares(), 8), 9);
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        Scene scene = sphere_scene(mesh, kHeadOn);
        scene.shader = Shader::gouraud;
        RenderOptions options = RenderOptions::exact();
        options.samples_per_axis = 2;
        options.sample_pattern = pattern;
        options.aovs = AovRequest::all();
        const auto [today, reordered] = render_both_ways(scene, options);
        CHECK(same_bits(today.image, reordered.image));
        CHECK(same_aovs(today.aovs, reordered.aovs));
    }
}

TEST_CASE("the painter's-ties scene depends on the order: the test above would see a wrong tie-break") {
    // Rendering the squares in another order changes the picture, so equal
    // pictures above mean the reordered render kept the caller's order.
    ReorderThreshold never(kNever);
    Scene scene = sphere_scene(coplanar_squares(), kHeadOn);
    scene.shader = Shader::flat;
    const RenderResult listed = render(scene);
    scene.mesh = shuffled_faces(scene.mesh, 5);
    const RenderResult shuffled = render(scene);
    CHECK_FALSE(same_bits(listed.image, shuffled.image));
}

TEST_CASE("a Renderer never draws a mesh edited in place from a stale copy") {
    ReorderThreshold always(0);
    Scene scene = sphere_scene(shuffled_faces(test_meshes::icosphere(11, 0.08), 10));
    scene.shader = Shader::phong;
    RenderOptions options = RenderOptions::exact();
    options.aovs = AovRequest::all();
    Renderer renderer(options);
    const auto fresh = [&] {
        ReorderThreshold never(kNever);
        return render(scene, options);
    };
    RenderResult expected = fresh();
    CHECK(same_bits(renderer.render(scene).image, expected.image));
    // Positions moved in place (same arrays, same sizes).
    for (glm::dvec3& p : scene.mesh.positions) p = p * 0.8 + glm::dvec3(0.1, 0.0, 0.0);
    expected = fresh();
    RenderResult got = renderer.render(scene);
    CHECK(same_bits(got.image, expected.image));
    CHECK(same_aovs(got.aovs, expected.aovs));
    // Colours and the triangles' corners edited in place: every triangle turned
    // around (its corners' order changes the normals), half of them dropped to one point.
    for (glm::vec3& c : scene.mesh.colors) c = glm::vec3(1.0f) - c;
    for (std::size_t t = 0; t < scene.mesh.triangles.size(); ++t) {
        Triangle& tri = scene.mesh.triangles[t];
        std::swap(tri[1], tri[2]);
        if (t % 2 == 0) tri[2] = tri[1] = tri[0];
    }
    expected = fresh();
    got = renderer.render(scene);
    CHECK(same_bits(got.image, expected.image));
    CHECK(same_aovs(got.aovs, expected.aovs));
    // Normals given by the caller, then edited in place.
    scene.mesh.normals = calculate_normals(scene.mesh);
    CHECK(same_bits(renderer.render(scene).image, fresh().image));
    for (glm::vec3& n : scene.mesh.normals) n = glm::vec3(n.y, n.z, n.x);
    CHECK(same_bits(renderer.render(scene).image, fresh().image));
}

TEST_CASE("the permutation is computed once per mesh, again for another mesh") {
    ReorderThreshold always(0);
    Scene scene = sphere_scene(shuffled_faces(test_meshes::icosphere(11, 0.08), 14));
    const RenderOptions options = RenderOptions::exact();
    detail::MeshOrder order;
    const Scene* drawn = &detail::scene_in_render_order(scene, options, false, order);
    CHECK(drawn == &order.scene);
    CHECK(order.original_triangles() != nullptr);
    CHECK(order.permutations_computed == 1);
    // Same mesh, positions edited in place: the permutation is kept, the copy follows the edit.
    scene.mesh.positions[0] += glm::dvec3(0.01);
    detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 1);
    CHECK(order.scene.mesh.positions[detail::vertex_targets(order)[0]] == scene.mesh.positions[0]);
    // Another mesh of the same size: a new permutation.
    scene.mesh = shuffled_faces(test_meshes::icosphere(11, 0.08), 15);
    detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 2);
    // Culling keeps the caller's order, and so the caller's indices.
    RenderOptions culling = options;
    culling.back_faces = BackFaces::cull_when_hidden;
    CHECK(&detail::scene_in_render_order(scene, culling, false, order) == &scene);
    CHECK(order.original_triangles() == nullptr);
}

TEST_CASE("the copy's triangles are kept while the caller's compare equal, made again after an edit in place") {
    ReorderThreshold always(0);
    Scene scene = sphere_scene(shuffled_vertices(shuffled_faces(test_meshes::icosphere(11, 0.08), 16), 17));
    const RenderOptions options = RenderOptions::exact();
    detail::MeshOrder order;
    // The copy's triangles under order's permutation (a fresh one could differ
    // once triangles moved: any permutation gives the same picture).
    const auto expected_copy = [&] {
        std::vector<Triangle> copy(scene.mesh.triangles.size());
        const std::vector<std::uint32_t> target = detail::vertex_targets(order);
        for (std::size_t k = 0; k < copy.size(); ++k) {
            const Triangle& tri = scene.mesh.triangles[order.triangle_source[k]];
            copy[k] = {target[tri[0]], target[tri[1]], target[tri[2]]};
        }
        return copy;
    };
    detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.triangles_made == 1);
    CHECK(order.triangles_snapshot == scene.mesh.triangles);
    // Positions moved: the triangles are kept.
    for (glm::dvec3& p : scene.mesh.positions) p *= 0.9;
    const Scene* drawn = &detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.triangles_made == 1);
    CHECK(drawn->mesh.triangles == expected_copy());
    // Each edit in place, however small, is drawn: the copy is made again. (Odd
    // triangles: the mesh's identity samples every second one of these 2,420,
    // and an edit there would compute a new permutation, hiding the comparison.)
    REQUIRE(scene.mesh.triangles.size() == 2420);
    const auto edits = std::vector<std::pair<std::string, std::function<void(std::vector<Triangle>&)>>>{
        {"two corners of a triangle swapped", [](std::vector<Triangle>& t) { std::swap(t[1][0], t[1][1]); }},
        {"the last triangle's last corner moved", [](std::vector<Triangle>& t) { t[2419][2] = t[2419][0]; }},
        {"two triangles swapped", [](std::vector<Triangle>& t) { std::swap(t[17], t[1001]); }},
    };
    std::size_t made = 1;
    for (const auto& [name, edit] : edits) {
        INFO(name);
        edit(scene.mesh.triangles);
        drawn = &detail::scene_in_render_order(scene, options, false, order);
        CHECK(order.permutations_computed == 1);
        CHECK(order.triangles_made == ++made);
        CHECK(drawn->mesh.triangles == expected_copy());
        CHECK(order.triangles_snapshot == scene.mesh.triangles);
        // Drawn again unchanged: kept.
        detail::scene_in_render_order(scene, options, false, order);
        CHECK(order.triangles_made == made);
    }
    // A cancel while they are made (at the first poll that finds them not
    // whole) leaves them taken for not made: the next frame makes them.
    std::swap(scene.mesh.triangles[5][1], scene.mesh.triangles[5][2]);
    REQUIRE(order.permutations_computed == 1);
    const std::function<void()> cancel_while_made = [&order] {
        if (!order.triangles_copied) throw RenderCancelled();
    };
    CHECK_THROWS_AS(detail::scene_in_render_order(scene, options, false, order, cancel_while_made), RenderCancelled);
    CHECK_FALSE(order.triangles_copied);
    drawn = &detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 1);
    CHECK(order.triangles_made == made + 2);
    CHECK(order.triangles_copied);
    CHECK(drawn->mesh.triangles == expected_copy());
    // A new permutation makes them again, even for the same triangles.
    order.forget_mesh();
    detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 2);
    CHECK(order.triangles_made == made + 3);
}

TEST_CASE("a cancel inside the mesh order stops it there and leaves no half-made permutation") {
    // A Renderer's poll throws RenderCancelled once a report asked to stop
    // (progress_monitor.hpp); here a poll that throws at its second call.
    ReorderThreshold always(0);
    const Scene first = sphere_scene(shuffled_faces(test_meshes::icosphere(11, 0.08), 14));
    const Scene second = sphere_scene(shuffled_faces(test_meshes::icosphere(11, 0.08), 15));
    const RenderOptions options = RenderOptions::exact();
    detail::MeshOrder order;
    detail::scene_in_render_order(first, options, false, order);
    REQUIRE(order.permutations_computed == 1);
    // The second mesh's order is cancelled halfway, over the first one's arrays.
    int polls = 0;
    const std::function<void()> cancel_at_second_poll = [&polls] {
        if (++polls == 2) throw RenderCancelled();
    };
    CHECK_THROWS_AS(detail::scene_in_render_order(second, options, false, order, cancel_at_second_poll),
                    RenderCancelled);
    CHECK(polls == 2);                        // stopped at that poll, not at the end
    CHECK(order.permutations_computed == 1);  // the second permutation was never finished
    // The first mesh again: its permutation was overwritten, so it is computed
    // afresh (not taken for still valid) and drawn as a fresh order draws it.
    const Scene& drawn = detail::scene_in_render_order(first, options, false, order);
    CHECK(order.permutations_computed == 2);
    detail::MeshOrder fresh;
    const Scene& expected = detail::scene_in_render_order(first, options, false, fresh);
    CHECK(drawn.mesh.triangles == expected.mesh.triangles);
    CHECK(drawn.mesh.positions == expected.mesh.positions);
}
