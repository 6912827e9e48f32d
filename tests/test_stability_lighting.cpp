// Hard lighting: cancelling and vanishing normals, lights at the shaded
// point, on the surface and at the eye, the eye on the surface, grazing light,
// R.V above 1 through rounding, and the exponents n = 0 and n = 1e4. Each test
// name states the expected outcome.
#include <random>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "phongrast/lighting.hpp"
#include "test_meshes.hpp"
#include "test_stability_common.hpp"

using namespace phongrast;
using stability::add_triangle;
using stability::at_pixel;
using stability::max_channel_difference;

namespace {

constexpr double kDepth = 8.0;

/// pixel_exact_scene with every term on, a grey surface and one white light
/// in front of the plane z = -8 (between it and the eye).
Scene lit_scene(Shader shader) {
    Scene scene = stability::pixel_exact_scene();
    scene.shader = shader;
    scene.lighting = Lighting::full();
    scene.material = PhongMaterial{};  // ka 0.1, kd 0.8, ks 1, n 1
    scene.material.n = 8;
    scene.ambient = glm::vec3(0.5f);
    scene.lights = {{{1.0, 2.0, -3.0}, {1, 1, 1}}};
    return scene;
}

/// A square of two triangles covering pixels 8..55 at depth 8, counter-clockwise
/// seen from the eye (its right-hand normal, +z, faces the eye).
void add_front_square(Mesh& mesh, const Scene& scene) {
    const auto base = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back(at_pixel(scene, 8, 56, kDepth));   // bottom left
    mesh.positions.push_back(at_pixel(scene, 56, 56, kDepth));  // bottom right
    mesh.positions.push_back(at_pixel(scene, 56, 8, kDepth));   // top right
    mesh.positions.push_back(at_pixel(scene, 8, 8, kDepth));    // top left
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
}

glm::vec3 ambient_of(const Scene& scene) { return scene.material.ka * scene.ambient; }  // white surface

}  // namespace

TEST_CASE("two-sided sheet: cancelling vertex normals fall back to a face normal, lit as the one-sided sheet") {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        Scene one_sided = lit_scene(shader);
        add_front_square(one_sided.mesh, one_sided);
        Scene two_sided = one_sided;
        // The same square again with the opposite winding: every vertex normal sums to zero.
        two_sided.mesh.triangles.push_back({0, 2, 1});
        two_sided.mesh.triangles.push_back({0, 3, 2});
        const std::vector<glm::vec3> normals = calculate_normals(two_sided.mesh);
        for (const glm::vec3& n : normals) CHECK(n == glm::vec3(0, 0, 1));  // the first largest face: the front one
        const RenderResult front = render(one_sided), both = render(two_sided);
        INFO(to_string(shader));
        STABILITY_CHECK_FINITE(both);
        CHECK(both.stats.samples_covered == 2 * front.stats.samples_covered);  // the back faces paint over
        // ... and only they are shaded where per-pixel lighting makes that pay (Overdraw::automatic).
        CHECK(both.stats.samples_shaded == (shader == Shader::phong ? 1 : 2) * front.stats.samples_shaded);
        float worst = 0.0f;
        for (std::size_t i = 0; i < front.image.pixels.size(); ++i) {
            worst = std::max(worst, max_channel_difference(front.image.pixels[i], both.image.pixels[i]));
        }
        CHECK(worst <= 1e-6f);  // the same picture up to the order of float additions
        CHECK(front.image.at(32, 32).x > ambient_of(one_sided).x + 0.1f);  // lit, not black
    }
}

