// The OpenCV and orthographic cameras of docs/scene-format.md ("Camera",
// contract version 2), checked against arithmetic done here, not against the
// renderer's own projection.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"
#include "support/meshes.hpp"
#include "vertex_stage.hpp"

using namespace phongrast;

namespace {

/// A rotation about a unit-length axis by `angle`, as rows (Rodrigues).
Matrix3x3 rotation(glm::dvec3 axis, double angle) {
    axis = glm::normalize(axis);
    const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
    const double x = axis.x, y = axis.y, z = axis.z;
    return {{{c + x * x * k, x * y * k - z * s, x * z * k + y * s},
             {y * x * k + z * s, c + y * y * k, y * z * k - x * s},
             {z * x * k - y * s, z * y * k + x * s, c + z * z * k}}};
}

Matrix3x4 pose(const Matrix3x3& R, const glm::dvec3& t) {
    return {{{R[0][0], R[0][1], R[0][2], t.x}, {R[1][0], R[1][1], R[1][2], t.y}, {R[2][0], R[2][1], R[2][2], t.z}}};
}

/// R p + t in plain double arithmetic.
glm::dvec3 pose_times(const Matrix3x4& m, const glm::dvec3& p) {
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) out[i] = m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3];
    return out;
}

/// R^T (q - t): the world point whose camera coordinates are q.
glm::dvec3 pose_inverse_times(const Matrix3x4& m, const glm::dvec3& q) {
    const glm::dvec3 d{q.x - m[0][3], q.y - m[1][3], q.z - m[2][3]};
    glm::dvec3 out;
    for (int j = 0; j < 3; ++j) out[j] = m[0][j] * d.x + m[1][j] * d.y + m[2][j] * d.z;
    return out;
}

Scene lit_scene(Mesh mesh, const Camera& camera, int rows, int columns) {
    Scene scene;
    scene.mesh = std::move(mesh);
    scene.camera = camera;
    scene.image.rows = rows;
    scene.image.columns = columns;
    scene.image.background = {0.0f, 0.0f, 0.0f};
    scene.lights = {{{3.0, 4.0, 5.0}, {1.0f, 1.0f, 1.0f}}, {{-4.0, 1.0, 2.0}, {0.5f, 0.2f, 0.1f}}};
    scene.material.ks = glm::vec3(0.6f);
    scene.material.n = 12.0f;
    return scene;
}

/// One triangle, unlit white on black, for coverage tests.
Scene coverage_scene(const glm::dvec3 (&corners)[3], const Camera& camera, int rows, int columns) {
    Mesh mesh;
    mesh.positions = {corners[0], corners[1], corners[2]};
    mesh.triangles = {{0, 1, 2}};
    Scene scene = lit_scene(mesh, camera, rows, columns);
    scene.lights.clear();
    scene.ambient = glm::vec3(1.0f);
    scene.material.ka = glm::vec3(1.0f);
    scene.lighting = Lighting::only_ambient();
    return scene;
}

std::vector<std::pair<int, int>> covered_pixels(const Image& image) {
    std::vector<std::pair<int, int>> out;
    for (int i = 0; i < image.rows; ++i) {
        for (int j = 0; j < image.columns; ++j) {
            if (image.at(i, j).x > 0.5f) out.push_back({i, j});
        }
    }
    return out;
}

int covered_count(const Image& image) { return static_cast<int>(covered_pixels(image).size()); }

}  // namespace

TEST_CASE("an OpenCV camera projects by the contract's formula, pixel centres at whole numbers + 0.5") {
    const Matrix3x4 w2c = pose(rotation({0.3, -1.0, 0.2}, 0.7), {0.4, -0.2, 6.0});
    const Matrix3x3 K{{{800.0, 3.5, 310.25}, {0.0, 760.0, 241.75}, {0.0, 0.0, 1.0}}};
    const Camera camera = Camera::from_opencv(K, w2c);
    const CameraFrame frame = make_camera_frame(camera, 480, 640);
    for (const glm::dvec3 p : {glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(-1.0, 0.5, 2.0), glm::dvec3(0.7, -0.9, -1.1)}) {
        const glm::dvec3 q = pose_times(w2c, p);
        REQUIRE(q.z > 0.0);
        const double column = (K[0][0] * q.x + K[0][1] * q.y) / q.z + K[0][2] + 0.5;
        const double row = K[1][1] * q.y / q.z + K[1][2] + 0.5;
        const ProjectedPoint got = frame.project(p);
        CHECK(got.column == Approx(column).margin(1e-9));
        CHECK(got.row == Approx(row).margin(1e-9));
        CHECK(got.depth == Approx(q.z).margin(1e-12));
    }
    // The eye is -R^T t, and camera_to_world is the inverse pose.
    const glm::dvec3 eye = camera.opencv.eye();
    const glm::dvec3 at_eye = pose_times(w2c, eye);
    CHECK(glm::length(at_eye) < 1e-12);
    const Matrix4x4 c2w = camera.opencv.camera_to_world();
    const Matrix3x4 back = invert_pose({c2w[0], c2w[1], c2w[2]}, "test");
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) CHECK(back[i][j] == Approx(w2c[i][j]).margin(1e-12));
    }
}

