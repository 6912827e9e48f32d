// Texture maps (contract "Texture maps"): the bilinear lookup by hand for
// each wrap mode and the t orientation, then rendered pixels of textured
// quads against that lookup: a screen-aligned quad (every wrap mode, float
// and double, clipped at the image border), and a slanted quad where exact
// mode takes (s, t) perspective-correct and seed mode linearly in screen space.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "phongrast/render.hpp"
#include "phongrast/texture.hpp"
#include "textured_quad.hpp"

using namespace phongrast;

namespace {

/// A texture of `rows` x `columns` texels with distinct values: texel (i, j) = (i, j, i*columns + j) / size.
std::shared_ptr<const TextureImage> numbered_texture(int rows, int columns) {
    auto image = std::make_shared<TextureImage>();
    image->rows = rows;
    image->columns = columns;
    image->name = "numbered";
    const float size = float(rows * columns);
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            image->texels.push_back(glm::vec3(float(i) / float(rows), float(j) / float(columns), float(i * columns + j) / size));
        }
    }
    return image;
}

TextureMap map_of(std::shared_ptr<const TextureImage> image, TextureWrap s, TextureWrap t) {
    TextureMap map;
    map.image = std::move(image);
    map.wrap_s = s;
    map.wrap_t = t;
    return map;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

}  // namespace

TEST_CASE("the bilinear lookup by hand: texel centres, midpoints, and each wrap mode at the border") {
    const auto image = numbered_texture(2, 2);  // rows 0 (top) and 1 (bottom)
    const auto texel = [&](int i, int j) { return glm::dvec3(image->at(i, j)); };
    const TextureMap repeat = map_of(image, TextureWrap::repeat, TextureWrap::repeat);
    // The centre of texel (row 0, column 0) is s = 1/4, t = 3/4 (t = 0 is the bottom row).
    CHECK(sample_bilinear(repeat, 0.25, 0.75) == texel(0, 0));
    CHECK(sample_bilinear(repeat, 0.75, 0.25) == texel(1, 1));
    CHECK(sample_bilinear(repeat, 0.25, 0.25) == texel(1, 0));
    // Halfway between all four centres.
    CHECK(near(sample_bilinear(repeat, 0.5, 0.5), (texel(0, 0) + texel(0, 1) + texel(1, 0) + texel(1, 1)) / 4.0, 1e-15));
    // s = 0: x = -1/2, halfway between column -1 and column 0.
    const glm::dvec3 top_left_edge = sample_bilinear(repeat, 0.0, 0.75);
    CHECK(near(top_left_edge, (texel(0, 1) + texel(0, 0)) / 2.0, 1e-15));  // repeat: column -1 is column 1
    const TextureMap clamp = map_of(image, TextureWrap::clamp_to_edge, TextureWrap::clamp_to_edge);
    CHECK(sample_bilinear(clamp, 0.0, 0.75) == texel(0, 0));                 // clamp: column -1 is column 0
    const TextureMap mirror = map_of(image, TextureWrap::mirrored_repeat, TextureWrap::mirrored_repeat);
    CHECK(sample_bilinear(mirror, 0.0, 0.75) == texel(0, 0));                // mirror: column -1 is column 0
    // One texel further out: column -2 (repeat: 0, clamp: 0, mirror: 1) and -1.
    CHECK(near(sample_bilinear(repeat, -0.5, 0.75), (texel(0, 0) + texel(0, 1)) / 2.0, 1e-15));
    CHECK(sample_bilinear(clamp, -0.5, 0.75) == texel(0, 0));
    CHECK(near(sample_bilinear(mirror, -0.5, 0.75), (texel(0, 1) + texel(0, 0)) / 2.0, 1e-15));
    // s = 1.25 (x = 2): repeat column 0, clamp column 1, mirror column 1 (the period is 2 sizes).
    CHECK(sample_bilinear(repeat, 1.25, 0.75) == texel(0, 0));
    CHECK(sample_bilinear(clamp, 1.25, 0.75) == texel(0, 1));
    CHECK(sample_bilinear(mirror, 1.25, 0.75) == texel(0, 1));
    // Each axis its own wrap: s repeats, t clamps.
    const TextureMap mixed = map_of(image, TextureWrap::repeat, TextureWrap::clamp_to_edge);
    CHECK(sample_bilinear(mixed, 1.25, 1.5) == texel(0, 0));
    CHECK(sample_bilinear(mixed, 1.25, -0.5) == texel(1, 0));
    // No image: T = 1.
    CHECK(sample_bilinear(TextureMap{}, 0.3, 0.4) == glm::dvec3(1.0));
}