TEST_CASE("a vertex shared by opposite faces takes the larger face's normal, the normal passing through zero gives no NaN") {
    // Triangle A faces the eye; triangle B, twice as large, faces away; they share vertex 0.
    Scene scene = lit_scene(Shader::phong);
    Mesh& mesh = scene.mesh;
    mesh.positions = {at_pixel(scene, 32, 32, kDepth), at_pixel(scene, 8, 40, kDepth), at_pixel(scene, 8, 24, kDepth),
                      at_pixel(scene, 56, 8, kDepth), at_pixel(scene, 56, 56, kDepth)};
    // A = 0, 2, 1 has the right-hand normal +z (towards the eye and the light); B = 0, 3, 4 has -z.
    mesh.triangles = {{0, 2, 1}, {0, 3, 4}};
    const std::vector<glm::vec3> normals = calculate_normals(mesh);
    CHECK(normals[0] == glm::vec3(0, 0, -1));  // B's
    CHECK(normals[1] == glm::vec3(0, 0, 1));
    for (const RenderOptions& options : {RenderOptions::seed(), RenderOptions::exact()}) {
        const RenderResult result = render(scene, options);
        STABILITY_CHECK_FINITE(result);
        // Inside A the interpolated normal turns from +z (left) through zero to -z
        // (towards vertex 0): lit on the left, ambient only next to vertex 0.
        CHECK(result.image.at(32, 10).x > ambient_of(scene).x + 0.1f);
        CHECK(result.image.at(32, 28) == ambient_of(scene));
        // B faces away from the light entirely: ambient only.
        CHECK(result.image.at(32, 50) == ambient_of(scene));
    }
}

TEST_CASE("opposite vertex normals: the interpolated normal passes through zero, each pixel is lit or ambient, never NaN") {
    Scene scene = lit_scene(Shader::phong);
    scene.lighting = parse_lighting("ambient+diffuse");
    add_triangle(scene.mesh, at_pixel(scene, 4, 60, kDepth), at_pixel(scene, 60, 60, kDepth),
                 at_pixel(scene, 32, 4, kDepth));
    scene.mesh.normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}};
    // Seed light vectors: L is the same for every pixel, so a pixel is exactly one of two colours.
    const RenderResult result = render(scene, RenderOptions::seed());
    STABILITY_CHECK_FINITE(result);
    const glm::vec3 ambient = ambient_of(scene);
    int lit = 0, dark = 0, other = 0;
    glm::vec3 lit_colour(-1.0f);
    for (const glm::vec3& p : result.image.pixels) {
        if (p == stability::kBackground) continue;
        if (p == ambient) {
            ++dark;
        } else if (lit_colour == glm::vec3(-1.0f) || p == lit_colour) {
            lit_colour = p;
            ++lit;
        } else {
            ++other;
        }
    }
    CHECK(lit > 100);
    CHECK(dark > 100);
    CHECK(other == 0);
    CHECK(lit_colour.x > ambient.x);
    // And exactly at zero the formula takes the zero normal: ambient only.
    const std::vector<PointLight> lights = scene.lights;
    CHECK(light(glm::vec3(0, 0, -8), glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(0.0f), scene.material, lights,
                scene.ambient, Lighting::full()) == ambient);
}

TEST_CASE("a light exactly at the shaded point contributes nothing: flat centroid and Gouraud vertex are ambient only") {
    // Flat lights the triangle at its centroid; put the light exactly there
    // (the centroid (0, 0, -8) is exact in float and double).
    Scene scene = lit_scene(Shader::flat);
    add_triangle(scene.mesh, {-3, -3, -8}, {6, -3, -8}, {-3, 6, -8});
    scene.lights = {{{0, 0, -8}, {1, 1, 1}}};
    for (Precision precision : {Precision::single_float, Precision::double_float}) {
        RenderOptions options = RenderOptions::exact();
        options.precision = precision;
        const RenderResult result = render(scene, options);
        STABILITY_CHECK_FINITE(result);
        CHECK(result.image.at(32, 32) == ambient_of(scene));
    }
    // Gouraud lights each vertex: a light exactly at vertex 0 leaves it ambient-only,
    // and the pixel centred on that vertex shows exactly that.
    Scene gouraud = lit_scene(Shader::gouraud);
    add_triangle(gouraud.mesh, at_pixel(gouraud, 20.5, 20.5, kDepth), at_pixel(gouraud, 50.5, 20.5, kDepth),
                 at_pixel(gouraud, 20.5, 50.5, kDepth));
    gouraud.lights = {{gouraud.mesh.positions[0], {1, 1, 1}}};
    // The light lies in the plane, so tilt the normals towards it: N.L > 0 at the other two vertices.
    const glm::vec3 tilted = glm::normalize(glm::vec3(-0.3f, 0.3f, 1.0f));
    gouraud.mesh.normals = {tilted, tilted, tilted};
    const RenderResult result = render(gouraud, RenderOptions::exact());
    STABILITY_CHECK_FINITE(result);
    const glm::vec3 at_vertex = result.image.at(20, 20);
    CHECK(at_vertex.x == Approx(ambient_of(gouraud).x).margin(1e-6));
    CHECK(result.image.at(25, 30).x > ambient_of(gouraud).x + 0.1f);  // lit away from the light
}

