// The distance output (AovPlanes::distance): the Euclidean distance from the
// eye to the surface point the depth output describes, checked against
// values computed by hand and against ray-plane intersections made here
// from the camera's own definition (a look-at camera's sensor, an OpenCV
// camera's K inverted as a matrix), with supersampling on ordered and
// rotated grids; and CameraFrame::camera_ray, the inverse of the projection.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "phongrast/render.hpp"
#include "resolve.hpp"  // rotated_grid_offset: where a rotated grid's samples lie

using namespace phongrast;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

Scene plane_scene(const Camera& camera, int rows, int columns) {
    Scene scene;
    scene.camera = camera;
    scene.image.rows = rows;
    scene.image.columns = columns;
    scene.lights = {{{2.0, 3.0, 6.0}, glm::vec3(1.0f)}};
    return scene;
}

// A quad (two triangles) centred at `centre`, spanned by +-half u and +-half v.
void add_quad(Mesh& mesh, const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& v, double half) {
    const auto base = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back(centre - half * u - half * v);
    mesh.positions.push_back(centre + half * u - half * v);
    mesh.positions.push_back(centre + half * u + half * v);
    mesh.positions.push_back(centre - half * u + half * v);
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
}

RenderOptions with_planes(int samples, SamplePattern pattern) {
    RenderOptions options = RenderOptions::exact();
    options.aovs.depth = options.aovs.distance = options.aovs.alpha = options.aovs.id = true;
    options.samples_per_axis = samples;
    options.sample_pattern = pattern;
    return options;
}

// The world direction of the ray through image pixel coordinates (column, row), scaled so that its
// camera depth is 1: from the camera's definition, not from CameraFrame's inverse mapping.
glm::dvec3 world_ray(const Camera& camera, const CameraFrame& frame, double column, double row) {
    if (camera.model == CameraModel::opencv) {
        // K^-1 (u, v, 1) with OpenCV's pixel centres at whole numbers, then R^T into the world.
        const OpenCvCamera& cv = camera.opencv;
        const glm::dmat3 K(cv.fx, 0.0, 0.0, cv.skew, cv.fy, 0.0, cv.cx, cv.cy, 1.0);  // column-major
        const glm::dvec3 in_camera = glm::inverse(K) * glm::dvec3(column - 0.5, row - 0.5, 1.0);
        const Matrix3x4& m = cv.world_to_camera;
        glm::dvec3 world(0.0);
        for (int i = 0; i < 3; ++i) world += glm::dvec3(m[i][0], m[i][1], m[i][2]) * in_camera[i];
        return world;
    }
    const double x = column / frame.columns * frame.sensor_width - frame.sensor_width / 2.0;
    const double y = frame.sensor_height / 2.0 - row / frame.rows * frame.sensor_height;
    return frame.right * (x / frame.focal) + frame.up * (y / frame.focal) + frame.forward;
}

struct Hit {
    double depth, distance;
};

// Where the ray through (column, row) meets the plane of the quad's first triangle.
Hit plane_hit(const Camera& camera, const CameraFrame& frame, const Mesh& mesh, double column, double row) {
    const glm::dvec3 a = mesh.positions[0], b = mesh.positions[1], c = mesh.positions[2];
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const glm::dvec3 direction = world_ray(camera, frame, column, row);
    const double t = glm::dot(normal, a - frame.eye) / glm::dot(normal, direction);
    return {t, t * glm::length(direction)};
}

// The image pixel coordinates of pixel (row, column)'s samples, in resolve order.
std::vector<glm::dvec2> sample_positions(int row, int column, int samples, SamplePattern pattern) {
    std::vector<glm::dvec2> positions;
    for (int i = 0; i < samples; ++i) {
        for (int j = 0; j < samples; ++j) {
            if (pattern == SamplePattern::ordered_grid || samples == 1) {
                positions.push_back({column + (j + 0.5) / samples, row + (i + 0.5) / samples});
            } else {
                positions.push_back(glm::dvec2(column + 0.5, row + 0.5) + detail::rotated_grid_offset(i, j, samples));
            }
        }
    }
    return positions;
}

