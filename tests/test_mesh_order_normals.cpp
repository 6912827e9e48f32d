// Computed normals of a reordered mesh (src/mesh_order.cpp, MeshOrder::
// vertex_corners): the copy's normals, gathered vertex by vertex in the
// copy's order, have the bits of calculate_normals() on the caller's mesh,
// at every thread count, on the cases the normals' fallback exists for; the
// corner list says what it should; and a list made for triangles since
// edited in place is made again, never used.
#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <tbb/task_arena.h>

#include "mesh_order.hpp"
#include "normals.hpp"
#include "shuffled_mesh.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

/// Every mesh reordered, whatever its size and order, for one scope.
class AlwaysReorder {
public:
    AlwaysReorder()
        : previous_(detail::set_reorder_min_triangles(0)), previous_always_(detail::set_reorder_always(true)) {}
    ~AlwaysReorder() {
        detail::set_reorder_min_triangles(previous_);
        detail::set_reorder_always(previous_always_);
    }
    AlwaysReorder(const AlwaysReorder&) = delete;
    AlwaysReorder& operator=(const AlwaysReorder&) = delete;

private:
    std::size_t previous_;
    bool previous_always_;
};

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    return a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

struct AwkwardMesh {
    Mesh mesh;
    std::uint32_t sheet = 0, point = 0, unreferenced = 0;  ///< a vertex of each case
};

/// An icosphere (72,000 triangles) with faces and vertices shuffled, plus the
/// normals' awkward cases: a two-sided sheet (its sums cancel: fallback),
/// triangles naming one vertex twice (a zero face added twice), a point, a
/// vertex whose faces lie far apart in the list, an unreferenced vertex;
/// with `far_points`, faces whose cross product overflows (skipped; their
/// vertices stretch the spatial sort's grid so that the sphere fills one cell).
AwkwardMesh awkward_mesh(unsigned seed, bool far_points = false) {
    AwkwardMesh out;
    Mesh& mesh = out.mesh;
    mesh = test_meshes::icosphere(60, 0.08);
    mesh.colors.clear();
    std::mt19937 random(seed);
    test_meshes_order::shuffle_faces_and_vertices(mesh, random);
    const auto add = [&](glm::dvec3 p) {
        mesh.positions.push_back(p);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    const auto insert = [&](std::size_t at, Triangle tri) {
        mesh.triangles.insert(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(at), tri);
    };
    const std::uint32_t a = add({0.2, 0.1, 0.3}), b = add({0.3, 0.1, 0.3}), c = add({0.2, 0.2, 0.3});
    insert(100, {a, b, c});  // the sheet's two sides, far apart in the list
    insert(40000, {a, c, b});
    insert(20000, {a, a, b});  // repeated corner: a zero face, twice
    insert(3000, {mesh.triangles[5][0], mesh.triangles[5][0], mesh.triangles[6][1]});  // on the sphere
    const std::uint32_t d = add({0.1, -0.1, 0.2});
    insert(50000, {d, d, d});  // a point
    if (far_points) {
        const std::uint32_t e = add({1e200, 0, 0}), f = add({0, 1e200, 0}), g = add({0, 0, 1e200});
        insert(7, {e, f, g});  // cross product overflows: skipped
        insert(60000, {e, f, mesh.triangles[0][0]});
    }
    const std::uint32_t h = add({0.5, 0.5, 2.0});
    insert(10, {mesh.triangles[5000][0], mesh.triangles[7000][1], h});
    mesh.triangles.push_back({h, mesh.triangles[9000][1], mesh.triangles[9000][2]});
    out.sheet = a;
    out.point = d;
    out.unreferenced = add({9, 9, 9});
    return out;
}

/// A scene whose normals are computed (no normals given, the normal output asked for).
Scene scene_of(const Mesh& mesh) {
    Scene scene;
    scene.mesh = mesh;
    scene.camera.eye = {0.3, 0.4, 3.2};
    scene.image.rows = scene.image.columns = 32;
    scene.lights = {{{2.0, 3.0, 4.0}, {0.8f, 0.7f, 0.6f}}};
    return scene;
}

RenderOptions normal_output() {
    RenderOptions options = RenderOptions::exact();
    options.aovs.normal = true;
    return options;
}

/// calculate_normals() of the caller's mesh, moved to the copy's numbering.
std::vector<glm::vec3> expected_normals(const Mesh& mesh, const detail::MeshOrder& order) {
    const std::vector<glm::vec3> caller = calculate_normals(mesh);
    std::vector<glm::vec3> out(caller.size());
    const std::vector<std::uint32_t> target = detail::vertex_targets(order);
    for (std::size_t v = 0; v < caller.size(); ++v) out[target[v]] = caller[v];
    return out;
}

}  // namespace

