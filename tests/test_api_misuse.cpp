// A caller's mistakes at the public C++ API: each is refused with a standard
// exception naming the C++ member, or is defined behaviour the test pins down
// (docs/robustness.md, "Mistakes at the API"). None reads or writes out of
// bounds; the sanitizer preset runs this file too.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include <catch2/catch.hpp>

#include "phongrast/image.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/render.hpp"

using namespace phongrast;
using Catch::Contains;

namespace {

/// A 32 x 32 picture of one lit triangle, filling most of it.
Scene triangle_scene() {
    Scene scene;
    scene.mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    scene.mesh.triangles = {{0, 1, 2}};
    scene.camera.eye = {0, 0, 3};
    scene.image.rows = 32;
    scene.image.columns = 32;
    scene.image.background = glm::vec3(0.0f);
    scene.lights = {{{1, 2, 4}, {1, 1, 1}}};
    return scene;
}

bool all_finite(const Image& image) {
    for (const glm::vec3& p : image.pixels) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    }
    return true;
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace

TEST_CASE("calculate_normals with an index past the positions throws std::out_of_range naming the corner") {
    const std::vector<glm::dvec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK_THROWS_AS(calculate_normals(positions, {{0, 1, 3}}), std::out_of_range);
    CHECK_THROWS_WITH(calculate_normals(positions, {{0, 1, 3}}),
                      Contains("triangles[0][2] = 3") && Contains("below positions.size() = 3"));
    CHECK_THROWS_AS(calculate_normals(positions, {{0, 1, 2}, {4000000000u, 0, 1}}), std::out_of_range);
    Mesh mesh;
    mesh.positions = positions;
    mesh.triangles = {{2, 7, 1}};
    CHECK_THROWS_WITH(calculate_normals(mesh), Contains("triangles[0][1] = 7"));
    // In range: unchanged.
    CHECK(calculate_normals(positions, {{0, 1, 2}}).size() == 3);
}

TEST_CASE("Image::at outside the image, or past a shortened pixel buffer, throws std::out_of_range") {
    Image image(4, 4, glm::vec3(0.5f));
    CHECK(image.at(3, 3) == glm::vec3(0.5f));
    CHECK_THROWS_AS(image.at(10, 10), std::out_of_range);
    CHECK_THROWS_AS(image.at(-1, 0), std::out_of_range);
    CHECK_THROWS_AS(image.at(0, 4), std::out_of_range);
    CHECK_THROWS_AS(image.at(0, -1), std::out_of_range);
    CHECK_THROWS_WITH(image.at(10, 10), Contains("image.rows = 4") && Contains("image.columns = 4"));
    image.pixels.resize(5);
    CHECK_THROWS_WITH(image.at(2, 0), Contains("image.pixels.size() is 5"));
    const Image& constant = image;
    CHECK_THROWS_AS(constant.at(4, 0), std::out_of_range);
}

TEST_CASE("Image's constructor and validate_image refuse negative sizes, sizes past the limit and short buffers") {
    CHECK_THROWS_AS(Image(-1, 4), std::invalid_argument);
    CHECK_THROWS_AS(Image(100000, 100000), std::length_error);
    CHECK_THROWS_WITH(Image(100000, 100000), Contains("100000 x 100000") && Contains("111.8 GiB"));
    CHECK(Image(0, 0).pixels.empty());
    Image image(2, 3);
    CHECK_NOTHROW(validate_image(image));
    image.pixels.pop_back();
    CHECK_THROWS_AS(validate_image(image), std::invalid_argument);
    CHECK_THROWS_WITH(validate_image(image), Contains("image.pixels.size() is 5") && Contains("2 * 3 = 6"));
}

TEST_CASE("one image-size limit: the side, the pixel count and the sample count, each naming the memory") {
    CHECK_NOTHROW(validate_image_size(kMaxImageSide, kMaxImagePixels / kMaxImageSide));
    CHECK_THROWS_AS(validate_image_size(kMaxImageSide + 1, 1), std::length_error);
    CHECK_THROWS_AS(validate_image_size(kMaxImageSide, kMaxImageSide), std::length_error);
    CHECK_THROWS_AS(validate_image_size(0, 1), std::invalid_argument);
    Scene scene = triangle_scene();
    scene.image.rows = 100000;
    scene.image.columns = 100000;
    CHECK_THROWS_AS(render(scene), std::length_error);
    CHECK_THROWS_WITH(render(scene), Contains("image.rows x image.columns") && Contains("100000 x 100000") &&
                                         Contains("111.8 GiB") && Contains("268435456"));
    // Samples count too: 8192 x 8192 pixels are fine, 16 samples each are not.
    scene.image.rows = 8192;
    scene.image.columns = 8192;
    CHECK_NOTHROW(validate_render(scene));
    RenderOptions options = RenderOptions::exact();
    options.samples_per_axis = 4;
    CHECK_THROWS_AS(validate_render(scene, options), std::length_error);
    CHECK_THROWS_WITH(validate_render(scene, options), Contains("samples_per_axis") && Contains("12.0 GiB"));
    scene.image.rows = 0;
    CHECK_THROWS_WITH(validate_render(scene), Contains("image.rows"));
}

TEST_CASE("errors name the C++ members: image.rows, image.columns, camera.sensor_height, camera.sensor_width") {
    Scene scene = triangle_scene();
    scene.image.columns = 0;
    CHECK_THROWS_WITH(render(scene), Contains("image.columns"));
    scene = triangle_scene();
    scene.camera.sensor_height = 0.0;
    CHECK_THROWS_WITH(render(scene), Contains("camera.sensor_height"));
    scene = triangle_scene();
    scene.camera.sensor_width = -1.0;
    CHECK_THROWS_WITH(render(scene), Contains("camera.sensor_width"));
    CHECK_THROWS_WITH(make_camera_frame(triangle_scene().camera, 0, 4), Contains("image.rows"));
}

TEST_CASE("out-of-range enums are refused, naming the member") {
    const Scene scene = triangle_scene();
    Scene bad_shader = scene;
    bad_shader.shader = static_cast<Shader>(42);
    CHECK_THROWS_AS(render(bad_shader), std::invalid_argument);
    CHECK_THROWS_WITH(render(bad_shader), Contains("shader: 42"));
    const auto refuses = [&](auto change, const char* member) {
        RenderOptions options = RenderOptions::exact();
        change(options);
        CHECK_THROWS_WITH(render(scene, options), Contains(member));
        CHECK_THROWS_AS(render(scene, options), std::invalid_argument);
    };
    refuses([](RenderOptions& o) { o.visibility = static_cast<Visibility>(2); }, "options.visibility");
    refuses([](RenderOptions& o) { o.precision = static_cast<Precision>(-1); }, "options.precision");
    refuses([](RenderOptions& o) { o.border = static_cast<BorderPolicy>(7); }, "options.border");
    refuses([](RenderOptions& o) { o.light_vectors = static_cast<LightVectors>(2); }, "options.light_vectors");
    refuses([](RenderOptions& o) { o.interpolation = static_cast<Interpolation>(9); }, "options.interpolation");
    refuses([](RenderOptions& o) { o.overdraw = static_cast<Overdraw>(3); }, "options.overdraw");
    refuses([](RenderOptions& o) { o.sample_pattern = static_cast<SamplePattern>(2); }, "options.sample_pattern");
    refuses([](RenderOptions& o) { o.back_faces = static_cast<BackFaces>(5); }, "options.back_faces");
    refuses([](RenderOptions& o) { o.samples_per_axis = 17; }, "options.samples_per_axis");
    refuses([](RenderOptions& o) { o.threads = -1; }, "options.threads");
}

TEST_CASE("negative coefficients, ambient and light intensities are legal: the formula's value, light sinks") {
    // The contract asks only that they be finite, and defines the picture for
    // any finite value: a negative intensity subtracts light (EXR keeps the
    // negative values, PNG clamps them to 0). IEEE multiplication is exactly
    // symmetric in sign, so a light of intensity -I gives exactly minus the
    // diffuse picture of +I.
    Scene scene = triangle_scene();
    scene.lighting = Lighting::only_diffuse();
    const Image lit = render(scene).image;
    Scene sink = scene;
    sink.lights[0].intensity = glm::vec3(-1.0f);
    const Image sunk = render(sink).image;
    REQUIRE(lit.pixels.size() == sunk.pixels.size());
    int negative = 0;
    for (std::size_t p = 0; p < lit.pixels.size(); ++p) {
        if (lit.pixels[p] == scene.image.background) continue;  // background, or unlit
        CHECK(sunk.pixels[p] == -lit.pixels[p]);
        negative += sunk.pixels[p].x < 0.0f ? 1 : 0;
    }
    CHECK(negative > 0);
    CHECK(all_finite(sunk));
    // Negative coefficients and ambient render too, finite.
    for (int which = 0; which < 4; ++which) {
        Scene odd = triangle_scene();
        if (which == 0) odd.material.ka = glm::vec3(-0.5f);
        if (which == 1) odd.material.kd = glm::vec3(-0.5f);
        if (which == 2) odd.material.ks = glm::vec3(-1.0f);
        if (which == 3) odd.ambient = glm::vec3(-0.2f);
        CHECK(all_finite(render(odd).image));
    }
    // NaN stays an error, named.
    Scene bad = scene;
    bad.lights[0].intensity.x = kNaN;
    CHECK_THROWS_WITH(render(bad), Contains("lights[0]"));
}

TEST_CASE("user normals: NaN is an error, zero takes the computed normal, any length is normalised") {
    Scene scene = triangle_scene();
    const Image computed = render(scene).image;  // computed normals: (0, 0, 1) at every vertex

    scene.mesh.normals = {{0, 0, 1}, {0, 0, kNaN}, {0, 0, 1}};
    CHECK_THROWS_AS(render(scene), std::invalid_argument);
    CHECK_THROWS_WITH(render(scene), Contains("mesh.normals[1]"));
    scene.mesh.normals[1] = {0, 0, std::numeric_limits<float>::infinity()};
    CHECK_THROWS_WITH(render(scene), Contains("mesh.normals[1]"));

    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene with = triangle_scene();
        with.shader = shader;
        const Image reference = render(with).image;
        with.mesh.normals = {{0, 0, 0}, {0, 0, 1}, {0, 0, 0}};  // zero: "compute this one"
        CHECK(render(with).image.pixels == reference.pixels);
        with.mesh.normals = {{0, 0, 5}, {0, 0, 0.001f}, {0, 0, 1e6f}};  // not unit: normalised
        CHECK(render(with).image.pixels == reference.pixels);
    }
    CHECK(all_finite(computed));
    // A wrong count stays an error, as before.
    scene.mesh.normals = {{0, 0, 1}};
    CHECK_THROWS_AS(render(scene), std::invalid_argument);
}