TEST_CASE("Phong with a light on a pixel of the surface: finite and bounded around the light") {
    // Per pixel, the interpolated point and the light differ only by rounding
    // there, so L's direction is arbitrary: the pixel may be anything from
    // ambient to fully lit, but never NaN nor beyond ambient + diffuse + specular.
    Scene scene = lit_scene(Shader::phong);
    add_front_square(scene.mesh, scene);
    scene.lights = {{at_pixel(scene, 32.5, 32.5, kDepth), {1, 1, 1}}};
    for (Precision precision : {Precision::single_float, Precision::double_float}) {
        RenderOptions options = RenderOptions::exact();
        options.precision = precision;
        const RenderResult result = render(scene, options);
        STABILITY_CHECK_FINITE(result);
        const float bound = ambient_of(scene).x + scene.material.kd.x + scene.material.ks.x + 1e-5f;
        for (const glm::vec3& p : result.image.pixels) {
            if (p == stability::kBackground) continue;
            CHECK(p.x >= ambient_of(scene).x - 1e-6f);
            CHECK(p.x <= bound);
        }
    }
}

TEST_CASE("a light in the plane of the surface gives ambient only (N.L = 0): no speckle from rounding") {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const RenderOptions& preset : {RenderOptions::seed(), RenderOptions::exact()}) {
            for (Precision precision : {Precision::single_float, Precision::double_float}) {
                Scene scene = lit_scene(shader);
                add_front_square(scene.mesh, scene);
                scene.lights = {{{5.3, -11.7, -kDepth}, {1, 1, 1}}};  // on the plane z = -8, outside the square
                RenderOptions options = preset;
                options.precision = precision;
                const RenderResult result = render(scene, options);
                INFO(to_string(shader) << (preset.interpolation == Interpolation::screen_affine ? " seed" : " exact")
                                       << (precision == Precision::double_float ? " double" : " float"));
                STABILITY_CHECK_FINITE(result);
                int not_ambient = 0;
                float worst = 0.0f;
                for (const glm::vec3& p : result.image.pixels) {
                    if (p == stability::kBackground) continue;
                    const float d = max_channel_difference(p, ambient_of(scene));
                    not_ambient += d > 1e-5f;
                    worst = std::max(worst, d);
                }
                INFO("largest difference from ambient " << worst);
                CHECK(not_ambient == 0);
            }
        }
    }
}