TEST_CASE("a tiny triangle around OpenCV pixel (u, v) covers exactly pixel (row v, column u), skew included") {
    // Pixel (row 37, column 52) is at OpenCV (52, 37); far from (cx, cy), so skew and the axes' signs matter.
    const int target_row = 37, target_column = 52;
    for (double skew : {0.0, 9.0}) {
        CAPTURE(skew);
        const Matrix3x4 w2c = pose(rotation({1.0, 2.0, -0.5}, 2.1), {-0.3, 0.8, 5.0});
        const Matrix3x3 K{{{90.0, skew, 31.0}, {0.0, 70.0, 22.0}, {0.0, 0.0, 1.0}}};
        const Camera camera = Camera::from_opencv(K, w2c);
        // Camera-space corners whose OpenCV projections lie 0.2 pixels around (u, v), found by inverting K here.
        const double Z = 4.0;
        glm::dvec3 corners[3];
        const double offsets[3][2] = {{-0.2, -0.2}, {0.25, -0.1}, {-0.05, 0.22}};
        for (int k = 0; k < 3; ++k) {
            const double u = target_column + offsets[k][0], v = target_row + offsets[k][1];
            const double Y = (v - K[1][2]) / K[1][1] * Z;
            const double X = ((u - K[0][2]) * Z - skew * Y) / K[0][0];
            corners[k] = pose_inverse_times(w2c, {X, Y, Z});
            // Back through K [R | t] in plain double: the corner lands where it was put.
            const glm::dvec3 q = pose_times(w2c, corners[k]);
            CHECK((K[0][0] * q.x + skew * q.y) / q.z + K[0][2] == Approx(u).margin(1e-9));
            CHECK(K[1][1] * q.y / q.z + K[1][2] == Approx(v).margin(1e-9));
        }
        for (const bool reversed : {false, true}) {  // either winding
            glm::dvec3 ordered[3] = {corners[0], reversed ? corners[2] : corners[1], reversed ? corners[1] : corners[2]};
            const Scene scene = coverage_scene(ordered, camera, 64, 96);
            const std::vector<std::pair<int, int>> covered = covered_pixels(render(scene).image);
            REQUIRE(covered.size() == 1);
            CHECK(covered[0].first == target_row);
            CHECK(covered[0].second == target_column);
        }
    }
}

TEST_CASE("an OpenCV camera equal to a look-at camera draws the same picture") {
    // The contract's equivalence: r = R's first row, u = minus its second, f = its third; focal = fy,
    // sensor = [M, N fy / fx], (cx, cy) = (N/2 - 0.5, M/2 - 0.5), skew 0.
    const int rows = 96, columns = 128;
    Camera look_at = Camera::look_at({2.0, 1.5, 3.0}, {0.1, 0.0, -0.2}, {0.0, 1.0, 0.0}, 2.0, 1.2, 1.9);
    const CameraFrame frame = make_camera_frame(look_at, rows, columns);
    const double fy = look_at.focal * rows / look_at.sensor_height;
    const double fx = look_at.focal * columns / look_at.sensor_width;
    Matrix3x4 w2c{};
    const glm::dvec3 basis[3] = {frame.right, -frame.up, frame.forward};
    for (int i = 0; i < 3; ++i) w2c[i] = {basis[i].x, basis[i].y, basis[i].z, -glm::dot(basis[i], look_at.eye)};
    const Camera opencv =
        Camera::from_opencv({{{fx, 0.0, columns / 2.0 - 0.5}, {0.0, fy, rows / 2.0 - 0.5}, {0.0, 0.0, 1.0}}}, w2c);

    for (Shader shader : {Shader::phong, Shader::gouraud, Shader::flat}) {
        CAPTURE(static_cast<int>(shader));
        Scene a = lit_scene(support::uv_sphere(24, 32, 1.0), look_at, rows, columns);
        a.shader = shader;
        Scene b = a;
        b.camera = opencv;
        RenderOptions options = RenderOptions::exact();
        options.precision = Precision::double_float;
        const Image image_a = render(a, options).image;
        const Image image_b = render(b, options).image;
        // The two cameras compute camera coordinates in different orders (R p + t against r.(p - eye)),
        // so positions differ by rounding (~1e-16 relative): in double that moves no snapped vertex
        // and no colour by more than 1e-9. Coverage is compared exactly.
        int coverage_differs = 0;
        float worst = 0.0f;
        for (std::size_t k = 0; k < image_a.pixels.size(); ++k) {
            const bool covered_a = image_a.pixels[k] != glm::vec3(0.0f), covered_b = image_b.pixels[k] != glm::vec3(0.0f);
            coverage_differs += covered_a != covered_b;
            worst = std::max(worst, glm::length(image_a.pixels[k] - image_b.pixels[k]));
        }
        CHECK(coverage_differs == 0);
        CHECK(worst < 1e-5f);
    }
}

