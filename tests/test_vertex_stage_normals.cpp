// The vertex stage's computed normals (src/vertex_stage.cpp): a mesh
// without normals, or with zero ones ("compute this one"), has them computed
// from its positions and triangles alone; a VertexStageMemory keeps them for
// the next frame while those compare equal, whatever normals the mesh is
// given meanwhile, and every frame's normals are a fresh memory's, bit for
// bit. A reordered copy's normals, final (CallerVertices::normals_final),
// are never computed again.
#include <cstring>
#include <vector>

#include <catch2/catch.hpp>

#include "normals.hpp"
#include "progress_monitor.hpp"
#include "test_meshes.hpp"
#include "vertex_stage.hpp"

using namespace phongrast;
namespace pd = phongrast::detail;

namespace {

Scene sphere_with_loose_vertex() {
    Scene scene;
    scene.mesh = test_meshes::icosphere(12, 0.08);
    scene.mesh.positions.push_back({4.0, 4.0, 4.0});  // unreferenced: its computed normal is zero
    if (!scene.mesh.colors.empty()) scene.mesh.colors.push_back(glm::vec3(0.5f));  // a valid mesh: one colour per vertex
    scene.camera.eye = {0.3, 0.4, 3.2};
    scene.image.rows = scene.image.columns = 32;
    return scene;
}

/// The camera-space normals of one vertex stage with `memory`.
std::vector<glm::vec3> stage_normals(const Scene& scene, pd::VertexStageMemory<float>& memory,
                                     pd::CallerVertices caller = {}) {
    const pd::View view(scene.camera, scene.image.rows, scene.image.columns, glm::dvec2(0.0));
    const ProgressCallback no_reports;
    pd::ProgressMonitor progress(no_reports);
    pd::TransformedVertices<float> out;
    pd::transform_vertices(scene.mesh, caller, view, true, memory, out, progress);
    std::vector<glm::vec3> normals;
    for (const pd::Varyings<float>& v : out.varyings) normals.push_back(v.normal);
    return normals;
}

bool same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
}

/// Kept memory's normals against a fresh memory's, and the times `kept` computed them.
std::size_t check_against_fresh(const Scene& scene, pd::VertexStageMemory<float>& kept) {
    pd::VertexStageMemory<float> fresh;
    const std::vector<glm::vec3> expected = stage_normals(scene, fresh);
    CHECK(same_bits(stage_normals(scene, kept), expected));
    return kept.normals_calculated;
}

}  // namespace

TEST_CASE("the vertex stage computes normals once while positions and triangles are unchanged, given ones or not") {
    Scene scene = sphere_with_loose_vertex();
    const std::uint32_t loose = static_cast<std::uint32_t>(scene.mesh.positions.size() - 1);
    pd::VertexStageMemory<float> kept;
    CHECK(check_against_fresh(scene, kept) == 1);
    CHECK(check_against_fresh(scene, kept) == 1);
    REQUIRE(same_bits(kept.normals, calculate_normals(scene.mesh)));
    REQUIRE(kept.normals[loose] == glm::vec3(0.0f));

    // Given normals with zeros (every third, and the loose vertex's): computed
    // there, from the kept normals; the others as given.
    std::vector<glm::vec3> given(scene.mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (std::size_t v = 0; v < given.size(); v += 3) given[v] = glm::vec3(0.0f);
    given[loose] = glm::vec3(0.0f);
    scene.mesh.normals = given;
    CHECK(check_against_fresh(scene, kept) == 1);
    std::vector<glm::vec3> expected = kept.normals;
    for (std::size_t v = 0; v < given.size(); ++v) {
        if (given[v] != glm::vec3(0.0f)) expected[v] = given[v];
    }
    CHECK(same_bits(kept.filled_normals, expected));
    // Other zeros: the last frame's filled-in normals are not taken for computed ones.
    for (std::size_t v = 0; v < given.size(); ++v) given[v] = v % 3 == 1 ? glm::vec3(0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    scene.mesh.normals = given;
    CHECK(check_against_fresh(scene, kept) == 1);
    // None given again: the computed ones as they were.
    scene.mesh.normals.clear();
    CHECK(check_against_fresh(scene, kept) == 1);

    // A vertex moved, then triangles rewound around it: computed anew each time.
    const std::uint32_t moved = scene.mesh.triangles[100][1];
    scene.mesh.positions[moved] *= 1.3;
    CHECK(check_against_fresh(scene, kept) == 2);
    CHECK(check_against_fresh(scene, kept) == 2);
    for (Triangle& t : scene.mesh.triangles) {
        if (t[0] == moved || t[1] == moved || t[2] == moved) std::swap(t[1], t[2]);
    }
    scene.mesh.normals = given;
    CHECK(check_against_fresh(scene, kept) == 3);
}

TEST_CASE("a reordered copy's final normals are used as they are, zero ones too") {
    Scene scene = sphere_with_loose_vertex();
    scene.mesh.normals = calculate_normals(scene.mesh);
    const std::uint32_t loose = static_cast<std::uint32_t>(scene.mesh.positions.size() - 1);
    REQUIRE(scene.mesh.normals[loose] == glm::vec3(0.0f));
    pd::VertexStageMemory<float> memory;
    const std::vector<glm::vec3> final_normals = stage_normals(scene, memory, pd::CallerVertices{nullptr, nullptr, true});
    CHECK(memory.normals_calculated == 0);
    // Zero is what computing it would give: the same normals either way.
    pd::VertexStageMemory<float> computing;
    CHECK(same_bits(final_normals, stage_normals(scene, computing)));
    CHECK(computing.normals_calculated == 1);
}