TEST_CASE("a reordered mesh's computed normals have the caller's order's bits at every thread count") {
    AlwaysReorder always;
    for (const bool far_points : {false, true}) {
        const Scene scene = scene_of(awkward_mesh(far_points ? 2 : 1, far_points).mesh);
        for (int threads : {1, 2, 3, 7}) {
            tbb::task_arena arena(threads);
            detail::MeshOrder order;
            const Scene* drawn = nullptr;
            arena.execute([&] { drawn = &detail::scene_in_render_order(scene, normal_output(), false, order); });
            INFO((far_points ? "with" : "without") << " far points, " << threads << " threads");
            REQUIRE(drawn == &order.scene);
            // Gathered through the corner list, not computed on the caller's mesh.
            CHECK(order.vertex_corners_made);
            CHECK(order.normals.empty());
            const std::vector<glm::vec3> expected = expected_normals(scene.mesh, order);
            CHECK(same_bits(drawn->mesh.normals, expected));
            // The order matters: summed in the copy's own order, some normals
            // differ (the far points put the whole sphere in one cell of the
            // spatial sort, which then keeps the caller's order of triangles).
            if (!far_points) CHECK_FALSE(same_bits(calculate_normals(drawn->mesh), expected));
        }
    }
    // The awkward cases are there: the sheet takes its face's normal, the point and the unreferenced vertex zero.
    const AwkwardMesh awkward = awkward_mesh(1);
    detail::MeshOrder order;
    const Scene scene = scene_of(awkward.mesh);
    const std::vector<glm::vec3>& normals = detail::scene_in_render_order(scene, normal_output(), false, order).mesh.normals;
    const std::vector<std::uint32_t> target = detail::vertex_targets(order);
    CHECK(std::abs(normals[target[awkward.sheet]].z) == 1.0f);
    CHECK(normals[target[awkward.point]] == glm::vec3(0.0f));
    CHECK(normals[target[awkward.unreferenced]] == glm::vec3(0.0f));
}

TEST_CASE("the corner list names each vertex's corners in the caller's order of triangles") {
    const Mesh mesh = awkward_mesh(3, true).mesh;
    detail::MeshOrder order;
    detail::compute_mesh_order(mesh, order);
    CHECK_FALSE(order.vertex_corners_made);
    detail::list_vertex_corners(mesh, order);
    REQUIRE(order.vertex_corners_made);
    const detail::VertexCorners& list = order.vertex_corners;
    REQUIRE(list.first.size() == mesh.positions.size() + 1);
    REQUIRE(list.first.front() == 0);
    REQUIRE(list.first.back() == 3 * mesh.triangles.size());
    REQUIRE(list.corners.size() == 3 * mesh.triangles.size());
    std::vector<bool> seen(4 * mesh.triangles.size(), false);
    const std::vector<std::uint32_t> target = detail::vertex_targets(order);
    for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
        std::uint64_t previous = 0;  // caller's triangle * 4 + corner, + 1
        for (std::uint32_t k = list.first[vertex]; k < list.first[vertex + 1]; ++k) {
            const std::uint32_t entry = list.corners[k];
            const std::uint32_t triangle = entry >> 2, corner = entry & 3u;
            REQUIRE(triangle < mesh.triangles.size());
            REQUIRE(corner < 3);
            REQUIRE_FALSE(seen[entry]);
            seen[entry] = true;
            const std::uint32_t original = order.triangle_source[triangle];
            REQUIRE(target[mesh.triangles[original][corner]] == vertex);
            const std::uint64_t rank = std::uint64_t(original) * 4 + corner + 1;
            REQUIRE(rank > previous);  // ascending caller's triangle, then corner
            previous = rank;
        }
    }
}