namespace {


/// A quad with corners `corners` (counter-clockwise seen from +z) and (s, t) at them, textured by `map`.
Mesh quad(const glm::dvec3 (&corners)[4], const glm::vec2 (&st)[4], const TextureMap& map) {
    return textured_quad_mesh(corners, st, map);
}

}  // namespace

TEST_CASE("a screen-aligned textured quad shows the bilinear lookup at each pixel centre, in every wrap mode") {
    const auto image = numbered_texture(2, 3);
    const int size = 12;
    // The quad overhangs the image (clipped in exact mode); seed mode draws one inside it.
    // Only ambient light of 1 on c = 1: Phong's pixel is T, Gouraud's T x A + S with A = 1 and S = 0.
    for (Shader shader : {Shader::phong, Shader::gouraud})
    for (bool seed : {false, true}) {
        const double half = seed ? 0.5 : 0.75;
        const glm::dvec3 corners[4] = {{-half, -half, 0.0}, {half, -half, 0.0}, {half, half, 0.0}, {-half, half, 0.0}};
        const double s0 = -0.6, s1 = 1.9, t0 = -0.3, t1 = 1.7;  // past the texture on every side
        const glm::vec2 st[4] = {{float(s0), float(t0)}, {float(s1), float(t0)}, {float(s1), float(t1)}, {float(s0), float(t1)}};
        for (TextureWrap wrap_s : {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat}) {
            for (TextureWrap wrap_t : {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat}) {
                const TextureMap map = map_of(image, wrap_s, wrap_t);
                Scene scene = textured_quad_scene(quad(corners, st, map), size);
                scene.shader = shader;
                for (Precision precision : {Precision::single_float, Precision::double_float}) {
                    RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
                    options.precision = precision;
                    const Image picture = render(scene, options).image;
                    INFO(to_string(shader) << ", " << std::string(seed ? "seed" : "exact") << ", s " << to_string(wrap_s) << ", t " << to_string(wrap_t)
                                                   << (precision == Precision::double_float ? ", double" : ", float"));
                    int checked = 0, wrong = 0;
                    for (int i = 0; i < size; ++i) {
                        for (int j = 0; j < size; ++j) {
                            const double x = (j + 0.5) / size - 0.5, y = 0.5 - (i + 0.5) / size;
                            const double s = s0 + (x + half) / (2 * half) * (s1 - s0);
                            const double t = t0 + (y + half) / (2 * half) * (t1 - t0);
                            const glm::dvec3 expected = sample_bilinear(map, s, t);
                            ++checked;
                            if (!near(glm::dvec3(picture.at(i, j)), expected, 2e-5)) {
                                ++wrong;
                                UNSCOPED_INFO("pixel " << i << ", " << j << ": " << picture.at(i, j).x << " "
                                                       << picture.at(i, j).y << " " << picture.at(i, j).z
                                                       << " expected " << expected.x << " " << expected.y << " "
                                                       << expected.z);
                            }
                        }
                    }
                    CHECK(checked == size * size);
                    CHECK(wrong == 0);
                }
            }
        }
    }
}

TEST_CASE("t = 0 is the image's bottom row, and nearest takes the texel under the sample") {
    // Top row red, bottom row blue.
    auto image = std::make_shared<TextureImage>();
    image->rows = 2;
    image->columns = 1;
    image->texels = {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    const TextureMap map = map_of(image, TextureWrap::clamp_to_edge, TextureWrap::clamp_to_edge);
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};  // OBJ-style: t up
    const Scene scene = textured_quad_scene(quad(corners, st, map), 8);
    for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest}) {
        RenderOptions options = RenderOptions::exact();
        options.texture_filter = filter;
        const Image picture = render(scene, options).image;
        INFO(to_string(filter));
        CHECK(picture.at(0, 3) == glm::vec3(1.0f, 0.0f, 0.0f));  // top: row 0 of the texture
        CHECK(picture.at(7, 3) == glm::vec3(0.0f, 0.0f, 1.0f));  // bottom: row 1
        if (filter == TextureFilter::nearest) {
            // Every pixel is one texel: the upper half red, the lower half blue.
            for (int i = 0; i < 8; ++i) CHECK(picture.at(i, 4) == (i < 4 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1)));
        } else {
            // Bilinear blends across the middle: row 3's centre is at texel y = 3.5/8 x 2 - 1/2 = 0.375.
            CHECK(picture.at(3, 4).x == Approx(0.625).margin(1e-6));
            CHECK(picture.at(3, 4).z == Approx(0.375).margin(1e-6));
        }
    }
}

