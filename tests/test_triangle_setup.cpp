// Triangle set-up on its own: what each kind of triangle becomes (draws and
// counts), for the whole and the clipped path alike.
#include <vector>

#include <catch2/catch.hpp>

#include "effects.hpp"
#include "fill_driver.hpp"
#include "triangle_setup.hpp"

namespace pd = phongrast::detail;

namespace {

/// One triangle of the scene set up on 64 x 64 samples with the default camera
/// (world (x, y, 0) lands on sample column (x + 0.5) * 64, row (0.5 - y) * 64).
struct SetUpOne {
    phongrast::Scene scene;
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    pd::ChunkVector<pd::FillTriangle<float>> draws;
    pd::SetupCounts counts;
    pd::TransformedVertices<float> vertices;

    explicit SetUpOne(std::vector<glm::dvec3> positions, phongrast::Shader shader = phongrast::Shader::phong) {
        scene.mesh.positions = std::move(positions);
        scene.mesh.triangles = {{0, 1, 2}};
        scene.image.rows = scene.image.columns = 64;
        scene.lights = {{{1.0, 1.0, 2.0}, glm::vec3(1.0f)}};
        scene.shader = shader;
    }

    void run() {
        const pd::View view(scene.camera, 64, 64, glm::dvec2(0.0));
        const phongrast::EffectSet effects = pd::find_effects(scene);
        pd::VertexStageMemory<float> memory;
        const phongrast::ProgressCallback no_reports;
        pd::ProgressMonitor progress(no_reports);
        pd::transform_vertices(scene.mesh, pd::CallerVertices{}, view, true, memory, vertices, progress);
        pd::LightRig<float> rig;
        pd::build_light_rig(scene, view.frame, rig);
        const pd::PointShader<float> shader{&rig, effects, true};
        const pd::FillPlan<float> plan = pd::plan_fill(scene, options, effects, rig);
        const pd::SetupInput<float> input{scene, options, view, vertices, pd::HiddenBackFaces::unknown, shader,
                                          plan.constants};
        pd::ClipVertexStore<float> store;
        pd::LightVectorsAt<float> vectors;
        pd::set_up_triangle(input, 0, draws, store, counts, vectors);
    }

    bool points_into_mesh(const pd::FillTriangle<float>& draw) const {
        for (const pd::Varyings<float>* v : draw.v) {
            if (v < vertices.varyings.data() || v >= vertices.varyings.data() + vertices.varyings.size()) return false;
        }
        return true;
    }
};

}  // namespace

TEST_CASE("a triangle inside the image is one draw pointing at the mesh's vertices, in either winding") {
    bool swapped_seen[2] = {false, false};
    for (const bool clockwise : {false, true}) {
        SetUpOne one(clockwise ? std::vector<glm::dvec3>{{-0.3, -0.3, 0}, {0.0, 0.3, 0}, {0.3, -0.3, 0}}
                               : std::vector<glm::dvec3>{{-0.3, -0.3, 0}, {0.3, -0.3, 0}, {0.0, 0.3, 0}});
        one.run();
        REQUIRE(one.draws.size() == 1);
        CHECK(one.counts.drawn == 1);
        CHECK(one.counts.clipped == 0);
        const pd::FillTriangle<float>& draw = one.draws[0];
        CHECK(draw.coverage.area2() > 0);
        REQUIRE(one.points_into_mesh(draw));
        CHECK(draw.coverage.row_min >= 0);
        CHECK(draw.coverage.row_max < 64);
        // The draw's corners follow the coverage order: corner 1 is the mesh's vertex 2 when swapped.
        const bool swapped = draw.v[1] == &one.vertices.varyings[2];
        swapped_seen[swapped ? 1 : 0] = true;
        CHECK(draw.v[0] == &one.vertices.varyings[0]);
        CHECK(draw.v[1] == &one.vertices.varyings[swapped ? 2 : 1]);
        CHECK(draw.v[2] == &one.vertices.varyings[swapped ? 1 : 2]);
        for (int i = 0; i < 3; ++i) {
            const pd::ScreenVertex& screen = one.vertices.screen[static_cast<std::size_t>(draw.v[i] - one.vertices.varyings.data())];
            const pd::SnappedPoint snapped = pd::snap(screen.column, screen.row);
            CHECK(draw.coverage.v[i].x == snapped.x);
            CHECK(draw.coverage.v[i].y == snapped.y);
        }
    }
    CHECK(swapped_seen[0]);  // one winding is kept, the other swapped
    CHECK(swapped_seen[1]);
}