TEST_CASE("an OpenCV camera supersamples in image pixels") {
    const Matrix3x4 w2c = pose(rotation({0.0, 1.0, 0.0}, 0.3), {0.0, 0.0, 4.0});
    const Camera camera = Camera::from_opencv({{{60.0, 0.0, 20.0}, {0.0, 60.0, 15.0}, {0.0, 0.0, 1.0}}}, w2c);
    Scene scene = lit_scene(support::uv_sphere(12, 16, 0.8), camera, 32, 40);
    RenderOptions options = RenderOptions::exact();
    options.aovs.alpha = true;
    const RenderResult one = render(scene, options);
    options.samples_per_axis = 4;
    const RenderResult four = render(scene, options);
    // The same silhouette: every pixel whose centre is covered in one is at least partly covered in the other.
    double alpha_one = 0.0, alpha_four = 0.0;
    for (std::size_t k = 0; k < one.aovs.alpha.size(); ++k) {
        alpha_one += one.aovs.alpha[k];
        alpha_four += four.aovs.alpha[k];
        if (one.aovs.alpha[k] == 1.0f) CHECK(four.aovs.alpha[k] > 0.0f);
    }
    CHECK(alpha_four == Approx(alpha_one).epsilon(0.05));
}

TEST_CASE("orthographic: an object's size in pixels does not depend on its distance") {
    // A 1 x 1 square facing the camera; the sensor is 4 x 4 world units on 64 x 64 pixels: 16 x 16 pixels.
    int previous = -1;
    for (double distance : {0.5, 3.0, 200.0}) {
        CAPTURE(distance);
        const Camera camera = Camera::orthographic({0.1, 0.1, distance}, {0.1, 0.1, 0.0}, {0, 1, 0}, 4.0, 4.0);
        Mesh square;
        square.positions = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
        square.triangles = {{0, 1, 2}, {0, 2, 3}};
        const glm::dvec3 tri[3] = {square.positions[0], square.positions[1], square.positions[2]};
        Scene scene = coverage_scene(tri, camera, 64, 64);
        scene.mesh = square;
        const Image image = render(scene).image;
        const int count = covered_count(image);
        CHECK(count == 16 * 16);
        if (previous >= 0) CHECK(count == previous);
        previous = count;
    }
}