TEST_CASE("a slanted quad: exact mode interpolates (s, t) perspective-correct, seed mode linearly on screen") {
    const auto image = numbered_texture(4, 4);
    const TextureMap map = map_of(image, TextureWrap::repeat, TextureWrap::repeat);
    // A square of side 0.8 tilted 60 degrees about x: the far edge is much smaller on screen.
    const double angle = 1.0471975511965976, side = 0.8;
    const glm::dvec3 p0(-0.4, -0.25, 0.2), e1(side, 0.0, 0.0), e2(0.0, side * std::cos(angle), -side * std::sin(angle));
    const glm::dvec3 corners[4] = {p0, p0 + e1, p0 + e1 + e2, p0 + e2};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {2.0f, 0.0f}, {2.0f, 2.0f}, {0.0f, 2.0f}};  // st = 2 (u, v)
    const Mesh mesh = quad(corners, st, map);
    const int size = 24;
    Scene scene = textured_quad_scene(mesh, size);
    const glm::dvec3 eye = scene.camera.eye;
    const glm::dvec3 normal = glm::normalize(glm::cross(e1, e2));

    // Gouraud's pixel is T x A + S with A = 1, S = 0 here: T at the same (s, t).
    for (Shader shader : {Shader::phong, Shader::gouraud})
    for (bool seed : {false, true}) {
        scene.shader = shader;
        RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
        options.aovs.id = true;
        const RenderResult result = render(scene, options);
        int covered = 0, wrong = 0;
        double largest_gap = 0.0;  // between the two interpolations, where the pictures differ
        for (int i = 0; i < size; ++i) {
            for (int j = 0; j < size; ++j) {
                const int id = result.aovs.id[std::size_t(i) * size + j];
                if (id < 0) continue;
                ++covered;
                const double x = (j + 0.5) / size - 0.5, y = 0.5 - (i + 0.5) / size;
                // Exact: the ray through the pixel centre meets the quad's plane at (u, v).
                const glm::dvec3 direction(x, y, -1.0);
                const double lambda = glm::dot(p0 - eye, normal) / glm::dot(direction, normal);
                const glm::dvec3 hit = eye + lambda * direction - p0;
                const double u = glm::dot(hit, e1) / (side * side), v = glm::dot(hit, e2) / (side * side);
                const glm::dvec2 exact_st(2.0 * u, 2.0 * v);
                // Seed: the screen-space barycentric weights of the pixel centre in triangle `id`.
                glm::dvec2 screen[3];
                glm::dvec2 corner_st[3];
                double corner_depth[3];
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t vertex = mesh.triangles[std::size_t(id)][k];
                    const glm::dvec3 p = mesh.positions[vertex];
                    const double depth = eye.z - p.z;
                    // Snapped to 1/256 of a pixel, as the rasteriser does before it interpolates.
                    screen[k] = glm::round(glm::dvec2((p.x / depth + 0.5) * size, (0.5 - p.y / depth) * size) * 256.0) /
                                256.0;
                    corner_depth[k] = depth;
                    corner_st[k] = glm::dvec2(mesh.texcoords[vertex]);
                }
                const glm::dvec2 centre(j + 0.5, i + 0.5);
                const auto area = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
                    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                };
                const double whole = area(screen[0], screen[1], screen[2]);
                const double w0 = area(centre, screen[1], screen[2]) / whole;
                const double w1 = area(screen[0], centre, screen[2]) / whole;
                const double w2 = 1.0 - w0 - w1;
                const glm::dvec2 seed_st = w0 * corner_st[0] + w1 * corner_st[1] + w2 * corner_st[2];
                // Exact mode: the same weights divided by depth, renormalised (perspective-correct on the
                // snapped triangle); within snapping of the ray's hit.
                const double q0 = w0 / corner_depth[0], q1 = w1 / corner_depth[1], q2 = w2 / corner_depth[2];
                const glm::dvec2 perspective_st = (q0 * corner_st[0] + q1 * corner_st[1] + q2 * corner_st[2]) / (q0 + q1 + q2);
                if (glm::length(perspective_st - exact_st) > 2e-3) ++wrong;
                const glm::dvec2 used = seed ? seed_st : perspective_st;
                largest_gap = std::max(largest_gap, glm::length(seed_st - exact_st));
                const glm::dvec3 expected = sample_bilinear(map, used.x, used.y);
                if (!near(glm::dvec3(result.image.at(i, j)), expected, 1e-4)) {
                    ++wrong;
                    if (wrong < 5) {
                        WARN("pixel " << i << ", " << j << " st " << used.x << " " << used.y << " got "
                                      << result.image.at(i, j).x << " " << result.image.at(i, j).y << " "
                                      << result.image.at(i, j).z << " expected " << expected.x << " " << expected.y
                                      << " " << expected.z);
                    }
                }
            }
        }
        INFO(to_string(shader) << ", " << (seed ? "seed" : "exact"));
        CHECK(covered > 150);
        CHECK(wrong == 0);
        CHECK(largest_gap > 0.1);  // the two interpolations really differ on this quad
    }
}