TEST_CASE("a light at the eye: L = V, brightest where the surface faces the eye, finite") {
    for (Shader shader : {Shader::gouraud, Shader::phong}) {
        Scene scene = lit_scene(shader);
        add_front_square(scene.mesh, scene);
        scene.lights = {{scene.camera.eye, {1, 1, 1}}};
        const RenderResult result = render(scene);
        INFO(to_string(shader));
        STABILITY_CHECK_FINITE(result);
        if (shader == Shader::phong) {
            // At the image centre N = L = V: N.L = 1, R = V, R.V = 1, so I = ka Ia + kd + ks
            // (the pixel centre is 0.7 px off the axis: within 5e-3).
            const float expected = ambient_of(scene).x + scene.material.kd.x + scene.material.ks.x;
            CHECK(result.image.at(32, 32).x == Approx(expected).margin(5e-3));
            CHECK(result.image.at(10, 10).x < result.image.at(32, 32).x - 0.1f);
        } else {
            // Gouraud: the four corners are lit alike, so the square is the corner's colour.
            const glm::vec3 corner = light(glm::vec3(at_pixel(scene, 8, 8, kDepth)), glm::vec3(0, 0, 1), glm::vec3(1.0f),
                                           glm::vec3(0.0f), scene.material, scene.lights, scene.ambient, Lighting::full());
            CHECK(result.image.at(32, 32).x == Approx(corner.x).margin(1e-5));
        }
    }
}

TEST_CASE("the eye on the surface (on a vertex of a sphere): finite, triangles through the eye are edge-on") {
    Scene scene = lit_scene(Shader::gouraud);
    scene.mesh = test_meshes::uv_sphere(12, 24, 1.0);
    scene.camera.eye = scene.mesh.positions[30];  // a vertex on the surface
    scene.camera.lookat = {0, 0, 0};
    scene.camera.up = {0.3, 0.1, 1};
    scene.lights = {{{0.5, 0.2, 0.1}, {1, 1, 1}}};  // inside the sphere, lighting what the eye sees
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        scene.shader = shader;
        INFO(to_string(shader));
        const RenderResult seed = render(scene, RenderOptions::seed());
        STABILITY_CHECK_FINITE(seed);
        CHECK(seed.stats.triangles_dropped > 0);  // those touching the eye have z_c = 0
        const RenderResult exact = render(scene, RenderOptions::exact());
        STABILITY_CHECK_FINITE(exact);
        CHECK(exact.stats.triangles_drawn > 100);
        CHECK(stability::count_not(exact.image) == std::uint64_t(64 * 64));  // inside the sphere: all surface
    }
}

TEST_CASE("grazing light: double follows the contract at N.L = +1e-7 (tiny diffuse, specular on), float treats it as 0, -1e-7 gives nothing") {
    // N.L within grazing_threshold() (64 epsilons: 7.6e-6 in float, 1.4e-14 in
    // double) of zero counts as zero: in float, 1e-7 is within rounding of zero.
    PhongMaterial material;
    material.n = 1;
    const auto check = [&](auto real_tag) {
        using Real = decltype(real_tag);
        const Vec3<Real> normal(0, 0, 1), color(1), intensity(1);
        const Real tilt = Real(1e-7);
        const bool resolved = tilt > grazing_threshold<Real>();
        for (Real sign : {Real(1), Real(-1)}) {
            // A unit L at N.L = sign * 1e-7, and the eye along its mirror direction.
            const Vec3<Real> to_light(std::sqrt(Real(1) - tilt * tilt), Real(0), sign * tilt);
            const Vec3<Real> to_eye(-to_light.x, Real(0), to_light.z);
            const Vec3<Real> diffuse = diffuse_from_direction<Real>(normal, color, to_light, material, intensity);
            const Vec3<Real> specular = specular_from_direction<Real>(normal, to_light, to_eye, material, intensity);
            INFO("sign " << sign << ", " << sizeof(Real) * 8 << "-bit");
            CHECK(std::isfinite(diffuse.x));
            CHECK(std::isfinite(specular.x));
            if (sign > 0 && resolved) {
                CHECK(double(diffuse.x) == Approx(0.8e-7).epsilon(1e-6));
                CHECK(double(specular.x) == Approx(1.0).epsilon(1e-12));
            } else {
                CHECK(diffuse == Vec3<Real>(0));
                CHECK(specular == Vec3<Real>(0));
            }
        }
        return resolved;
    };
    CHECK_FALSE(check(float{}));
    CHECK(check(double{}));
}