// Every fully covered pixel: depth and distance are the nearest sample's, and distance / depth is
// that sample's ray length. Returns how many pixels were checked.
int check_nearest_sample(const Scene& scene, int samples, SamplePattern pattern) {
    const RenderResult result = render(scene, with_planes(samples, pattern));
    const AovPlanes& planes = result.aovs;
    REQUIRE(planes.distance.size() == result.image.pixels.size());
    const CameraFrame frame = make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    int checked = 0;
    for (int row = 0; row < scene.image.rows; ++row) {
        for (int column = 0; column < scene.image.columns; ++column) {
            const std::size_t p = std::size_t(row) * std::size_t(scene.image.columns) + std::size_t(column);
            if (planes.id[p] < 0) {
                CHECK(planes.distance[p] == kInfinity);  // the background, as depth
                continue;
            }
            if (planes.alpha[p] < 1.0f) continue;  // an edge pixel: which samples are covered is not analytic
            Hit nearest{std::numeric_limits<double>::infinity(), 0.0};
            double ray_length = 0.0;
            for (const glm::dvec2& s : sample_positions(row, column, samples, pattern)) {
                const Hit hit = plane_hit(scene.camera, frame, scene.mesh, s.x, s.y);
                if (hit.depth < nearest.depth) {
                    nearest = hit;
                    ray_length = hit.distance / hit.depth;
                }
            }
            INFO("row " << row << " column " << column);
            // 1e-4: the rasterizer snaps corners to 1/256 pixel (as test_aov's depth check).
            CHECK(planes.depth[p] == Approx(nearest.depth).epsilon(1e-4));
            CHECK(planes.distance[p] == Approx(nearest.distance).epsilon(1e-4));
            // The ratio does not depend on the snapping: the sample's ray alone, to float rounding.
            CHECK(double(planes.distance[p]) / double(planes.depth[p]) == Approx(ray_length).epsilon(1e-6));
            ++checked;
        }
    }
    return checked;
}

}  // namespace

TEST_CASE("distance of a plane facing a look-at camera is z_c sqrt(1 + x^2 + y^2), by hand") {
    // Eye at z = 5 looking at the plane z = 0, focal 1, a 1 x 1 sensor of 4 x 4 pixels: pixel
    // centres at x, y = +-0.125 and +-0.375 focal lengths from the axis, z_c = 5 everywhere.
    Scene scene = plane_scene(Camera::look_at({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0, 1.0, 1.0), 4, 4);
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 3.0);  // wider than the view
    const RenderResult result = render(scene, with_planes(1, SamplePattern::ordered_grid));
    const std::vector<float>& depth = result.aovs.depth;
    const std::vector<float>& distance = result.aovs.distance;
    REQUIRE(distance.size() == 16);
    const double corner = 5.659615711335886;  // 5 sqrt(1 + 0.375^2 + 0.375^2)
    const double edge = 5.376453291901642;    // 5 sqrt(1 + 0.375^2 + 0.125^2)
    const double centre = 5.0775240028974755; // 5 sqrt(1 + 0.125^2 + 0.125^2)
    const double expected[16] = {corner, edge,   edge,   corner,  //
                                 edge,   centre, centre, edge,    //
                                 edge,   centre, centre, edge,    //
                                 corner, edge,   edge,   corner};
    for (std::size_t p = 0; p < 16; ++p) {
        INFO("pixel " << p);
        CHECK(depth[p] == Approx(5.0).epsilon(1e-6));
        CHECK(distance[p] == Approx(expected[p]).epsilon(1e-6));
    }
}

TEST_CASE("distance alone: no depth plane handed back, the colour image unchanged, the same values as with depth") {
    Scene scene = plane_scene(Camera::look_at({0.3, 0.2, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0, 1.0, 1.0), 16, 16);
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, glm::normalize(glm::dvec3(1.0, 0.0, 0.3)), {0.0, 1.0, 0.0}, 1.5);
    for (const int samples : {1, 3}) {
        RenderOptions options = RenderOptions::exact();
        options.samples_per_axis = samples;
        const RenderResult plain = render(scene, options);
        options.aovs.distance = true;
        const RenderResult alone = render(scene, options);
        CHECK(alone.image.pixels == plain.image.pixels);
        CHECK(alone.aovs.depth.empty());  // used inside (distance is made from it), not asked for
        CHECK(alone.aovs.normal.empty());
        REQUIRE(alone.aovs.distance.size() == 16 * 16);
        const RenderResult both = render(scene, with_planes(samples, SamplePattern::ordered_grid));
        CHECK(alone.aovs.distance == both.aovs.distance);
    }
}

