// The camera follows docs/scene-format.md ("Camera") exactly.
#include <catch2/catch.hpp>

#include "phongrast/camera.hpp"

using namespace phongrast;

namespace {

Camera looking_down_minus_z() {
    Camera camera;
    camera.eye = {0, 0, 10};
    camera.lookat = {0, 0, 0};
    camera.up = {0, 1, 0};
    camera.focal = 2;
    camera.sensor_height = 2;
    camera.sensor_width = 4;
    return camera;
}

}  // namespace

TEST_CASE("the basis is the contract's f, r, u") {
    const CameraFrame frame = make_camera_frame(looking_down_minus_z(), 100, 200);
    CHECK(frame.forward == glm::dvec3(0, 0, -1));
    CHECK(frame.right.x == Approx(1.0));
    CHECK(frame.up.y == Approx(1.0));
}

TEST_CASE("a point on the optical axis lands at the image centre") {
    const CameraFrame frame = make_camera_frame(looking_down_minus_z(), 100, 200);
    for (double z : {5.0, 0.0, -100.0}) {
        const ProjectedPoint p = frame.project({0, 0, z});
        CHECK(p.column == Approx(100.0));
        CHECK(p.row == Approx(50.0));
        CHECK(p.depth == Approx(10.0 - z));
    }
}

TEST_CASE("known points project to hand-computed pixels") {
    const CameraFrame frame = make_camera_frame(looking_down_minus_z(), 100, 200);
    // (1, 0.5, 0): z_c = 10, x = 2*1/10 = 0.2, y = 2*0.5/10 = 0.1.
    // column = (0.2 + 2)/4*200 = 110, row = (1 - 0.1)/2*100 = 45.
    const ProjectedPoint p = frame.project({1, 0.5, 0});
    CHECK(p.column == Approx(110.0));
    CHECK(p.row == Approx(45.0));
    CHECK(p.depth == Approx(10.0));
    // The sensor's corner at the focal distance maps to pixel (0, 0).
    const ProjectedPoint corner = frame.project({-2, 1, 8});
    CHECK(corner.column == Approx(0.0).margin(1e-12));
    CHECK(corner.row == Approx(0.0).margin(1e-12));
}

TEST_CASE("the image is not mirrored") {
    Camera camera = looking_down_minus_z();
    // Look along +x instead, with z up: right is then -y... compute generically.
    camera.eye = {-10, 0, 0};
    camera.lookat = {0, 0, 0};
    camera.up = {0, 0, 1};
    const CameraFrame frame = make_camera_frame(camera, 100, 100);
    const glm::dvec3 right_of_view = frame.right;  // cross(f, up) = x cross z = -y
    CHECK(right_of_view.y == Approx(-1.0));
    const ProjectedPoint right = frame.project(right_of_view);
    const ProjectedPoint above = frame.project({0, 0, 1});
    CHECK(right.column > 50.0);
    CHECK(right.row == Approx(50.0));
    CHECK(above.row < 50.0);
    CHECK(above.column == Approx(50.0));
}

TEST_CASE("up need not be unit nor orthogonal to the view direction") {
    Camera a = looking_down_minus_z();
    Camera b = a;
    b.up = {0, 5, 3};  // tilted towards the view direction, not unit
    const CameraFrame fa = make_camera_frame(a, 64, 64), fb = make_camera_frame(b, 64, 64);
    const ProjectedPoint pa = fa.project({0.3, -0.7, 1}), pb = fb.project({0.3, -0.7, 1});
    CHECK(pa.column == Approx(pb.column));
    CHECK(pa.row == Approx(pb.row));
}

TEST_CASE("invalid cameras are rejected with the field named") {
    Camera camera = looking_down_minus_z();
    SECTION("eye equal to lookat") {
        camera.lookat = camera.eye;
        CHECK_THROWS_WITH(make_camera_frame(camera, 10, 10), Catch::Contains("camera.lookat"));
    }
    SECTION("up parallel to the view direction") {
        camera.up = {0, 0, -3};
        CHECK_THROWS_WITH(make_camera_frame(camera, 10, 10), Catch::Contains("camera.up"));
    }
    SECTION("zero focal") {
        camera.focal = 0;
        CHECK_THROWS_WITH(make_camera_frame(camera, 10, 10), Catch::Contains("camera.focal"));
    }
    SECTION("zero sensor") {
        camera.sensor_width = 0;
        CHECK_THROWS_WITH(make_camera_frame(camera, 10, 10), Catch::Contains("sensor"));
    }
    SECTION("non-finite eye") {
        camera.eye.x = std::numeric_limits<double>::infinity();
        CHECK_THROWS_WITH(make_camera_frame(camera, 10, 10), Catch::Contains("camera.eye"));
    }
    SECTION("no pixels") {
        CHECK_THROWS_WITH(make_camera_frame(camera, 0, 10), Catch::Contains("image.rows"));
    }
}