TEST_CASE("supersampling averages textured samples, and faces without texture coordinates have T = 1") {
    const auto image = numbered_texture(3, 3);
    const TextureMap map = map_of(image, TextureWrap::repeat, TextureWrap::repeat);
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    Mesh mesh = quad(corners, st, map);
    Scene scene = textured_quad_scene(mesh, 6);
    RenderOptions options = RenderOptions::exact();
    options.samples_per_axis = 2;
    for (Shader shader : {Shader::phong, Shader::gouraud}) {
        // Gouraud lit with a highlight, so that A and S both vary across the quad.
        Scene lit = scene;
        lit.shader = shader;
        if (shader == Shader::gouraud) {
            lit.lighting = Lighting::full();
            lit.ambient = glm::vec3(0.2f);
            lit.material = PhongMaterial{glm::vec3(0.3f), glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 8.0f};
            lit.lights = {PointLight{glm::dvec3(0.3, 0.4, 0.6), glm::vec3(1.0f, 0.9f, 0.8f)}};
        }
        const Image pixels = render(lit, options).image;
        Scene large = lit;
        large.image.rows = large.image.columns = 12;
        const Image samples = render(large, RenderOptions::exact()).image;
        INFO(to_string(shader));
        for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
                const glm::vec3 sum = samples.at(2 * i, 2 * j) + samples.at(2 * i, 2 * j + 1) +
                                      samples.at(2 * i + 1, 2 * j) + samples.at(2 * i + 1, 2 * j + 1);
                CHECK(pixels.at(i, j) == sum * 0.25f);
            }
        }
    }
    // The second triangle loses a corner's (s, t): it draws with T = 1, the first stays textured.
    mesh.texcoord_triangles[1][2] = kNoIndex;
    scene.mesh = mesh;
    options.samples_per_axis = 1;
    options.aovs.id = true;
    const RenderResult result = render(scene, options);
    for (std::size_t p = 0; p < result.image.pixels.size(); ++p) {
        if (result.aovs.id[p] == 1) CHECK(result.image.pixels[p] == glm::vec3(1.0f));
    }
    CHECK(result.image.at(5, 4) != glm::vec3(1.0f));  // lower right: triangle 0, textured
}

TEST_CASE("every shader draws textures with every filter, and a broken texture image is refused, naming the field") {
    const auto image = numbered_texture(2, 2);
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    Scene scene = textured_quad_scene(quad(corners, st, map_of(image, TextureWrap::repeat, TextureWrap::repeat)), 4);
    // Gouraud since T x A + S at its vertices; trilinear since the mip pyramid
    // (tests/test_texture_trilinear.cpp). Here 2 x 2 texels over 4 x 4 pixels
    // are magnified: trilinear is bilinear on level 0, bit for bit.
    for (Shader shader : {Shader::gouraud, Shader::flat, Shader::phong}) {
        scene.shader = shader;
        for (TextureFilter filter : {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear}) {
            RenderOptions exact = RenderOptions::exact(), seed = RenderOptions::seed();
            exact.texture_filter = seed.texture_filter = filter;
            CHECK_NOTHROW(render(scene, exact));
            CHECK_NOTHROW(render(scene, seed));
            CHECK_NOTHROW(validate_render(scene, exact));
        }
        RenderOptions trilinear = RenderOptions::exact();
        trilinear.texture_filter = TextureFilter::trilinear;
        CHECK(render(scene, trilinear).image.pixels == render(scene, RenderOptions::exact()).image.pixels);
    }
    scene.shader = Shader::phong;
    // A texture image whose size does not match its texels.
    auto broken = std::make_shared<TextureImage>(*image);
    broken->texels.pop_back();
    scene.mesh.materials[0].texture->image = broken;
    CHECK_THROWS_WITH(render(scene, RenderOptions::exact()), Catch::StartsWith("mesh.materials[0] (textured).texture"));
}