TEST_CASE("a distance past float's largest is float's largest, never the background's infinity") {
    // Double precision draws depths up to 1e300; the planes are float. At z_c = 1e38 a corner pixel's
    // ray (an 8 x 8 sensor at focal 1: length about 5.3) reaches 5.3e38, past float's 3.4e38.
    Scene scene = plane_scene(Camera::look_at({0.0, 0.0, 1e38}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0, 8.0, 8.0), 8, 8);
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 6e38);
    RenderOptions options = with_planes(1, SamplePattern::ordered_grid);
    options.precision = Precision::double_float;
    const RenderResult result = render(scene, options);
    const AovPlanes& planes = result.aovs;
    REQUIRE(planes.distance.size() == 64);
    int clamped = 0;
    for (std::size_t p = 0; p < 64; ++p) {
        INFO("pixel " << p);
        REQUIRE(planes.id[p] >= 0);
        CHECK(planes.depth[p] == Approx(1e38).epsilon(1e-5));
        CHECK(std::isfinite(planes.distance[p]));
        CHECK(planes.distance[p] >= planes.depth[p]);
        clamped += planes.distance[p] == std::numeric_limits<float>::max();
    }
    CHECK(clamped >= 4);  // the corners at least
    CHECK(clamped < 64);  // the centre's rays are short enough
}

TEST_CASE("a depth past float's largest is float's largest, never the background's infinity") {
    // Double precision draws a plane 1e39 away (float's largest is 3.4e38):
    // its depth and distance planes hold float's largest, its id is set.
    Scene scene = plane_scene(Camera::look_at({0.0, 0.0, 1e39}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0, 8.0, 8.0), 8, 8);
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 6e39);
    RenderOptions options = with_planes(1, SamplePattern::ordered_grid);
    options.precision = Precision::double_float;
    const AovPlanes& planes = render(scene, options).aovs;
    REQUIRE(planes.depth.size() == 64);
    for (std::size_t p = 0; p < 64; ++p) {
        INFO("pixel " << p);
        REQUIRE(planes.id[p] >= 0);
        CHECK(planes.depth[p] == std::numeric_limits<float>::max());
        CHECK(planes.distance[p] == std::numeric_limits<float>::max());
    }
}

