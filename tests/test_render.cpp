// render(): painter's order, shaders, presets, and the seed's eight figures.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

// Camera at z = 10 looking at the origin with focal 10 and a 10 x 10 sensor:
// on the plane z = 0, pixel (column, row) of a 100 x 100 image is world
// ((column - 50) / 10, (50 - row) / 10, 0).
Scene screen_aligned_scene(int size = 100) {
    Scene scene;
    scene.camera.eye = {0, 0, 10};
    scene.camera.lookat = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.focal = 10;
    scene.camera.sensor_height = 10;
    scene.camera.sensor_width = 10;
    scene.image.rows = size;
    scene.image.columns = size;
    scene.image.background = {0, 0, 1};
    scene.material.ka = glm::vec3(1.0f);
    scene.ambient = glm::vec3(1.0f);
    scene.lighting = Lighting::only_ambient();
    return scene;
}

glm::dvec3 world_at(double column, double row, double z = 0.0) {
    // Points off the z = 0 plane are scaled so that they project to the same pixel.
    const double scale = (10.0 - z) / 10.0;
    return {(column - 50.0) / 10.0 * scale, (50.0 - row) / 10.0 * scale, z};
}

void add_triangle(Mesh& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::vec3& color) {
    const auto base = std::uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.colors.insert(mesh.colors.end(), {color, color, color});
    mesh.triangles.push_back({base, base + 1, base + 2});
}

float max_difference(const Image& a, const Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(a.pixels[i] - b.pixels[i]);
        worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
    }
    return worst;
}

bool close(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-6f) {
    const glm::vec3 d = glm::abs(a - b);
    return std::max(d.x, std::max(d.y, d.z)) <= tolerance;
}