TEST_CASE("flat shading of a textured face: T at the sample times A, plus S, both lit once per triangle") {
    const auto image = numbered_texture(3, 4);
    const TextureMap map = map_of(image, TextureWrap::mirrored_repeat, TextureWrap::repeat);
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{-0.5f, 0.0f}, {1.5f, 0.0f}, {1.5f, 2.0f}, {-0.5f, 2.0f}};
    const int size = 16;
    Scene textured = textured_quad_scene(quad(corners, st, map), size);
    textured.shader = Shader::flat;
    textured.lighting = Lighting::full();
    textured.ambient = glm::vec3(0.2f);
    textured.material = PhongMaterial{glm::vec3(0.3f), glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 8.0f};
    textured.lights = {PointLight{glm::dvec3(0.3, 0.4, 0.6), glm::vec3(1.0f, 0.9f, 0.8f)}};
    // The same quad untextured, lit without ks (A) and with only ks (S): flat writes each triangle's value.
    Scene colour_part = textured;
    colour_part.mesh.materials.clear();
    colour_part.mesh.face_materials.clear();
    colour_part.mesh.texcoords.clear();
    colour_part.mesh.texcoord_triangles.clear();
    Scene specular_part = colour_part;
    colour_part.material.ks = glm::vec3(0.0f);
    specular_part.material.ka = specular_part.material.kd = glm::vec3(0.0f);
    for (bool seed : {false, true}) {
        const RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
        const Image picture = render(textured, options).image;
        const Image a = render(colour_part, options).image;
        const Image s_part = render(specular_part, options).image;
        int wrong = 0;
        double specular_seen = 0.0;
        for (int i = 0; i < size; ++i) {
            for (int j = 0; j < size; ++j) {
                const double x = (j + 0.5) / size - 0.5, y = 0.5 - (i + 0.5) / size;
                const glm::dvec3 texel = sample_bilinear(map, -0.5 + (x + 0.5) * 2.0, (y + 0.5) * 2.0);
                const glm::dvec3 expected = texel * glm::dvec3(a.at(i, j)) + glm::dvec3(s_part.at(i, j));
                specular_seen = std::max(specular_seen, double(s_part.at(i, j).x));
                if (!near(glm::dvec3(picture.at(i, j)), expected, 2e-5)) ++wrong;
            }
        }
        INFO((seed ? "seed" : "exact"));
        CHECK(wrong == 0);
        CHECK(specular_seen > 0.01);  // the split is tested with a real highlight
    }
}

TEST_CASE("the uv output: (s, t) at each pixel, interpolated as the shading interpolates it") {
    const auto image = numbered_texture(2, 2);
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {2.0f, 0.0f}, {2.0f, 1.0f}, {0.0f, 1.0f}};
    const int size = 10;
    Scene scene = textured_quad_scene(quad(corners, st, map_of(image, TextureWrap::repeat, TextureWrap::repeat)), size);
    scene.mesh.triangles[1] = {0, 2, 3};
    scene.mesh.positions[3] = glm::dvec3(-0.5, 0.3, 0.0);  // the second triangle no longer reaches the top: background there
    for (Shader shader : {Shader::phong, Shader::flat, Shader::gouraud}) {
        scene.shader = shader;
        INFO(to_string(shader));
        RenderOptions options = RenderOptions::exact();
        options.aovs.uv = true;
        options.aovs.id = true;
        const RenderResult result = render(scene, options);
        REQUIRE(result.aovs.uv.size() == std::size_t(size * size));
        int background = 0;
        for (int i = 0; i < size; ++i) {
            for (int j = 0; j < size; ++j) {
                const std::size_t p = std::size_t(i) * size + std::size_t(j);
                const glm::vec2 uv = result.aovs.uv[p];
                if (result.aovs.id[p] < 0) {
                    ++background;
                    CHECK(uv == glm::vec2(0.0f));
                } else if (result.aovs.id[p] == 0) {
                    // Triangle 0 is the lower-right half of the square: s = 2 (x + 1/2), t = y + 1/2.
                    const double x = (j + 0.5) / size - 0.5, y = 0.5 - (i + 0.5) / size;
                    CHECK(uv.x == Approx(2.0 * (x + 0.5)).margin(1e-5));
                    CHECK(uv.y == Approx(y + 0.5).margin(1e-5));
                }
            }
        }
        CHECK(background > 0);
    }
    CHECK(parse_aovs("uv").uv);
    CHECK(to_string(AovRequest::all()) == "depth,normal,id,alpha,uv,distance");
}