TEST_CASE("a corner list made for triangles since edited in place is made again") {
    AlwaysReorder always;
    Scene scene = scene_of(awkward_mesh(4).mesh);
    const RenderOptions options = normal_output();
    detail::MeshOrder order;
    detail::scene_in_render_order(scene, options, false, order);
    REQUIRE(order.vertex_corners_made);
    const detail::VertexCorners made = order.vertex_corners;
    // Positions moved in place: the list still holds, the normals follow.
    for (glm::dvec3& p : scene.mesh.positions) p = glm::dvec3(p.x * 1.5, p.y, p.z - 0.25 * p.x);
    const Scene* drawn = &detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 1);
    CHECK(same_bits(drawn->mesh.normals, expected_normals(scene.mesh, order)));
    CHECK(order.vertex_corners.corners == made.corners);
    const auto edits = std::vector<std::pair<std::string, std::function<void(std::vector<Triangle>&)>>>{
        {"two corners of one triangle swapped", [](std::vector<Triangle>& t) { std::swap(t[123][0], t[123][2]); }},
        {"one corner moved to another vertex", [](std::vector<Triangle>& t) { t[4567][1] = t[89][0]; }},
        {"two triangles swapped", [](std::vector<Triangle>& t) { std::swap(t[11], t[54321]); }},
        {"a triangle turned into a repeated corner", [](std::vector<Triangle>& t) { t[777][2] = t[777][0]; }},
    };
    for (const auto& [name, edit] : edits) {
        INFO(name);
        const detail::VertexCorners before = order.vertex_corners;
        edit(scene.mesh.triangles);
        drawn = &detail::scene_in_render_order(scene, options, false, order);
        CHECK(order.permutations_computed == 1);  // same arrays: the permutation is kept
        CHECK(order.vertex_corners_made);
        CHECK(order.normals.empty());
        CHECK(same_bits(drawn->mesh.normals, expected_normals(scene.mesh, order)));
        CHECK(order.vertex_corners.corners != before.corners);
    }
    // An edit drawn by a frame that computes no normals (no light, no
    // normal output: ambient only) is still seen by the next frame that does.
    const std::vector<PointLight> lights = scene.lights;
    scene.lights.clear();
    std::swap(scene.mesh.triangles[2024][0], scene.mesh.triangles[2024][1]);
    REQUIRE(detail::scene_in_render_order(scene, RenderOptions::exact(), false, order).mesh.normals.empty());
    CHECK(order.permutations_computed == 1);
    CHECK_FALSE(order.vertex_corners_made);
    scene.lights = lights;
    drawn = &detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 1);
    CHECK(order.vertex_corners_made);
    CHECK(same_bits(drawn->mesh.normals, expected_normals(scene.mesh, order)));
    // A list of another size is refused.
    detail::NormalsScratch scratch;
    std::vector<glm::vec3> normals;
    CHECK_FALSE(detail::calculate_normals_by_corners(scene.mesh.positions, scene.mesh.triangles,
                                                     detail::VertexCorners{}, scratch, normals));
}

