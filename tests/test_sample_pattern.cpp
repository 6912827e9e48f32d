// RenderOptions::sample_pattern: the rotated grid's samples sit where its
// comment says, and it agrees with the ordered grid where no edge is near.
#include <catch2/catch.hpp>

#include "phongrast/render.hpp"

using namespace phongrast;

namespace {

// A white rectangle (ambient only, so its colour is exactly 1) on a black
// background, seen straight on: world x = (column - 10) / 10 on a 20 x 20 image.
// Its left edge is the vertical line at `edge_column`.
Scene vertical_edge_scene(double edge_column) {
    Scene scene;
    scene.camera.eye = {0, 0, 10};
    scene.camera.focal = 10;
    scene.camera.sensor_height = scene.camera.sensor_width = 2;
    scene.image.rows = scene.image.columns = 20;
    scene.image.background = glm::vec3(0.0f);
    scene.material.ka = glm::vec3(1.0f);
    scene.ambient = glm::vec3(1.0f);
    scene.lighting = Lighting::only_ambient();
    const double left = (edge_column - 10.0) / 10.0;
    scene.mesh.positions = {{left, -5, 0}, {5, -5, 0}, {5, 5, 0}, {left, 5, 0}};
    scene.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return scene;
}

RenderOptions with_samples(int per_axis, SamplePattern pattern) {
    RenderOptions options = RenderOptions::exact();
    options.samples_per_axis = per_axis;
    options.sample_pattern = pattern;
    return options;
}

}  // namespace

TEST_CASE("a 2x2 rotated grid resolves a vertical edge into quarters, the ordered grid into halves") {
    // Edge at column 10.3: the rotated grid's columns in pixel 10 are 10.125,
    // 10.375, 10.625, 10.875 (3 of 4 right of the edge, covered); the
    // ordered grid's are 10.25 and 10.75 (1 of 2 columns covered).
    const Scene scene = vertical_edge_scene(10.3);
    const Image rotated = render(scene, with_samples(2, SamplePattern::rotated_grid)).image;
    const Image ordered = render(scene, with_samples(2, SamplePattern::ordered_grid)).image;
    CHECK(rotated.at(10, 10).x == Approx(0.75f));
    CHECK(ordered.at(10, 10).x == Approx(0.5f));
    // Away from the edge both are exactly the surface or the background.
    CHECK(rotated.at(10, 5).x == 0.0f);
    CHECK(rotated.at(10, 15).x == 1.0f);
    CHECK(ordered.at(10, 15).x == 1.0f);
}

TEST_CASE("an s x s rotated grid puts one sample in each of the s^2 column strips of a pixel") {
    // The samples' columns are 10 + (k + 1/2) / 16. Sliding the edge across
    // pixel 10 in steps of 1/16 pixel (between sample columns), coverage with
    // s = 4 must drop by exactly 1/16 per step: 16 distinct levels.
    for (int strip = 0; strip < 16; ++strip) {
        const double edge = 10.0 + strip / 16.0;
        const Image image = render(vertical_edge_scene(edge), with_samples(4, SamplePattern::rotated_grid)).image;
        CHECK(image.at(3, 10).x == Approx(1.0f - float(strip) / 16.0f));
    }
}

TEST_CASE("one sample per pixel ignores the pattern") {
    const Scene scene = vertical_edge_scene(10.3);
    const Image rotated = render(scene, with_samples(1, SamplePattern::rotated_grid)).image;
    const Image ordered = render(scene, with_samples(1, SamplePattern::ordered_grid)).image;
    CHECK(rotated.pixels == ordered.pixels);
}