namespace {

/// The lit textured quad of the Gouraud tests: the screen-aligned square of
/// textured_quad_scene() with a colour per vertex, one light and a highlight.
Scene lit_gouraud_quad(const TextureMap& map, const glm::vec2 (&st)[4], int size) {
    const glm::dvec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
    Scene scene = textured_quad_scene(quad(corners, st, map), size);
    scene.mesh.colors = {glm::vec3(1.0f, 0.8f, 0.6f), glm::vec3(0.5f, 1.0f, 0.7f), glm::vec3(0.9f, 0.4f, 1.0f),
                         glm::vec3(0.6f, 0.7f, 0.8f)};
    scene.shader = Shader::gouraud;
    scene.lighting = Lighting::full();
    scene.ambient = glm::vec3(0.2f);
    scene.material = PhongMaterial{glm::vec3(0.3f), glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.5f), 8.0f};
    // Nearly the mirror image of the eye about the normal at corner 2: a highlight there.
    scene.lights = {PointLight{glm::dvec3(0.7, 0.7, 0.6), glm::vec3(1.0f, 0.9f, 0.8f)}};
    return scene;
}

/// A = ka Ia c + Ip kd c max(0, N.L) and S = Ip ks max(0, R.V)^n for the
/// single light of `scene`, with the unit vectors L and V taken at `from`
/// (the point itself in exact mode, its triangle's centroid in seed mode).
void lit_parts(const Scene& scene, const glm::dvec3& from, const glm::dvec3& normal, const glm::dvec3& color,
               glm::dvec3& a, glm::dvec3& s) {
    const PhongMaterial& m = scene.material;
    const glm::dvec3 to_light = glm::normalize(scene.lights[0].position - from);
    const glm::dvec3 to_eye = glm::normalize(scene.camera.eye - from);
    const glm::dvec3 intensity(scene.lights[0].intensity);
    const double n_dot_l = std::max(0.0, glm::dot(normal, to_light));
    a = glm::dvec3(m.ka) * glm::dvec3(scene.ambient) * color + intensity * glm::dvec3(m.kd) * color * n_dot_l;
    const glm::dvec3 reflected = 2.0 * n_dot_l * normal - to_light;
    const double r_dot_v = std::max(0.0, glm::dot(reflected, to_eye));
    s = n_dot_l > 0.0 ? intensity * glm::dvec3(m.ks) * std::pow(r_dot_v, double(m.n)) : glm::dvec3(0.0);
}

/// The largest difference of two pictures over the pixels both paint, and the
/// number of pixels one paints and the other does not (background -1).
double largest_difference(const Image& a, const Image& b, int& painted_apart) {
    double largest = 0.0;
    painted_apart = 0;
    for (std::size_t p = 0; p < a.pixels.size(); ++p) {
        if ((a.pixels[p].x == -1.0f) != (b.pixels[p].x == -1.0f)) ++painted_apart;
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(double(a.pixels[p][c]) - double(b.pixels[p][c])));
    }
    return largest;
}

/// The scene without its texture: no materials, no texture coordinates (a version-1 mesh).
Scene untextured(Scene scene) {
    scene.mesh.materials.clear();
    scene.mesh.face_materials.clear();
    scene.mesh.texcoords.clear();
    scene.mesh.texcoord_triangles.clear();
    return scene;
}

std::shared_ptr<const TextureImage> white_texture() {
    auto image = std::make_shared<TextureImage>();
    image->rows = 2;
    image->columns = 3;
    image->name = "white";
    image->texels.assign(6, glm::vec3(1.0f));
    return image;
}

}  // namespace