TEST_CASE("a cancel while the corner list is made leaves none taken for made") {
    AlwaysReorder always;
    Scene scene = scene_of(awkward_mesh(5).mesh);
    const RenderOptions options = normal_output();
    detail::MeshOrder order;
    detail::scene_in_render_order(scene, options, false, order);
    REQUIRE(order.vertex_corners_made);
    // Made again (as after an edit in place), cancelled halfway: the list is half overwritten.
    int polls = 0;
    const std::function<void()> cancel_at_second_poll = [&polls] {
        if (++polls == 2) throw RenderCancelled();
    };
    CHECK_THROWS_AS(detail::list_vertex_corners(scene.mesh, order, cancel_at_second_poll), RenderCancelled);
    CHECK(polls == 2);
    CHECK_FALSE(order.vertex_corners_made);
    // The next frame of a moved vertex (the same mesh would reuse its
    // normals, no list needed), same permutation, makes it whole and draws
    // the caller's order's normals.
    scene.mesh.positions[scene.mesh.triangles[0][0]] *= 1.25;
    const Scene& drawn = detail::scene_in_render_order(scene, options, false, order);
    CHECK(order.permutations_computed == 1);
    CHECK(order.normals_computed == 2);
    CHECK(order.vertex_corners_made);
    CHECK(same_bits(drawn.mesh.normals, expected_normals(scene.mesh, order)));
}

TEST_CASE("given normals with zeros (computed there) render the same bits reordered or not") {
    // A zero user normal means "compute this one" (docs/robustness.md): the
    // computed ones must have the caller's order's bits too. Zeroed: every
    // tenth normal, and those whose bits change when summed in the copy's
    // order (sums of faces whose components nearly cancel). The copy's
    // normals are checked directly: these few bits seldom reach a pixel (the
    // pictures below agreed before the copy computed them too).
    AwkwardMesh awkward = awkward_mesh(6);
    Scene scene = scene_of(awkward.mesh);
    const std::vector<glm::vec3> computed = calculate_normals(scene.mesh);
    std::vector<glm::vec3> given = computed;
    std::size_t order_dependent = 0;
    {
        AlwaysReorder always;
        detail::MeshOrder order;
        const Mesh& copy = detail::scene_in_render_order(scene, normal_output(), false, order).mesh;
        const std::vector<glm::vec3> copy_order = calculate_normals(copy);
        const std::vector<std::uint32_t> target = detail::vertex_targets(order);
        for (std::size_t v = 0; v < given.size(); ++v) {
            const bool differs = std::memcmp(&copy_order[target[v]], &computed[v], sizeof(glm::vec3)) != 0;
            order_dependent += differs;
            if (differs || v % 10 == 0) given[v] = glm::vec3(0.0f);
        }
    }
    REQUIRE(order_dependent > 0);
    scene.mesh.normals = given;
    {
        // The copy's normals: the given ones, and the caller's order's computed ones where they are zero.
        AlwaysReorder always;
        detail::MeshOrder order;
        const Mesh& copy = detail::scene_in_render_order(scene, normal_output(), false, order).mesh;
        std::vector<glm::vec3> expected(given.size());
        const std::vector<std::uint32_t> target = detail::vertex_targets(order);
        for (std::size_t v = 0; v < given.size(); ++v) {
            expected[target[v]] = given[v] != glm::vec3(0.0f) ? given[v] : computed[v];
        }
        CHECK(same_bits(copy.normals, expected));
        CHECK(order.vertex_corners_made);
    }
    scene.image.rows = scene.image.columns = 256;
    scene.camera.focal = 1.9;
    for (const glm::dvec3& eye : {glm::dvec3(0.3, 0.4, 3.2), glm::dvec3(-0.3, -0.4, -3.2), glm::dvec3(3.0, 0.1, 0.2),
                                  glm::dvec3(-3.0, 0.1, 0.2), glm::dvec3(0.1, 3.2, 0.0), glm::dvec3(0.1, -3.2, 0.0)}) {
        scene.camera.eye = eye;
        for (const Shader shader : {Shader::gouraud, Shader::phong}) {
            scene.shader = shader;
            const RenderOptions options = normal_output();
            RenderResult today, reordered;
            {
                const std::size_t previous = detail::set_reorder_min_triangles(std::numeric_limits<std::size_t>::max());
                today = render(scene, options);
                detail::set_reorder_min_triangles(previous);
            }
            {
                AlwaysReorder always;
                reordered = render(scene, options);
            }
            INFO("eye " << eye.x << " " << eye.y << " " << eye.z << ", " << to_string(shader));
            REQUIRE(today.stats.triangles_drawn > 1000);
            CHECK(same_bits(today.image.pixels, reordered.image.pixels));
            CHECK(same_bits(today.aovs.normal, reordered.aovs.normal));
        }
    }
}

