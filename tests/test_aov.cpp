// The extra outputs: depth, normal, id and alpha against geometry computed
// here independently (ray-plane intersections, a sphere's centre, pixel
// rectangles), and the colour image unchanged by asking for them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

Scene base_scene(int size) {
    Scene scene;
    scene.camera.eye = {0.0, 0.0, 5.0};
    scene.camera.lookat = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.focal = 1.0;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.0;
    scene.image.rows = scene.image.columns = size;
    scene.lights = {{{2.0, 3.0, 6.0}, glm::vec3(1.0f)}};
    return scene;
}

// A quad (two triangles) on the plane z = a x + b y + c over [x0, x1] x [y0, y1].
void add_plane_quad(Mesh& mesh, double a, double b, double c, double x0, double x1, double y0, double y1) {
    const auto base = std::uint32_t(mesh.positions.size());
    const double corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    for (const auto& corner : corners) {
        mesh.positions.push_back({corner[0], corner[1], a * corner[0] + b * corner[1] + c});
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
}

// The world ray through a pixel centre: eye + t * direction, whose camera depth is t * focal.
glm::dvec3 pixel_direction(const CameraFrame& frame, int row, int column) {
    const double x = (column + 0.5) / frame.columns * frame.sensor_width - frame.sensor_width / 2.0;
    const double y = frame.sensor_height / 2.0 - (row + 0.5) / frame.rows * frame.sensor_height;
    return frame.right * x + frame.up * y + frame.forward * frame.focal;
}

// Camera depth where the pixel's ray meets the plane z = a x + b y + c, or infinity if it misses the quad.
double plane_depth(const CameraFrame& frame, int row, int column, double a, double b, double c) {
    const glm::dvec3 direction = pixel_direction(frame, row, column);
    const glm::dvec3 normal(-a, -b, 1.0);  // plane: normal . p = c
    const double t = (c - glm::dot(normal, frame.eye)) / glm::dot(normal, direction);
    return t * frame.focal;
}

RenderOptions with_aovs(RenderOptions options, AovRequest aovs = AovRequest::all()) {
    options.aovs = aovs;
    return options;
}

// A torus at 48x48 and visit(scene, options) for each shader, mode (exact, seed),
// visibility and sampling (1 and 2x2 samples per pixel).
template <typename Visit>
void for_each_torus_render(Visit&& visit) {
    Scene scene = base_scene(48);
    scene.mesh = test_meshes::torus(32, 16, 1.2, 0.45);
    scene.camera.eye = {0.5, 2.5, 4.0};
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (RenderOptions options : {RenderOptions::exact(), RenderOptions::seed()}) {
            for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
                for (int samples : {1, 2}) {
                    scene.shader = shader;
                    options.visibility = visibility;
                    options.samples_per_axis = samples;
                    visit(scene, options);
                }
            }
        }
    }
}

}  // namespace

TEST_CASE("depth is the analytic camera depth of a tilted plane, in every mode, +infinity off it") {
    Scene scene = base_scene(48);
    const double a = 0.35, b = -0.2, c = 0.5;
    // About half the image; every corner inside the view, so the seed's border rule keeps it whole.
    add_plane_quad(scene.mesh, a, b, c, -1.6, 1.6, -1.6, 1.6);
    const CameraFrame frame = make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    for (RenderOptions options : {RenderOptions::exact(), RenderOptions::seed()}) {
        for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
            options.visibility = visibility;
            const RenderResult result = render(scene, with_aovs(options));
            REQUIRE(result.aovs.depth.size() == result.image.pixels.size());
            int on_plane = 0;
            for (int row = 0; row < scene.image.rows; ++row) {
                for (int column = 0; column < scene.image.columns; ++column) {
                    const std::size_t p = std::size_t(row) * std::size_t(scene.image.columns) + std::size_t(column);
                    if (result.aovs.id[p] < 0) {
                        CHECK(result.aovs.depth[p] == kInfinity);
                        continue;
                    }
                    ++on_plane;
                    const double expected = plane_depth(frame, row, column, a, b, c);
                    INFO("row " << row << " column " << column);
                    // Within 1e-4: the rasterizer snaps corners to 1/256 pixel, which moves the
                    // drawn plane by up to 1/512 pixel from the exact one.
                    CHECK(result.aovs.depth[p] == Approx(expected).epsilon(1e-4));
                }
            }
            CHECK(on_plane > 48 * 48 / 4);
            CHECK(on_plane < 48 * 48);
        }
    }
}