TEST_CASE("Gouraud on a textured face: A and S lit at the corners by hand, the pixel T x A + S") {
    const auto image = numbered_texture(3, 4);
    const TextureMap map = map_of(image, TextureWrap::mirrored_repeat, TextureWrap::repeat);
    const glm::vec2 st[4] = {{-0.5f, 0.0f}, {1.5f, 0.0f}, {1.5f, 2.0f}, {-0.5f, 2.0f}};
    const int size = 16;
    const glm::dvec3 normal(0.0, 0.0, 1.0);  // computed from the flat quad's positions
    for (bool seed : {false, true}) {
        Scene scene = lit_gouraud_quad(map, st, size);
        // Seed mode lights at the centroids: the light nearly mirrors the eye about triangle 0's.
        if (seed) scene.lights[0].position = glm::dvec3(0.27, -0.27, 0.6);
        for (Precision precision : {Precision::single_float, Precision::double_float}) {
            RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
            options.precision = precision;
            options.aovs.id = true;
            const RenderResult result = render(scene, options);
            INFO((seed ? "seed" : "exact") << (precision == Precision::double_float ? ", double" : ", float"));
            int wrong = 0, covered = 0;
            double specular_seen = 0.0, colour_range = 0.0;
            for (int i = 0; i < size; ++i) {
                for (int j = 0; j < size; ++j) {
                    const int id = result.aovs.id[std::size_t(i) * size + std::size_t(j)];
                    if (id < 0) continue;
                    ++covered;
                    const Triangle& tri = scene.mesh.triangles[std::size_t(id)];
                    glm::dvec3 p[3], centroid(0.0);
                    for (int k = 0; k < 3; ++k) {
                        p[k] = scene.mesh.positions[tri[k]];
                        centroid += p[k] / 3.0;
                    }
                    // All corners at one depth: perspective-correct and screen-linear weights agree.
                    const double x = (j + 0.5) / size - 0.5, y = 0.5 - (i + 0.5) / size;
                    const auto area = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
                        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                    };
                    const glm::dvec2 c(x, y), a0(p[0]), a1(p[1]), a2(p[2]);
                    const double whole = area(a0, a1, a2);
                    const double w[3] = {area(c, a1, a2) / whole, area(a0, c, a2) / whole, area(a0, a1, c) / whole};
                    glm::dvec3 a_pixel(0.0), s_pixel(0.0);
                    glm::dvec2 st_pixel(0.0);
                    for (int k = 0; k < 3; ++k) {
                        glm::dvec3 a_corner, s_corner;
                        lit_parts(scene, seed ? centroid : p[k], normal, glm::dvec3(scene.mesh.colors[tri[k]]), a_corner,
                                  s_corner);
                        a_pixel += w[k] * a_corner;
                        s_pixel += w[k] * s_corner;
                        st_pixel += w[k] * glm::dvec2(scene.mesh.texcoords[tri[k]]);
                    }
                    const glm::dvec3 expected = sample_bilinear(map, st_pixel.x, st_pixel.y) * a_pixel + s_pixel;
                    specular_seen = std::max(specular_seen, s_pixel.x);
                    colour_range = std::max(colour_range, std::abs(a_pixel.x - a_pixel.y));
                    if (!near(glm::dvec3(result.image.at(i, j)), expected, 2e-5)) {
                        ++wrong;
                        if (wrong < 5) {
                            WARN("pixel " << i << ", " << j << " got " << result.image.at(i, j).x << " "
                                          << result.image.at(i, j).y << " " << result.image.at(i, j).z << " expected "
                                          << expected.x << " " << expected.y << " " << expected.z);
                        }
                    }
                }
            }
            CHECK(covered == size * size);
            CHECK(wrong == 0);
            CHECK(specular_seen > (seed ? 0.02 : 0.1));  // a real highlight
            CHECK(colour_range > 0.05);   // and vertex colours that differ
        }
    }
}

TEST_CASE("textured Gouraud with a white texture is the untextured Gouraud picture, through clipping") {
    // Not bit for bit: the textured picture interpolates A and S apart and adds
    // them after T x A, where the untextured one interpolates their sum lit in
    // one pass, and the bilinear T of four white texels is 1 only up to
    // rounding. The difference is a few roundings of values below 2, and the
    // picture is stored in float: at most 2.5e-7 (2 ulps of 1; measured: one
    // ulp in float renders, none in double ones, whose ~1e-16 rounds away).
    const TextureMap white = map_of(white_texture(), TextureWrap::repeat, TextureWrap::repeat);
    const glm::vec2 st[4] = {{-0.3f, 0.1f}, {1.7f, 0.2f}, {1.4f, 2.1f}, {-0.2f, 1.9f}};
    const int size = 16;
    // 1. The screen-aligned square, whole.
    const Scene square = lit_gouraud_quad(white, st, size);
    // 2. The same far beyond the guard band (2^18 samples): clipped to it in exact mode.
    Scene huge = square;
    for (glm::dvec3& p : huge.mesh.positions) p *= 60000.0;
    // 3. A floor running from in front of the image to behind the eye: clipped at the near plane.
    Scene floor = square;
    floor.mesh.positions = {{-0.6, -0.3, 3.0}, {0.6, -0.3, 3.0}, {0.6, -0.3, -2.0}, {-0.6, -0.3, -2.0}};
    floor.lights = {PointLight{glm::dvec3(0.2, 0.5, -0.5), glm::vec3(1.0f, 0.9f, 0.8f)}};
    struct Case {
        const char* name;
        const Scene* scene;
        bool seed_too;  // seed mode drops what crosses the image border
    };
    for (const Case& c : {Case{"square", &square, true}, Case{"beyond the guard band", &huge, false},
                          Case{"through the near plane", &floor, false}}) {
        const Scene plain = untextured(*c.scene);
        for (bool seed : {false, true}) {
            if (seed && !c.seed_too) continue;
            for (Precision precision : {Precision::single_float, Precision::double_float}) {
                for (TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest, TextureFilter::trilinear}) {
                    RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
                    options.precision = precision;
                    options.texture_filter = filter;
                    const RenderResult textured = render(*c.scene, options);
                    const RenderResult reference = render(plain, options);
                    INFO(c.name << (seed ? ", seed" : ", exact")
                                << (precision == Precision::double_float ? ", double, " : ", float, ") << to_string(filter));
                    if (!seed) CHECK((c.scene == &square) == (textured.stats.triangles_clipped == 0));
                    int painted_apart = 0;
                    const double largest = largest_difference(textured.image, reference.image, painted_apart);
                    CHECK(painted_apart == 0);
                    CHECK(largest <= 2.5e-7);
                    CHECK(textured.stats.samples_shaded > std::uint64_t(size * size / 4));
                }
            }
        }
    }
}