TEST_CASE("orthographic: V is -f everywhere in the specular term") {
    // Plane z = 0 facing +z, camera on the z axis looking down, one light at the camera's position.
    // With V = -f = (0, 0, 1): R.V = 2 (N.L)(N.V) - L.V = L_z; with V towards a point eye it would be 2 L_z^2 - 1.
    const glm::dvec3 eye{0.0, 0.0, 3.0};
    const Camera camera = Camera::orthographic(eye, {0.0, 0.0, 0.0}, {0, 1, 0}, 8.0, 8.0);
    Mesh plane;
    plane.positions = {{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}};
    plane.triangles = {{0, 1, 2}, {0, 2, 3}};
    Scene scene = lit_scene(plane, camera, 16, 16);
    scene.lights = {{eye, {1.0f, 1.0f, 1.0f}}};
    scene.material.ka = scene.material.kd = glm::vec3(0.0f);
    scene.material.ks = glm::vec3(1.0f);
    scene.material.n = 1.0f;
    scene.lighting = Lighting::only_specular();
    for (bool specialize : {true, false}) {
        CAPTURE(specialize);
        RenderOptions options = RenderOptions::exact();
        options.specialize_effects = specialize;
        const Image image = render(scene, options).image;
        double largest_gap = 0.0;  // between the two candidate V's, to show the test tells them apart
        for (int i = 0; i < 16; ++i) {
            for (int j = 0; j < 16; ++j) {
                // The pixel centre's point on the plane: x = (j + 0.5)/16 * 8 - 4, y = 4 - (i + 0.5)/16 * 8.
                const glm::dvec3 p{(j + 0.5) / 2.0 - 4.0, 4.0 - (i + 0.5) / 2.0, 0.0};
                const glm::dvec3 L = glm::normalize(scene.lights[0].position - p);
                const double expected = L.z;  // R.V with V = (0, 0, 1), n = 1
                largest_gap = std::max(largest_gap, std::abs(expected - (2 * L.z * L.z - 1)));
                CHECK(image.at(i, j).x == Approx(expected).margin(2e-6));
            }
        }
        CHECK(largest_gap > 0.1);
        // Gouraud: the same at the vertices, interpolated; the centre pixels lie between corners where L_z is known.
    }
    scene.shader = Shader::gouraud;
    const Image gouraud = render(scene).image;
    // Every corner is at distance sqrt(32 + 9) from the light: L_z = 3 / sqrt(41) at each, so every pixel is that.
    const double corner = 3.0 / std::sqrt(41.0);
    for (const glm::vec3& pixel : gouraud.pixels) CHECK(pixel.x == Approx(corner).margin(2e-6));
}

TEST_CASE("orthographic: the eye's plane clips, it is not a perspective division") {
    // A quad from 2 units in front of the eye to 2 units behind it, seen edge-on-ish from above.
    const Camera camera = Camera::orthographic({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0, 1, 0}, 4.0, 4.0);
    Mesh quad;
    quad.positions = {{-1, -1, 2}, {1, -1, 2}, {1, 1, -2}, {-1, 1, -2}};  // z_c = -z: front half has y > 0
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    const glm::dvec3 tri[3] = {quad.positions[0], quad.positions[1], quad.positions[2]};
    Scene scene = coverage_scene(tri, camera, 40, 40);
    scene.mesh = quad;
    RenderOptions options = RenderOptions::exact();
    options.aovs.depth = true;
    const RenderResult result = render(scene, options);
    // Rows 0..19 are y in (0, 2): in front. Rows 20..39: behind, not drawn. Columns 10..29: x in (-1, 1).
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            const bool expected = i < 10 + 10 && i >= 10 && j >= 10 && j < 30;
            CAPTURE(i, j);
            CHECK((result.image.at(i, j).x > 0.5f) == expected);
            if (expected) {
                // z_c along the axis: y = 2 - (i + 0.5) / 10 on the quad, whose z_c is 2 y.
                const double y = 2.0 - (i + 0.5) / 10.0;
                CHECK(result.aovs.depth[static_cast<std::size_t>(i) * 40 + j] == Approx(2.0 * y).margin(1e-5));
            }
        }
    }
}