TEST_CASE("a reordered copy's normals are computed once while the caller's positions and triangles are unchanged") {
    AlwaysReorder always;
    AwkwardMesh awkward = awkward_mesh(7);
    Scene scene = scene_of(awkward.mesh);
    const RenderOptions options = normal_output();
    detail::MeshOrder order;
    // Each frame: the copy's normals and positions as computed from scratch,
    // and the times they were computed.
    const auto frame = [&](const char* what) {
        INFO(what);
        const Mesh& copy = detail::scene_in_render_order(scene, options, false, order).mesh;
        std::vector<glm::vec3> expected = expected_normals(scene.mesh, order);
        const std::vector<std::uint32_t> target = detail::vertex_targets(order);
        std::vector<glm::dvec3> positions(scene.mesh.positions.size());
        std::vector<glm::vec3> colors(scene.mesh.colors.size());
        for (std::size_t v = 0; v < positions.size(); ++v) {
            positions[target[v]] = scene.mesh.positions[v];
            if (!colors.empty()) colors[target[v]] = scene.mesh.colors[v];
            if (!scene.mesh.normals.empty() && scene.mesh.normals[v] != glm::vec3(0.0f)) {
                expected[target[v]] = scene.mesh.normals[v];
            }
        }
        CHECK(same_bits(copy.normals, expected));
        CHECK(same_bits(copy.positions, positions));
        CHECK(same_bits(copy.colors, colors));
        CHECK(order.vertex_arrays_copied);
        CHECK(order.caller_vertices().normals_final);
        return order.normals_computed;
    };
    CHECK(frame("first") == 1);
    CHECK(frame("unchanged") == 1);
    // Given normals, some zero: only their zeros are computed, from the kept ones.
    std::vector<glm::vec3> given(scene.mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    for (std::size_t v = 0; v < given.size(); v += 4) given[v] = glm::vec3(0.0f);
    scene.mesh.normals = given;
    CHECK(frame("given with zeros") == 1);
    scene.mesh.normals.clear();
    CHECK(frame("none given again: not the last frame's") == 1);
    // Colours play no part: gathered, normals kept.
    scene.mesh.colors.assign(scene.mesh.positions.size(), glm::vec3(0.25f, 0.5f, 0.75f));
    CHECK(frame("colours given") == 1);
    // The caller's positions or triangles changed: computed again.
    scene.mesh.positions[awkward.sheet] += glm::dvec3(0.0, 0.0, 0.01);
    CHECK(frame("a vertex moved") == 2);
    std::swap(scene.mesh.triangles[321][0], scene.mesh.triangles[321][1]);
    CHECK(frame("a triangle rewound") == 3);
    CHECK(frame("unchanged") == 3);
    // A frame that needs no normals drops the copy's vertex arrays: the next one computes them.
    const std::vector<PointLight> lights = scene.lights;
    scene.lights.clear();
    REQUIRE(detail::scene_in_render_order(scene, RenderOptions::exact(), false, order).mesh.positions.empty());
    scene.lights = lights;
    CHECK(frame("after a frame without normals") == 4);
    // A new permutation computes them again, for the same mesh.
    order.forget_mesh();
    CHECK(frame("new permutation") == 5);
    CHECK(order.permutations_computed == 2);
    // A cancel while they are computed leaves none kept.
    scene.mesh.positions[awkward.point] *= 0.5;
    const std::size_t before = order.normals_computed;
    const std::function<void()> cancel_while_computed = [&order] {
        if (!order.kept_normals.valid && order.triangles_copied) throw RenderCancelled();
    };
    CHECK_THROWS_AS(detail::scene_in_render_order(scene, options, false, order, cancel_while_computed),
                    RenderCancelled);
    CHECK_FALSE(order.kept_normals.valid);
    CHECK(frame("after a cancel") == before + 1);
}