TEST_CASE("textured Gouraud through the near plane: T at the interpolated (s, t) x A + S, A and S as untextured Gouraud interpolates them") {
    const auto image = numbered_texture(4, 3);
    const TextureMap map = map_of(image, TextureWrap::repeat, TextureWrap::mirrored_repeat);
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.5f, 0.0f}, {1.5f, 2.5f}, {0.0f, 2.5f}};
    const int size = 20;
    Scene floor = lit_gouraud_quad(map, st, size);
    floor.mesh.positions = {{-0.6, -0.3, 3.0}, {0.6, -0.3, 3.0}, {0.6, -0.3, -2.0}, {-0.6, -0.3, -2.0}};
    // Beyond the far edge, low: a highlight at its corners (R.V about 0.92 there).
    floor.lights = {PointLight{glm::dvec3(0.0, 0.3, -5.0), glm::vec3(1.0f, 0.9f, 0.8f)}};
    // The untextured floor lit without ks (A) and with only ks (S).
    Scene colour_part = untextured(floor);
    Scene specular_part = colour_part;
    colour_part.material.ks = glm::vec3(0.0f);
    specular_part.material.ka = specular_part.material.kd = glm::vec3(0.0f);
    RenderOptions options = RenderOptions::exact();
    options.aovs.uv = true;
    const RenderResult result = render(floor, options);
    CHECK(result.stats.triangles_clipped == 2);
    const Image a = render(colour_part, RenderOptions::exact()).image;
    const Image s_part = render(specular_part, RenderOptions::exact()).image;
    int wrong = 0, covered = 0;
    double specular_seen = 0.0;
    for (int i = 0; i < size; ++i) {
        for (int j = 0; j < size; ++j) {
            if (a.at(i, j).x == -1.0f) continue;
            ++covered;
            const glm::vec2 uv = result.aovs.uv[std::size_t(i) * size + std::size_t(j)];
            const glm::dvec3 expected =
                sample_bilinear(map, uv.x, uv.y) * glm::dvec3(a.at(i, j)) + glm::dvec3(s_part.at(i, j));
            specular_seen = std::max(specular_seen, double(s_part.at(i, j).x));
            if (!near(glm::dvec3(result.image.at(i, j)), expected, 1e-4)) ++wrong;
        }
    }
    CHECK(covered > size * size / 4);
    CHECK(wrong == 0);
    CHECK(specular_seen > 0.01);
}

TEST_CASE("textured Gouraud: a face without texture coordinates keeps the untextured picture, its neighbour is textured") {
    const TextureMap map = map_of(numbered_texture(3, 3), TextureWrap::repeat, TextureWrap::repeat);
    const glm::vec2 st[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    const int size = 12;
    Scene scene = lit_gouraud_quad(map, st, size);
    scene.mesh.texcoord_triangles[1][2] = kNoIndex;  // triangle 1 (upper left) draws with T = 1
    const Scene plain = untextured(scene);
    for (bool seed : {false, true}) {
        RenderOptions options = seed ? RenderOptions::seed() : RenderOptions::exact();
        options.aovs.id = true;
        const RenderResult result = render(scene, options);
        const Image reference = render(plain, options).image;
        INFO((seed ? "seed" : "exact"));
        int untextured_pixels = 0, textured_apart = 0;
        double largest = 0.0;
        for (std::size_t p = 0; p < result.image.pixels.size(); ++p) {
            const glm::dvec3 difference = glm::abs(glm::dvec3(result.image.pixels[p]) - glm::dvec3(reference.pixels[p]));
            const double most = std::max(difference.x, std::max(difference.y, difference.z));
            if (result.aovs.id[p] == 1) {
                ++untextured_pixels;
                largest = std::max(largest, most);
            } else if (most > 0.01) {
                ++textured_apart;
            }
        }
        CHECK(untextured_pixels > size * size / 3);
        // The same lighting at the same corners: the untextured picture, up to float rounding (see above).
        CHECK(largest <= 2.5e-7);
        CHECK(textured_apart > size * size / 3);
    }
}