TEST_CASE("normals of a sphere point away from its centre, unit length, for every shader") {
    Scene scene = base_scene(64);
    scene.mesh = test_meshes::uv_sphere(24, 48, 1.5);
    const CameraFrame frame = make_camera_frame(scene.camera, 64, 64);
    for (Shader shader : {Shader::phong, Shader::gouraud, Shader::flat}) {
        for (Lighting lighting : {Lighting::full(), Lighting::only_ambient()}) {
            INFO(to_string(shader) << ", " << to_string(lighting));
            scene.shader = shader;
            scene.lighting = lighting;
            const RenderResult result = render(scene, with_aovs(RenderOptions::exact()));
            double worst = 1.0;
            for (int row = 0; row < 64; ++row) {
                for (int column = 0; column < 64; ++column) {
                    const std::size_t p = std::size_t(row) * 64 + std::size_t(column);
                    if (result.aovs.id[p] < 0) {
                        CHECK(result.aovs.normal[p] == glm::vec3(0.0f));
                        continue;
                    }
                    // The surface point from the depth output, then its outward direction.
                    const glm::dvec3 point =
                        frame.eye + pixel_direction(frame, row, column) * (double(result.aovs.depth[p]) / frame.focal);
                    const glm::dvec3 outward = glm::normalize(point);
                    const glm::dvec3 normal(result.aovs.normal[p]);
                    CHECK(glm::length(normal) == Approx(1.0).epsilon(1e-5));
                    worst = std::min(worst, glm::dot(normal, outward));
                }
            }
            // Smooth shading interpolates vertex normals; flat has one per facet (a 7.5 degree grid).
            CHECK(worst > (shader == Shader::flat ? 0.98 : 0.999));
        }
    }
}

TEST_CASE("ids name the triangle the scene puts at each pixel, the last painted where they overlap") {
    Scene scene = base_scene(40);
    // Triangle 0: a far quad's first half; triangle 2: a near quad over the image centre.
    add_plane_quad(scene.mesh, 0.0, 0.0, -1.0, -3.0, 3.0, -3.0, 3.0);  // far, covers the whole view
    add_plane_quad(scene.mesh, 0.0, 0.0, 1.0, -0.5, 0.5, -0.5, 0.5);   // near, the middle
    const CameraFrame frame = make_camera_frame(scene.camera, 40, 40);
    for (Visibility visibility : {Visibility::painter, Visibility::depth_buffer}) {
        RenderOptions options = RenderOptions::exact();
        options.visibility = visibility;
        const RenderResult result = render(scene, with_aovs(options));
        for (int row = 0; row < 40; ++row) {
            for (int column = 0; column < 40; ++column) {
                const glm::dvec3 d = pixel_direction(frame, row, column);
                // Where the ray meets each plane, in world x, y: which quad half holds the pixel centre.
                const auto hit = [&](double z) { return frame.eye + d * ((z - frame.eye.z) / d.z); };
                const glm::dvec3 near = hit(1.0), far = hit(-1.0);
                const double margin = 1e-6;  // pixel centres exactly on an edge are left to the top-left rule
                std::int32_t expected;
                if (std::abs(near.x) < 0.5 - margin && std::abs(near.y) < 0.5 - margin) {
                    if (std::abs(near.x - near.y) < margin) continue;  // on the near quad's diagonal
                    expected = near.y < near.x ? 2 : 3;                // (x0,y0)-(x1,y0)-(x1,y1) lies below y = x
                } else if (std::abs(near.x) > 0.5 + margin || std::abs(near.y) > 0.5 + margin) {
                    if (std::abs(far.x - far.y) < margin) continue;
                    expected = far.y < far.x ? 0 : 1;
                } else {
                    continue;
                }
                INFO("row " << row << " column " << column);
                CHECK(result.aovs.id[std::size_t(row) * 40 + std::size_t(column)] == expected);
            }
        }
    }
}

TEST_CASE("alpha is 0 off the mesh, 1 inside and the exact covered fraction on a split pixel") {
    // A square whose left edge runs through pixel column 10 at 10 + offset.
    Scene scene = base_scene(20);
    scene.camera.sensor_height = scene.camera.sensor_width = 2.0;
    scene.camera.focal = 5.0;  // the plane z = 0 maps 1 world unit to 10 pixels
    const double column_to_x = 0.1;
    for (const auto& [offset, samples, pattern, expected] :
         {std::tuple{0.5, 2, SamplePattern::ordered_grid, 0.5f}, std::tuple{0.5, 4, SamplePattern::ordered_grid, 0.5f},
          std::tuple{0.75, 4, SamplePattern::ordered_grid, 0.25f}, std::tuple{0.5, 2, SamplePattern::rotated_grid, 0.5f},
          std::tuple{0.75, 1, SamplePattern::ordered_grid, 0.0f}}) {
        INFO("edge at column 10 + " << offset << ", " << samples << "^2 samples");
        scene.mesh = Mesh{};
        const double left = (10.0 + offset) * column_to_x - 1.0;
        add_plane_quad(scene.mesh, 0.0, 0.0, 0.0, left, 0.55, -0.55, 0.55);
        RenderOptions options = with_aovs(RenderOptions::exact(), AovRequest{false, false, false, true});
        options.samples_per_axis = samples;
        options.sample_pattern = pattern;
        const RenderResult result = render(scene, options);
        REQUIRE(result.aovs.alpha.size() == 400);
        CHECK(result.aovs.depth.empty());  // not asked for
        CHECK(result.aovs.alpha[10 * 20 + 10] == expected);
        CHECK(result.aovs.alpha[10 * 20 + 12] == 1.0f);
        CHECK(result.aovs.alpha[10 * 20 + 5] == 0.0f);
        CHECK(result.aovs.alpha[1 * 20 + 12] == 0.0f);
    }
}