TEST_CASE("an empty mesh is reported in RenderStats::empty_scene, and renders the background") {
    Scene scene = triangle_scene();
    CHECK_FALSE(render(scene).stats.empty_scene);
    scene.mesh.triangles.clear();
    RenderResult result = render(scene);
    CHECK(result.stats.empty_scene);
    for (const glm::vec3& p : result.image.pixels) CHECK(p == scene.image.background);
    scene.mesh = Mesh{};
    CHECK(render(scene).stats.empty_scene);
    // Found by fuzz_api: a rotated grid's resolve rebuilt the statistics and lost the flag.
    for (SamplePattern pattern : {SamplePattern::ordered_grid, SamplePattern::rotated_grid}) {
        RenderOptions options = RenderOptions::exact();
        options.samples_per_axis = 3;
        options.sample_pattern = pattern;
        CHECK(render(scene, options).stats.empty_scene);
        CHECK_FALSE(render(triangle_scene(), options).stats.empty_scene);
    }
}

TEST_CASE("threads above the hardware's are clamped and draw the same picture") {
    const Scene scene = triangle_scene();
    RenderOptions one = RenderOptions::exact();
    one.threads = 1;
    RenderOptions many = RenderOptions::exact();
    many.threads = 1000;
    CHECK(render(scene, many).image.pixels == render(scene, one).image.pixels);
    Renderer renderer(many);
    CHECK(renderer.render(scene).image.pixels == render(scene, one).image.pixels);
}

TEST_CASE("a moved-from Renderer works again like a new Renderer()") {
    const Scene scene = triangle_scene();
    RenderOptions seed = RenderOptions::seed();
    Renderer renderer(seed);
    renderer.render(scene);
    Renderer moved(std::move(renderer));
    CHECK(moved.options().border == BorderPolicy::drop_triangle);
    // NOLINTNEXTLINE(bugprone-use-after-move): that is the point of the test.
    CHECK(renderer.options().border == RenderOptions::exact().border);
    CHECK(renderer.render(scene).image.pixels == render(scene, RenderOptions::exact()).image.pixels);
    Renderer assigned;
    assigned = std::move(moved);
    // NOLINTNEXTLINE(bugprone-use-after-move)
    moved.set_options(seed);
    CHECK(moved.render(scene).image.pixels == render(scene, seed).image.pixels);
}