TEST_CASE("orthographic distance is the depth, from the plane through the eye") {
    Scene scene = plane_scene(Camera::orthographic({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.0, 2.0), 24, 24);
    // A tilted plane: depth varies over the image, and distance must follow it exactly.
    add_quad(scene.mesh, {0.0, 0.0, 0.5}, glm::normalize(glm::dvec3(1.0, 0.0, 0.3)),
             glm::normalize(glm::dvec3(0.0, 1.0, -0.2)), 0.8);
    for (const int samples : {1, 2}) {
        const RenderResult result = render(scene, with_planes(samples, SamplePattern::ordered_grid));
        const AovPlanes& planes = result.aovs;
        int covered = 0, background = 0;
        for (std::size_t p = 0; p < planes.distance.size(); ++p) {
            INFO("pixel " << p << ", " << samples << " samples per axis");
            CHECK(planes.distance[p] == planes.depth[p]);  // bit for bit, +inf on the background too
            (planes.id[p] < 0 ? background : covered) += 1;
        }
        CHECK(covered > 100);
        CHECK(background > 0);
    }
    const CameraFrame frame = make_camera_frame(scene.camera, 24, 24);
    CHECK(frame.camera_ray(3.25, 17.5) == glm::dvec3(0.0, 0.0, 1.0));
}

TEST_CASE("distance comes from the nearest covered sample, ordered and rotated grids, look-at camera") {
    Scene scene = plane_scene(Camera::look_at({0.4, -0.3, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.2, 1.0, 1.25), 20, 25);
    // Tilted in both directions, so that one sample of each pixel is strictly the nearest.
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, glm::normalize(glm::dvec3(1.0, 0.0, 0.4)),
             glm::normalize(glm::dvec3(0.0, 1.0, 0.3)), 6.0);
    CHECK(check_nearest_sample(scene, 1, SamplePattern::ordered_grid) == 20 * 25);
    CHECK(check_nearest_sample(scene, 2, SamplePattern::ordered_grid) == 20 * 25);
    CHECK(check_nearest_sample(scene, 3, SamplePattern::ordered_grid) == 20 * 25);
    CHECK(check_nearest_sample(scene, 2, SamplePattern::rotated_grid) == 20 * 25);
}

TEST_CASE("distance of an OpenCV camera with skew, K in image pixels whatever the samples") {
    // A rotated, translated camera (world_to_camera = [R | t]) with a skewed K.
    const double ax = 0.17, ay = -0.26;  // radians about x, then y
    const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(ax), std::sin(ax), 0.0, -std::sin(ax), std::cos(ax));
    const glm::dmat3 ry(std::cos(ay), 0.0, -std::sin(ay), 0.0, 1.0, 0.0, std::sin(ay), 0.0, std::cos(ay));
    const glm::dmat3 R = rx * ry;  // column-major: R[j][i] is row i, column j
    Matrix3x4 pose{};
    const glm::dvec3 t(0.1, -0.2, 4.0);
    for (int i = 0; i < 3; ++i) pose[i] = {R[0][i], R[1][i], R[2][i], t[i]};
    const Matrix3x3 K{{{40.0, 6.0, 15.5}, {0.0, 36.0, 11.5}, {0.0, 0.0, 1.0}}};
    Scene scene = plane_scene(Camera::from_opencv(K, pose), 24, 32);
    // The plane through the world origin (z_c = 4 there), tilted against the optical axis.
    const glm::dvec3 right = glm::transpose(R) * glm::normalize(glm::dvec3(1.0, 0.0, -0.25));
    const glm::dvec3 down = glm::transpose(R) * glm::normalize(glm::dvec3(0.0, 1.0, 0.2));
    add_quad(scene.mesh, {0.0, 0.0, 0.0}, right, down, 6.0);
    for (const int samples : {1, 2, 3}) {
        INFO(samples << " samples per axis");
        CHECK(check_nearest_sample(scene, samples, SamplePattern::ordered_grid) == 24 * 32);
    }
    CHECK(check_nearest_sample(scene, 2, SamplePattern::rotated_grid) == 24 * 32);
}

TEST_CASE("camera_ray inverts the projection: look-at, OpenCV with skew and samples, orthographic") {
    const Matrix3x3 K{{{50.0, 7.0, 20.25}, {0.0, 45.0, 14.5}, {0.0, 0.0, 1.0}}};
    const Matrix3x4 identity{{{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}};
    const Camera cameras[] = {
        Camera::look_at({1.0, 2.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.7, 0.9, 1.3),
        Camera::from_opencv(K, identity),
    };
    for (const Camera& camera : cameras) {
        for (const int samples : {1, 2, 4}) {
            const CameraFrame frame = make_camera_frame(camera, 30 * samples, 40 * samples, samples);
            for (const glm::dvec2 pixel : {glm::dvec2(0.0, 0.0), glm::dvec2(13.25, 7.5), glm::dvec2(79.0, 119.5)}) {
                const glm::dvec3 ray = frame.camera_ray(pixel.x, pixel.y);
                CHECK(ray.z == 1.0);
                const ProjectedPoint back = frame.pixel_from_camera(2.5 * ray);
                CHECK(back.column == Approx(pixel.x).margin(1e-9));
                CHECK(back.row == Approx(pixel.y).margin(1e-9));
                CHECK(back.depth == 2.5);
            }
        }
    }
    // By hand: OpenCV pixel (column 20.75, row 15) with samples 1 is (u, v) = (20.25, 14.5) = (cx, cy): the axis.
    const CameraFrame frame = make_camera_frame(cameras[1], 30, 40, 1);
    CHECK(frame.camera_ray(20.75, 15.0) == glm::dvec3(0.0, 0.0, 1.0));
    // One row of 45 pixels below it: Y / Z = 1, and the skew moves the column by 7 pixels at X = 0.
    const glm::dvec3 below = frame.camera_ray(20.75 + 7.0, 60.0);
    CHECK(below.x == Approx(0.0).margin(1e-12));
    CHECK(below.y == Approx(-1.0));  // camera space's y is up, OpenCV's Y down
}