TEST_CASE("coverage and ids alone (no plane needing the weights) equal those of every plane asked together") {
    // Alpha and id without depth, normal, uv or distance take a path that sets
    // each span's samples without the fill's weights (the thumbnail's alpha);
    // with every plane, each sample's weights are computed. Both must agree.
    const AovRequest alone[] = {{false, false, false, true}, {false, false, true, false}, {false, false, true, true}};
    for_each_torus_render([&](const Scene& scene, const RenderOptions& options) {
        const RenderResult every = render(scene, with_aovs(options));
        REQUIRE(std::count(every.aovs.alpha.begin(), every.aovs.alpha.end(), 0.0f) > 0);
        REQUIRE(std::count(every.aovs.alpha.begin(), every.aovs.alpha.end(), 1.0f) > 0);
        for (const AovRequest& planes : alone) {
            INFO(to_string(scene.shader) << (options.visibility == Visibility::painter ? ", painter" : ", depth buffer")
                                         << ", " << options.samples_per_axis << "^2 samples, planes "
                                         << to_string(planes));
            const RenderResult some = render(scene, with_aovs(options, planes));
            CHECK(some.image.pixels == every.image.pixels);
            CHECK(some.aovs.alpha.size() == (planes.alpha ? every.aovs.alpha.size() : 0));
            if (planes.alpha) CHECK(some.aovs.alpha == every.aovs.alpha);
            CHECK(some.aovs.id.size() == (planes.id ? every.aovs.id.size() : 0));
            if (planes.id) CHECK(some.aovs.id == every.aovs.id);
            CHECK(some.aovs.depth.empty());
            CHECK(some.aovs.normal.empty());
        }
    });
}

TEST_CASE("asking for extra outputs leaves the colour image and the counts as they are") {
    for_each_torus_render([](const Scene& scene, const RenderOptions& options) {
        const RenderResult plain = render(scene, options);
        const RenderResult with = render(scene, with_aovs(options));
        CHECK(plain.aovs.depth.empty());
        CHECK(plain.aovs.id.empty());
        CHECK(with.image.pixels == plain.image.pixels);
        CHECK(with.stats.samples_shaded == plain.stats.samples_shaded);
        CHECK(with.stats.diffuse_evaluations == plain.stats.diffuse_evaluations);
    });
}

TEST_CASE("extra outputs are the same for 1 and 2 threads, in float and double") {
    Scene scene = base_scene(64);
    scene.mesh = test_meshes::torus(48, 24, 1.2, 0.45);
    scene.camera.eye = {0.5, 2.5, 4.0};
    for (Precision precision : {Precision::single_float, Precision::double_float}) {
        RenderOptions options = with_aovs(RenderOptions::exact());
        options.precision = precision;
        options.samples_per_axis = 2;
        options.threads = 1;
        const RenderResult one = render(scene, options);
        options.threads = 2;
        const RenderResult two = render(scene, options);
        CHECK(one.aovs.depth == two.aovs.depth);
        CHECK(one.aovs.normal == two.aovs.normal);
        CHECK(one.aovs.id == two.aovs.id);
        CHECK(one.aovs.alpha == two.aovs.alpha);
    }
}

TEST_CASE("the depth buffer reports the nearest surface where painter's order shows the last painted") {
    // Two planes crossing at x = 0: z = 0.5 x and z = -0.5 x. Each pixel's nearest is the larger z.
    Scene scene = base_scene(32);
    // Both cover the whole view.
    add_plane_quad(scene.mesh, 0.5, 0.0, 0.0, -3.0, 3.0, -3.0, 3.0);
    add_plane_quad(scene.mesh, -0.5, 0.0, 0.0, -3.0, 3.0, -3.0, 3.0);
    const CameraFrame frame = make_camera_frame(scene.camera, 32, 32);
    RenderOptions options = with_aovs(RenderOptions::exact());
    options.visibility = Visibility::depth_buffer;
    const RenderResult result = render(scene, options);
    for (int row = 0; row < 32; ++row) {
        for (int column = 0; column < 32; ++column) {
            const double nearest = std::min(plane_depth(frame, row, column, 0.5, 0.0, 0.0),
                                            plane_depth(frame, row, column, -0.5, 0.0, 0.0));
            CHECK(result.aovs.depth[std::size_t(row) * 32 + std::size_t(column)] == Approx(nearest).epsilon(1e-4));
        }
    }
}

TEST_CASE("aov names: parsing, listing and errors") {
    CHECK(to_string(parse_aovs("depth,id")) == "depth,id");
    CHECK(to_string(parse_aovs("all")) == "depth,normal,id,alpha,uv,distance");
    CHECK_FALSE(AovRequest{}.any());
    CHECK_THROWS_WITH(parse_aovs("depth,colour"), Catch::Contains("unknown output 'colour'"));
    CHECK_THROWS_WITH(parse_aovs(""), Catch::Contains("expected depth, normal, id, alpha, uv, distance or all"));
    CHECK(parse_aovs("distance").distance);
}