TEST_CASE("camera validation names the member") {
    const Matrix3x3 K{{{100.0, 0.0, 50.0}, {0.0, 100.0, 50.0}, {0.0, 0.0, 1.0}}};
    const Matrix3x4 good = pose(rotation({0, 0, 1}, 0.5), {0, 0, 3});
    const auto message = [](auto make) {
        try {
            make();
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    Matrix3x3 bad_fx = K;
    bad_fx[0][0] = 0.0;
    CHECK_THAT(message([&] { Camera::from_opencv(bad_fx, good); }), Catch::Contains("camera.opencv.fx"));
    Matrix3x3 bad_fy = K;
    bad_fy[1][1] = std::nan("");
    CHECK_THAT(message([&] { Camera::from_opencv(bad_fy, good); }), Catch::Contains("camera.opencv.fy"));
    Matrix3x3 bad_row = K;
    bad_row[2][2] = 2.0;
    CHECK_THAT(message([&] { Camera::from_opencv(bad_row, good); }), Catch::Contains("camera.K"));
    Matrix3x4 scaled = good;
    for (int j = 0; j < 3; ++j) scaled[0][j] *= 1.001;  // 1e-3 off: not a rotation
    CHECK_THAT(message([&] { Camera::from_opencv(K, scaled); }),
               Catch::Contains("camera.opencv.world_to_camera") && Catch::Contains("not a rotation"));
    Matrix3x4 nearly = good;
    nearly[0][0] += 1e-8;  // within the tolerance
    CHECK(message([&] { Camera::from_opencv(K, nearly); }) == "no error");
    Matrix3x4 mirror = good;
    for (int j = 0; j < 3; ++j) mirror[2][j] = -mirror[2][j];
    CHECK_THAT(message([&] { Camera::from_opencv(K, mirror); }), Catch::Contains("determinant"));
    Matrix3x4 not_finite = good;
    not_finite[1][3] = std::numeric_limits<double>::infinity();
    CHECK_THAT(message([&] { Camera::from_opencv(K, not_finite); }),
               Catch::Contains("camera.opencv.world_to_camera[1][3]"));
    CHECK_THAT(message([&] { Camera::from_opencv_camera_to_world(K, scaled); }),
               Catch::Contains("camera.camera_to_world"));
    // A camera edited after construction is checked again by make_camera_frame.
    Camera edited = Camera::from_opencv(K, good);
    edited.opencv.cx = std::nan("");
    CHECK_THAT(message([&] { make_camera_frame(edited, 10, 10); }), Catch::Contains("camera.opencv.cx"));
    // Orthographic: focal is not used, so not checked.
    Camera ortho = Camera::orthographic({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0, 1.0);
    ortho.focal = 0.0;
    CHECK(message([&] { make_camera_frame(ortho, 10, 10); }) == "no error");
}

TEST_CASE("near planes: look-at 1e-4 focal, OpenCV 1e-4 of the farthest vertex, orthographic the eye's plane") {
    using phongrast::detail::ScreenVertex;
    using phongrast::detail::View;
    const Camera look_at = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 2.0, 1.0, 1.0);
    CHECK(View(look_at, 8, 8, glm::dvec2(0.0)).near_depth == 2.0 * 1e-4);
    const Camera ortho = Camera::orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1.0, 1.0);
    const View ortho_view(ortho, 8, 8, glm::dvec2(0.0));
    CHECK(ortho_view.near_depth > 0.0);
    CHECK(ortho_view.near_depth == std::numeric_limits<double>::denorm_min());  // z_c > 0 exactly
    const Camera opencv = Camera::from_opencv({{{10.0, 0.0, 4.0}, {0.0, 10.0, 4.0}, {0.0, 0.0, 1.0}}},
                                              pose(rotation({0, 1, 0}, 0.0), {0, 0, 5}));
    View view(opencv, 8, 8, glm::dvec2(0.0));
    phongrast::detail::FrameVector<ScreenVertex> screen = {{0, 0, -3.0}, {0, 0, 2.0}, {0, 0, 50.0}};
    phongrast::detail::place_near_plane(view, screen);
    CHECK(view.near_depth == Approx(50.0 * 1e-4));
    // Nothing in front of the eye: a positive plane all vertices are behind.
    screen = {{0, 0, -3.0}, {0, 0, -1.0}};
    phongrast::detail::place_near_plane(view, screen);
    CHECK(view.near_depth > 0.0);
}

TEST_CASE("an OpenCV camera clips a triangle reaching behind it, and draws nothing of one wholly behind") {
    const Camera camera = Camera::from_opencv({{{20.0, 0.0, 15.5}, {0.0, 20.0, 15.5}, {0.0, 0.0, 1.0}}},
                                              pose(rotation({0, 1, 0}, 0.0), {0, 0, 0}));
    // OpenCV axes with R = I: z forward. One corner 4 units behind the eye.
    const glm::dvec3 reaching[3] = {{-1.0, -1.0, 3.0}, {1.0, -1.0, 3.0}, {0.0, 1.0, -4.0}};
    const Image clipped = render(coverage_scene(reaching, camera, 32, 32)).image;
    CHECK(covered_count(clipped) > 50);  // clipped at the near plane, not dropped
    const glm::dvec3 behind[3] = {{-1.0, -1.0, -3.0}, {1.0, -1.0, -3.0}, {0.0, 1.0, -4.0}};
    CHECK(covered_count(render(coverage_scene(behind, camera, 32, 32)).image) == 0);
}