bool all_finite(const Image& image) {
    for (const glm::vec3& p : image.pixels) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("painter's order: the nearer triangle wins whatever the input order") {
    const glm::vec3 red(1, 0, 0), green(0, 1, 0);
    for (bool near_first : {true, false}) {
        Scene scene = screen_aligned_scene();
        // Both cover pixel (50, 50); the red one is nearer the eye (z = 2).
        const auto near = [&] { add_triangle(scene.mesh, world_at(20, 20, 2), world_at(80, 20, 2), world_at(50, 80, 2), red); };
        const auto far = [&] { add_triangle(scene.mesh, world_at(30, 10, -3), world_at(90, 70, -3), world_at(10, 70, -3), green); };
        if (near_first) {
            near();
            far();
        } else {
            far();
            near();
        }
        const RenderResult result = render(scene);
        INFO("near triangle listed first: " << near_first);
        CHECK(close(result.image.at(50, 50), red));
        CHECK(close(result.image.at(60, 15), green));  // covered by the far one only
        CHECK(result.stats.triangles_drawn == 2);
    }
}

TEST_CASE("equal depths keep the mesh's order: the later triangle overwrites") {
    Scene scene = screen_aligned_scene();
    add_triangle(scene.mesh, world_at(20, 20), world_at(80, 20), world_at(50, 80), {1, 0, 0});
    add_triangle(scene.mesh, world_at(20, 20), world_at(80, 20), world_at(50, 80), {0, 1, 0});
    CHECK(close(render(scene).image.at(40, 50), glm::vec3(0, 1, 0)));
}

TEST_CASE("Gouraud reproduces vertex colours at pixels on the vertices") {
    const glm::vec3 colors[3] = {{1, 0, 0}, {0, 1, 0}, {0.2f, 0.4f, 0.6f}};
    for (int k = 0; k < 3; ++k) {
        Scene scene = screen_aligned_scene();
        scene.shader = Shader::gouraud;
        // Right angle at (20.5, 20.5), a pixel centre owned by the top and left edges.
        scene.mesh.positions = {world_at(20.5, 20.5), world_at(70.5, 20.5), world_at(20.5, 70.5)};
        scene.mesh.colors = {colors[k], colors[(k + 1) % 3], colors[(k + 2) % 3]};
        scene.mesh.triangles = {{0, 1, 2}};
        for (RenderOptions options : {RenderOptions::seed(), RenderOptions::exact()}) {
            const glm::vec3 at_vertex = render(scene, options).image.at(20, 20);
            CHECK(at_vertex.x == Approx(colors[k].x).margin(1e-6));
            CHECK(at_vertex.y == Approx(colors[k].y).margin(1e-6));
            CHECK(at_vertex.z == Approx(colors[k].z).margin(1e-6));
        }
    }
}

TEST_CASE("on a flat plane with a constant normal Gouraud and Phong agree (seed light vectors)") {
    Scene scene = screen_aligned_scene();
    scene.lighting = Lighting::full();
    scene.material = PhongMaterial{};
    scene.material.n = 5;
    scene.ambient = glm::vec3(0.3f);
    scene.lights = {{{3, 4, 6}, {1, 1, 1}}, {{-5, 1, 3}, {0.5f, 0.2f, 0.1f}}};
    scene.mesh.positions = {world_at(10, 10), world_at(90, 15), world_at(40, 90), world_at(95, 85)};
    scene.mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    scene.mesh.triangles = {{0, 2, 1}, {1, 2, 3}};
    scene.shader = Shader::gouraud;
    const Image gouraud = render(scene, RenderOptions::seed()).image;
    scene.shader = Shader::phong;
    const Image phong = render(scene, RenderOptions::seed()).image;
    CHECK(max_difference(gouraud, phong) < 1e-5f);
}

namespace {

// Eye at the origin looking down -z, 1 x 1 sensor, 64 x 64 pixels: the world
// point that projects to (column, row) at camera depth `depth`.
glm::dvec3 at_pixel(double column, double row, double depth, double focal = 1.0) {
    return {(column / 64.0 - 0.5) * depth / focal, (0.5 - row / 64.0) * depth / focal, -depth};
}

Scene perspective_scene(double focal = 1.0) {
    Scene scene;
    scene.camera.eye = {0, 0, 0};
    scene.camera.lookat = {0, 0, -1};
    scene.camera.focal = focal;
    scene.camera.sensor_height = 1;
    scene.camera.sensor_width = 1;
    scene.image = {64, 64, {0, 0, 0}};
    scene.mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    scene.mesh.triangles = {{0, 1, 2}};
    scene.shader = Shader::phong;
    return scene;
}

}  // namespace

TEST_CASE("seed and exact presets differ on a large close-up triangle") {
    // A floor-like triangle from depth 1 (bottom of the image) to depth 20 (top),
    // lit from close by: affine interpolation and centroid light vectors are both wrong here.
    Scene scene = perspective_scene();
    scene.mesh.positions = {at_pixel(4, 60, 1), at_pixel(60, 60, 1), at_pixel(32, 4, 20)};
    scene.lights = {{at_pixel(32, 50, 1.5) + glm::dvec3(0, 0.3, 0), {1, 1, 1}}};
    const RenderResult seed = render(scene, RenderOptions::seed());
    const RenderResult exact = render(scene, RenderOptions::exact());
    CHECK(seed.stats.triangles_dropped == 0);  // all three vertices are inside the image
    CHECK(seed.stats.samples_shaded == exact.stats.samples_shaded);
    CHECK(max_difference(seed.image, exact.image) > 0.1f);
}

TEST_CASE("seed and exact presets agree on a small distant triangle") {
    // Six pixels wide through a narrow (2.9 degree) field of view, 100 units
    // away: V, L and 1/z barely change across it, so the seed's per-triangle
    // vectors and affine interpolation are almost exact (within 1/255).
    Scene scene = perspective_scene(20.0);
    scene.mesh.positions = {at_pixel(29, 35, 100, 20), at_pixel(35, 35, 100.2, 20), at_pixel(32, 29, 100.4, 20)};
    scene.lights = {{{300, 500, 200}, {1, 1, 1}}};
    const RenderResult seed = render(scene, RenderOptions::seed());
    const RenderResult exact = render(scene, RenderOptions::exact());
    REQUIRE(exact.stats.samples_shaded > 10);
    CHECK(max_difference(seed.image, exact.image) < 1.0f / 255.0f);
}

TEST_CASE("border handling: seed drops, exact clips") {
    Scene scene = screen_aligned_scene();
    // One vertex far left of the image, one behind the eye.
    add_triangle(scene.mesh, world_at(-500, 50), world_at(60, 20), world_at(60, 80), {1, 0, 0});
    add_triangle(scene.mesh, {0, -1, 20}, {2, 3, 0}, {-2, 3, 0}, {0, 1, 0});
    const RenderResult seed = render(scene, RenderOptions::seed());
    CHECK(seed.stats.triangles_dropped == 2);
    CHECK(seed.stats.samples_shaded == 0);
    CHECK(seed.image.at(50, 50) == glm::vec3(0, 0, 1));
    const RenderResult exact = render(scene, RenderOptions::exact());
    CHECK(exact.stats.triangles_dropped == 0);
    CHECK(exact.stats.triangles_clipped == 2);
    CHECK(exact.stats.triangles_drawn == 2);
    CHECK(close(exact.image.at(50, 50), glm::vec3(1, 0, 0)));
    CHECK(close(exact.image.at(50, 0), glm::vec3(1, 0, 0)));  // the clipped part reaches the border
    CHECK(exact.stats.nonfinite_values_replaced == 0);
    CHECK(all_finite(exact.image));
}

TEST_CASE("the eight seed figures are finite, show the background, and ambient is ka * Ia * c") {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(12, 24, 1.0);
    const glm::vec3 surface(0.8f, 0.4f, 0.2f);
    scene.mesh.colors.assign(scene.mesh.positions.size(), surface);
    scene.camera.eye = {0, 0, 6};
    scene.camera.focal = 3;
    scene.camera.sensor_height = scene.camera.sensor_width = 2;
    scene.image = {48, 48, {0, 0, 1}};
    scene.material.ka = {0.5f, 0.25f, 1.0f};
    scene.ambient = {0.2f, 0.4f, 0.6f};
    scene.lights = {{{0, 10, 0}, {1, 1, 1}}, {{3, 3, 3}, {1, 0, 0}}};
    for (Shader shader : {Shader::gouraud, Shader::phong}) {
        for (const char* lighting : {"ambient", "diffuse", "specular", "full"}) {
            scene.shader = shader;
            scene.lighting = parse_lighting(lighting);
            for (RenderOptions options : {RenderOptions::seed(), RenderOptions::exact()}) {
                const RenderResult result = render(scene, options);
                INFO(to_string(shader) << " " << lighting);
                CHECK(all_finite(result.image));
                CHECK(result.stats.nonfinite_values_replaced == 0);
                CHECK(result.image.at(0, 0) == glm::vec3(0, 0, 1));
                CHECK(result.image.at(47, 47) == glm::vec3(0, 0, 1));
                CHECK(result.image.at(24, 24) != glm::vec3(0, 0, 1));
                if (scene.lighting == Lighting::only_ambient()) {
                    const glm::vec3 expected = scene.material.ka * scene.ambient * surface;
                    for (const glm::vec3& p : result.image.pixels) {
                        if (p == glm::vec3(0, 0, 1)) continue;
                        CHECK(p.x == Approx(expected.x).margin(1e-6));
                        CHECK(p.y == Approx(expected.y).margin(1e-6));
                        CHECK(p.z == Approx(expected.z).margin(1e-6));
                    }
                }
            }
        }
    }
}

TEST_CASE("the image is the same for any number of threads") {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(40, 80, 1.0);
    scene.camera.eye = {0.5, 0.7, 4};
    scene.camera.focal = 2;
    scene.image = {300, 200, {0, 0, 0}};
    scene.lights = {{{2, 2, 2}, {1, 1, 1}}};
    RenderOptions options = RenderOptions::exact();
    options.threads = 1;
    const Image one = render(scene, options).image;
    for (int threads : {2, 8}) {
        options.threads = threads;
        CHECK(render(scene, options).image.pixels == one.pixels);
    }
}

TEST_CASE("render_object takes the seed's plain arrays") {
    const Scene scene = screen_aligned_scene();
    const Image image = render_object({world_at(20, 20), world_at(80, 20), world_at(50, 80)}, {}, {{0, 1, 2}},
                                      scene.camera, scene.image, scene.material, scene.ambient, {}, Shader::flat,
                                      Lighting::only_ambient());
    CHECK(close(image.at(40, 50), glm::vec3(1.0f)));  // white by default, ka = Ia = 1
    CHECK(image.at(5, 5) == glm::vec3(0, 0, 1));
}

TEST_CASE("invalid scenes are rejected with the field named") {
    Scene scene = screen_aligned_scene();
    add_triangle(scene.mesh, world_at(20, 20), world_at(80, 20), world_at(50, 80), {1, 0, 0});
    SECTION("index out of range") {
        scene.mesh.triangles.push_back({0, 1, 7});
        CHECK_THROWS_WITH(render(scene), Catch::Contains("vertex index 7"));
    }
    SECTION("large meshes are checked in parallel, and the first bad element is named") {
        const glm::dvec3 p = world_at(50, 50);
        scene.mesh.positions.assign(300000, p);
        scene.mesh.colors.assign(300000, {1, 1, 1});
        scene.mesh.triangles.assign(300000, {0, 1, 2});
        scene.mesh.triangles[200001] = {0, 300001, 1};
        scene.mesh.triangles[100001] = {0, 1, 300000};
        CHECK_THROWS_WITH(render(scene), Catch::Contains("triangle 100001 has vertex index 300000"));
        scene.mesh.colors[250000].g = std::numeric_limits<float>::infinity();
        scene.mesh.colors[70000].r = std::numeric_limits<float>::quiet_NaN();
        CHECK_THROWS_WITH(render(scene), Catch::Contains("colour of vertex 70000 is not finite"));
        scene.mesh.positions[299999].x = std::numeric_limits<double>::infinity();
        scene.mesh.positions[131072].z = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH(render(scene), Catch::Contains("position of vertex 131072 is not finite"));
        scene.mesh.positions.assign(300000, p);
        scene.mesh.colors.assign(300000, {1, 1, 1});
        scene.mesh.triangles.assign(300000, {0, 1, 2});
        scene.mesh.normals.assign(300000, {0, 0, 1});
        scene.mesh.normals[200000].y = std::numeric_limits<float>::quiet_NaN();
        scene.mesh.normals[150000].x = -std::numeric_limits<float>::infinity();
        CHECK_THROWS_WITH(render(scene), Catch::Contains("mesh.normals[150000]"));
        scene.mesh.normals[150000].x = 0.0f;
        scene.mesh.normals[200000].y = 0.0f;
        CHECK_NOTHROW(render(scene));  // every block valid: no block reports its end as a bad element
    }
    SECTION("the finiteness test takes every finite number, however large or small, and names the first bad one") {
        // The largest doubles, subnormals and -0 pass; of two bad elements in
        // one block of the parallel check, the first is named.
        const double largest = std::numeric_limits<double>::max();
        const double tiny = std::numeric_limits<double>::denorm_min();
        Mesh mesh;
        mesh.positions.assign(200000, {largest, -largest, tiny});
        mesh.positions[7] = {-0.0, -tiny, 0.0};
        mesh.triangles.assign(1, {0, 1, 2});
        CHECK_NOTHROW(validate_mesh(mesh));
        mesh.positions[131072 + 200].y = std::numeric_limits<double>::quiet_NaN();
        mesh.positions[131072 + 37].z = -std::numeric_limits<double>::infinity();
        CHECK_THROWS_WITH(validate_mesh(mesh), Catch::Contains("position of vertex 131109 is not finite"));
    }
    SECTION("negative exponent") {
        scene.material.n = -1;
        CHECK_THROWS_WITH(render(scene), Catch::Contains("material.n"));
    }
    SECTION("zero-size image") {
        scene.image.columns = 0;
        CHECK_THROWS_WITH(render(scene), Catch::Contains("image.columns"));
    }
}