TEST_CASE("R.V above 1 through rounding is clamped: the highlight never exceeds ks * Ip, even for n = 1e4") {
    // Find unit vectors in float where the computed R.V exceeds 1 (V = R, renormalised).
    std::mt19937 rng(3);
    std::normal_distribution<float> gaussian;
    PhongMaterial material;
    material.n = 1e4f;
    int found = 0;
    for (int trial = 0; trial < 20000 && found < 50; ++trial) {
        const glm::vec3 normal = glm::normalize(glm::vec3(gaussian(rng), gaussian(rng), gaussian(rng)));
        glm::vec3 to_light = glm::normalize(glm::vec3(gaussian(rng), gaussian(rng), gaussian(rng)));
        if (glm::dot(normal, to_light) <= 0.0f) to_light = -to_light;
        const glm::vec3 reflected = 2.0f * normal * glm::dot(normal, to_light) - to_light;
        const glm::vec3 to_eye = glm::normalize(reflected);
        if (!(glm::dot(reflected, to_eye) > 1.0f)) continue;
        ++found;
        const glm::vec3 s = specular_from_direction<float>(normal, to_light, to_eye, material, glm::vec3(1.0f));
        CHECK(s == glm::vec3(1.0f));  // clamped to R.V = 1, and 1^n = 1
    }
    CHECK(found == 50);  // rounding does push R.V above 1 this often
}

TEST_CASE("n = 0: the specular term is exactly ks * Ip wherever N.L > 0, and 0 where N.L <= 0") {
    for (double light_z : {-2.0, -20.0}) {  // in front of the plane, then behind it
        Scene scene = lit_scene(Shader::phong);
        scene.lighting = Lighting::only_specular();
        scene.material.n = 0;
        scene.material.ks = glm::vec3(0.7f);
        scene.lights = {{{0.3, 0.1, light_z}, {1, 1, 1}}};
        add_front_square(scene.mesh, scene);
        const RenderResult result = render(scene);
        STABILITY_CHECK_FINITE(result);
        const glm::vec3 expected = light_z > -kDepth ? glm::vec3(0.7f) : glm::vec3(0.0f);
        int wrong = 0;
        for (const glm::vec3& p : result.image.pixels) wrong += p != stability::kBackground && p != expected;
        INFO("light at z = " << light_z);
        CHECK(wrong == 0);
    }
}

TEST_CASE("n = 1e4: a needle-sharp highlight, finite, bounded, float within n * 1e-6 of double") {
    Scene scene = lit_scene(Shader::phong);
    scene.mesh = test_meshes::uv_sphere(24, 48, 1.0);
    scene.camera.eye = {0, 0, 4};
    scene.camera.lookat = {0, 0, 0};
    scene.camera.focal = 2;
    scene.lights = {{{0, 0, 4}, {1, 1, 1}}};  // at the eye: the highlight faces us at the centre
    scene.material.n = 1e4f;
    scene.image.rows = scene.image.columns = 65;  // the centre pixel looks exactly along the axis
    RenderOptions options = RenderOptions::exact();
    const RenderResult single = render(scene, options);
    options.precision = Precision::double_float;
    const RenderResult twice = render(scene, options);
    STABILITY_CHECK_FINITE(single);
    STABILITY_CHECK_FINITE(twice);
    const float bound = ambient_of(scene).x + scene.material.kd.x + scene.material.ks.x;
    float brightest = 0.0f, worst = 0.0f;
    for (std::size_t i = 0; i < single.image.pixels.size(); ++i) {
        brightest = std::max(brightest, single.image.pixels[i].x);
        worst = std::max(worst, max_channel_difference(single.image.pixels[i], twice.image.pixels[i]));
    }
    CHECK(brightest <= bound + 1e-5f);
    CHECK(brightest > ambient_of(scene).x + scene.material.kd.x + 0.1f);  // the highlight is there
    // (R.V)^n amplifies R.V's float rounding (a few 1e-8) n times: 1e4 * 1e-6 = 1e-2 is generous.
    CHECK(worst <= 1e-2f);
}