TEST_CASE("a zero-area triangle is counted degenerate and a tiny one between samples") {
    SetUpOne line({{-0.3, -0.3, 0}, {0.0, 0.0, 0}, {0.3, 0.3, 0}});
    line.run();
    CHECK(line.draws.empty());
    CHECK(line.counts.degenerate == 1);

    // 0.2 samples wide, between sample centres 32.5 and 33.5.
    SetUpOne tiny({{0.5 / 64, 0.0, 0}, {0.7 / 64, 0.0, 0}, {0.6 / 64, -0.1 / 64, 0}});
    tiny.run();
    CHECK(tiny.draws.empty());
    CHECK(tiny.counts.between_samples == 1);
    CHECK(tiny.counts.degenerate == 0);
}

TEST_CASE("a triangle across the border is clipped (exact) or dropped (seed)") {
    const std::vector<glm::dvec3> across = {{-0.3, -0.3, 0}, {0.9, -0.3, 0}, {0.0, 0.3, 0}};
    SetUpOne clipped(across);
    clipped.run();
    CHECK(clipped.counts.clipped == 1);
    CHECK(clipped.counts.drawn == 1);
    REQUIRE(!clipped.draws.empty());
    for (const pd::FillTriangle<float>& draw : clipped.draws) {
        CHECK_FALSE(clipped.points_into_mesh(draw));  // the clipped corners live in the clip store
        CHECK(draw.coverage.column_max < 64);
    }

    SetUpOne dropped(across);
    dropped.options = phongrast::RenderOptions::seed();
    dropped.run();
    CHECK(dropped.draws.empty());
    CHECK(dropped.counts.dropped == 1);
}

TEST_CASE("a triangle beyond the image but inside the guard band is counted outside") {
    SetUpOne beside({{0.7, -0.1, 0}, {0.9, -0.1, 0}, {0.8, 0.1, 0}});
    beside.run();
    CHECK(beside.draws.empty());
    CHECK(beside.counts.outside == 1);
}

TEST_CASE("flat set-up lights the triangle once and gives every corner that colour") {
    SetUpOne flat({{-0.3, -0.3, 0}, {0.3, -0.3, 0}, {0.0, 0.3, 0}}, phongrast::Shader::flat);
    flat.run();
    REQUIRE(flat.draws.size() == 1);
    CHECK(flat.counts.lit_points == 1);
    const pd::FillTriangle<float>& draw = flat.draws[0];
    CHECK(draw.lit[0] == draw.lit[1]);
    CHECK(draw.lit[1] == draw.lit[2]);
    CHECK(draw.lit[0].x > 0.0f);
}

TEST_CASE("Phong set-up keeps the centroid for the seed's light vectors, and none without them") {
    const std::vector<glm::dvec3> positions = {{-0.3, -0.3, 0}, {0.3, -0.3, 0}, {0.0, 0.3, 0}};
    SetUpOne seed(positions);
    seed.options.light_vectors = phongrast::LightVectors::triangle_centroid;
    seed.run();
    REQUIRE(seed.draws.size() == 1);
    const pd::FrameVector<pd::Varyings<float>>& corners = seed.vertices.varyings;
    const glm::vec3 centroid = (corners[0].position + corners[1].position + corners[2].position) / 3.0f;
    CHECK(centroid.z != 0.0f);  // in camera space, in front of the eye
    CHECK(seed.draws[0].centroid() == centroid);

    SetUpOne exact(positions);
    exact.run();
    REQUIRE(exact.draws.size() == 1);
    CHECK(exact.draws[0].centroid() == glm::vec3(0.0f));
}

TEST_CASE("a small triangle whose bounding box holds a centre it does not cover is counted between samples") {
    // Legs of 0.9 samples from (32, 32): the box holds centre (32.5, 32.5), the hypotenuse passes before it.
    SetUpOne missing({{0.0, 0.0, 0}, {0.9 / 64, 0.0, 0}, {0.0, -0.9 / 64, 0}});
    missing.run();
    CHECK(missing.draws.empty());
    CHECK(missing.counts.between_samples == 1);
    CHECK(missing.counts.drawn == 0);
    // Legs of 1.1 samples: the hypotenuse passes beyond the centre, which is drawn.
    SetUpOne covering({{0.0, 0.0, 0}, {1.1 / 64, 0.0, 0}, {0.0, -1.1 / 64, 0}});
    covering.run();
    CHECK(covering.draws.size() == 1);
    CHECK(covering.counts.drawn == 1);
}
