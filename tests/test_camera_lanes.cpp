// src/camera_lanes.cpp transforms many points at once for the vertex stage;
// every lane must carry the same bits as CameraFrame's one-point functions
// (and View::sample_from_camera), or pictures would change by a rounding.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "camera_lanes.hpp"
#include "phongrast/camera.hpp"

using namespace phongrast;
using namespace phongrast::detail;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct NamedFrame {
    std::string name;
    CameraFrame frame;
};

std::vector<NamedFrame> frames() {
    const Camera look_at = Camera::look_at({2.5, -1.25, 7.0}, {0.1, 0.3, -0.2}, {0.2, 1.0, 0.1}, 1.7, 1.1, 1.45);
    const Camera orthographic = Camera::orthographic({-3.0, 2.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.5, 3.5);
    // A rotation (rows of an orthonormal basis) and a translation, K with skew.
    const double c = std::cos(0.4), s = std::sin(0.4);
    const Matrix3x3 K{{{820.5, 1.25, 311.7}, {0.0, 790.25, 245.3}, {0.0, 0.0, 1.0}}};
    const Matrix3x4 pose{{{c, 0.0, s, 0.3}, {0.0, 1.0, 0.0, -0.2}, {-s, 0.0, c, 6.5}}};
    const Camera opencv = Camera::from_opencv(K, pose);
    return {{"look-at", make_camera_frame(look_at, 480, 640, 1)},
            {"look-at, 3 samples per pixel", make_camera_frame(look_at, 1440, 1920, 3)},
            {"orthographic", make_camera_frame(orthographic, 300, 200, 1)},
            {"OpenCV with skew", make_camera_frame(opencv, 480, 640, 1)},
            {"OpenCV, 2 samples per pixel", make_camera_frame(opencv, 960, 1280, 2)}};
}

/// Points near the camera's view and far from it, huge and tiny, some behind the eye.
std::vector<glm::dvec3> points(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<glm::dvec3> out;
    for (const double scale : {1e-6, 0.3, 1.0, 4.0, 25.0, 1e6}) {
        for (int i = 0; i < 101; ++i) out.push_back(glm::dvec3(unit(random), unit(random), unit(random)) * scale);
    }
    return out;
}

}  // namespace

TEST_CASE("camera_from_world_lanes and sample_from_camera_lanes give the one-point functions' bits") {
    std::mt19937 random(20261129);
    const std::vector<glm::dvec3> world = points(random);
    const std::size_t n = world.size();
    const glm::dvec2 offset(0.375, -0.125);  // a pass's sample offset (rotated grid)
    for (const NamedFrame& named : frames()) {
        SECTION(named.name) {
            const CameraFrame& frame = named.frame;
            std::vector<double> x(n), y(n), z(n), column(n), row(n);
            camera_from_world_lanes(frame, world.data(), n, {x.data(), y.data(), z.data()});
            sample_from_camera_lanes(frame, offset, n, x.data(), y.data(), z.data(), column.data(), row.data());
            std::size_t in_front = 0;
            for (std::size_t k = 0; k < n; ++k) {
                const glm::dvec3 camera = frame.camera_from_world(world[k]);
                INFO("point " << k);
                REQUIRE(same_bits(x[k], camera.x));
                REQUIRE(same_bits(y[k], camera.y));
                REQUIRE(same_bits(z[k], camera.z));
                if (!(camera.z > 0.0)) continue;  // the vertex stage gives these no sample position
                ++in_front;
                const ProjectedPoint p = frame.pixel_from_camera(camera);
                REQUIRE(same_bits(column[k], p.column - offset.x));
                REQUIRE(same_bits(row[k], p.row - offset.y));
            }
            CHECK(in_front > n / 4);  // the comparison saw many points
        }
    }
}

TEST_CASE("camera_from_world_direction_lanes gives camera_from_world_direction's bits for float directions") {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> directions(333);
    for (glm::vec3& d : directions) d = {unit(random), unit(random), unit(random)};
    directions[0] = glm::vec3(0.0f);  // a zero normal stays zero
    const std::size_t n = directions.size();
    for (const NamedFrame& named : frames()) {
        SECTION(named.name) {
            std::vector<double> x(n), y(n), z(n);
            camera_from_world_direction_lanes(named.frame, directions.data(), n, {x.data(), y.data(), z.data()});
            for (std::size_t k = 0; k < n; ++k) {
                const glm::dvec3 camera = named.frame.camera_from_world_direction(glm::dvec3(directions[k]));
                INFO("direction " << k);
                REQUIRE(same_bits(x[k], camera.x));
                REQUIRE(same_bits(y[k], camera.y));
                REQUIRE(same_bits(z[k], camera.z));
            }
        }
    }
}
