// What test_effects.cpp leaves open: more configurations
// where a specialised kernel must match the general one bit for bit, term
// counts for every zero that should cost nothing (kd, ka, Ia, dark lights) in
// every shader, the triangle accounting of RenderStats, and back-face culling
// detection on meshes that look closed but must not be culled.
#include <algorithm>
#include <iterator>
#include <string>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

Scene coloured_sphere_scene() {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(12, 24, 1.0);
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.7f));
    }
    scene.camera.eye = {0.3, 0.6, 4};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.4;
    scene.image = {40, 40, {0, 0, 0}};
    scene.material.n = 7;
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}, {{-3, 1, 2}, {0.5f, 0.4f, 0.3f}}};
    return scene;
}

RenderResult render_kernel(const Scene& scene, RenderOptions options, bool specialized) {
    options.specialize_effects = specialized;
    return render(scene, options);
}

// Every way a triangle can leave setup is counted exactly once.
std::uint64_t accounted(const RenderStats& s) {
    return s.triangles_culled + s.triangles_degenerate + s.triangles_dropped + s.triangles_outside +
           s.triangles_out_of_range + s.triangles_between_samples + s.triangles_drawn;
}

// The mesh's triangles that face away from the eye, by the right-hand rule
// (counter-clockwise seen from outside), computed here independently.
std::uint64_t count_back_faces(const Mesh& mesh, const glm::dvec3& eye) {
    std::uint64_t back = 0;
    for (const Triangle& t : mesh.triangles) {
        const glm::dvec3& a = mesh.positions[t[0]];
        const glm::dvec3 normal = glm::cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
        back += glm::dot(normal, eye - a) < 0.0;
    }
    return back;
}

// Appends `part` to `mesh`, moved by `offset`, with its winding reversed when `flip`.
void append(Mesh& mesh, const Mesh& part, const glm::dvec3& offset, bool flip) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (const glm::dvec3& p : part.positions) mesh.positions.push_back(p + offset);
    for (Triangle t : part.triangles) {
        if (flip) std::swap(t[1], t[2]);
        mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
}

// Pixels that culling changed, and how many of them agree with the depth buffer.
struct CullingChange {
    int changed = 0;
    int agree_with_depth = 0;
};
CullingChange compare_culling(const Scene& scene, const RenderOptions& painter) {
    RenderOptions culled = painter;
    culled.back_faces = BackFaces::cull_when_hidden;
    RenderOptions depth = painter;
    depth.visibility = Visibility::depth_buffer;
    const Image a = render(scene, painter).image;
    const Image b = render(scene, culled).image;
    const Image z = render(scene, depth).image;
    CullingChange result;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (a.pixels[i] == b.pixels[i]) continue;
        ++result.changed;
        const glm::vec3 d = glm::abs(b.pixels[i] - z.pixels[i]);
        result.agree_with_depth += std::max(d.x, std::max(d.y, d.z)) < 1e-5f;
    }
    return result;
}

}  // namespace

TEST_CASE("specialised kernels match the general kernel for zero coefficients and other options") {
    const Scene base = coloured_sphere_scene();
    struct Variant {
        const char* name;
        void (*apply)(Scene&);
    };
    const Variant variants[] = {
        {"kd = 0", [](Scene& s) { s.material.kd = glm::vec3(0.0f); }},
        {"ka = 0", [](Scene& s) { s.material.ka = glm::vec3(0.0f); }},
        {"Ia = 0", [](Scene& s) { s.ambient = glm::vec3(0.0f); }},
        {"every light dark", [](Scene& s) { for (PointLight& l : s.lights) l.intensity = glm::vec3(0.0f); }},
        {"no lights", [](Scene& s) { s.lights.clear(); }},
        {"no colours (white)", [](Scene& s) { s.mesh.colors.clear(); }},
        {"n = 0", [](Scene& s) { s.material.n = 0.0f; }},
        {"one channel of ks", [](Scene& s) { s.material.ks = glm::vec3(0.0f, 0.7f, 0.0f); }},
    };
    RenderOptions depth = RenderOptions::exact();
    depth.visibility = Visibility::depth_buffer;
    RenderOptions twice = RenderOptions::seed();
    twice.precision = Precision::double_float;
    twice.samples_per_axis = 2;
    const RenderOptions option_sets[] = {RenderOptions::seed(), RenderOptions::exact(), depth, twice};
    int compared = 0;
    for (const Variant& variant : variants) {
        for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
            for (const char* lighting : {"ambient", "full", "diffuse+specular"}) {
                Scene scene = base;
                variant.apply(scene);
                scene.shader = shader;
                scene.lighting = parse_lighting(lighting);
                for (std::size_t o = 0; o < std::size(option_sets); ++o) {
                    INFO(variant.name << ", " << to_string(shader) << ", " << lighting << ", options " << o);
                    const RenderResult general = render_kernel(scene, option_sets[o], false);
                    const RenderResult special = render_kernel(scene, option_sets[o], true);
                    CHECK(special.image.pixels == general.image.pixels);
                    CHECK(special.stats.samples_shaded == general.stats.samples_shaded);
                    ++compared;
                }
            }
        }
    }
    CHECK(compared == 8 * 3 * 3 * 4);
}

TEST_CASE("the effect set records what the scene makes non-zero") {
    Scene scene = coloured_sphere_scene();
    scene.lighting = Lighting::full();
    EffectSet e = render(scene).stats.effects;
    CHECK(e.ambient);
    CHECK(e.diffuse);
    CHECK(e.specular);
    CHECK(e.normals);
    CHECK(e.varying_colors);
    CHECK(e.active_lights == 2);
    CHECK(to_string(e) == "ambient+diffuse+specular, varying colours, 2 active light(s)");

    scene.mesh.colors.assign(scene.mesh.positions.size(), glm::vec3(0.2f, 0.4f, 0.6f));
    CHECK_FALSE(render(scene).stats.effects.varying_colors);
    // -0 equals +0 as a value but not as bits: painting every vertex with the
    // first one's colour would flip the sign of a zero channel.
    scene.mesh.colors.assign(scene.mesh.positions.size(), glm::vec3(0.0f, 0.4f, 0.6f));
    scene.mesh.colors[5].x = -0.0f;
    CHECK(render(scene).stats.effects.varying_colors);
    scene.mesh.colors.clear();
    CHECK_FALSE(render(scene).stats.effects.varying_colors);

    scene.ambient = glm::vec3(0.0f);
    scene.material.kd = glm::vec3(0.0f);
    e = render(scene).stats.effects;
    CHECK_FALSE(e.ambient);
    CHECK_FALSE(e.diffuse);
    CHECK(e.specular);
    CHECK(e.normals);

    scene.lighting = Lighting::only_ambient();
    scene.ambient = glm::vec3(0.5f);
    e = render(scene).stats.effects;
    CHECK(e.ambient);
    CHECK_FALSE(e.normals);
    CHECK(to_string(e) == "ambient, uniform colour, 2 active light(s)");

    scene.lighting = parse_lighting("diffuse+specular");
    for (PointLight& light : scene.lights) light.intensity = glm::vec3(0.0f);
    e = render(scene).stats.effects;
    CHECK(to_string(e) == "none, uniform colour, 0 active light(s)");
    CHECK_FALSE(e.normals);
}

TEST_CASE("every zero that makes a term vanish also removes its evaluations, in every shader") {
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const RenderOptions& options : {RenderOptions::seed(), RenderOptions::exact()}) {
            INFO(to_string(shader) << (options.border == BorderPolicy::clip ? " exact" : " seed"));
            Scene scene = coloured_sphere_scene();
            scene.shader = shader;

            Scene matte = scene;
            matte.material.kd = glm::vec3(0.0f);
            const RenderStats no_diffuse = render(matte, options).stats;
            CHECK(no_diffuse.diffuse_evaluations == 0);
            CHECK(no_diffuse.specular_evaluations > 0);

            Scene no_ka = scene;
            no_ka.material.ka = glm::vec3(0.0f);
            CHECK(render(no_ka, options).stats.ambient_evaluations == 0);
            Scene no_ia = scene;
            no_ia.ambient = glm::vec3(0.0f);
            CHECK(render(no_ia, options).stats.ambient_evaluations == 0);

            // A dark light costs nothing: the counts equal those without it.
            Scene dark = scene;
            dark.lights.push_back({{0, -4, 2}, glm::vec3(0.0f)});
            const RenderStats with_dark = render(dark, options).stats;
            const RenderStats without = render(scene, options).stats;
            CHECK(with_dark.effects.active_lights == 2);
            CHECK(with_dark.diffuse_evaluations == without.diffuse_evaluations);
            CHECK(with_dark.specular_evaluations == without.specular_evaluations);
            CHECK(with_dark.ambient_evaluations == without.ambient_evaluations);

            // Everything dark and no ambient: nothing at all is evaluated.
            Scene black = dark;
            black.ambient = glm::vec3(0.0f);
            for (PointLight& light : black.lights) light.intensity = glm::vec3(0.0f);
            const RenderStats none = render(black, options).stats;
            CHECK(none.samples_shaded > 0);
            CHECK(none.ambient_evaluations + none.diffuse_evaluations + none.specular_evaluations == 0);
            CHECK(none.normal_interpolations == 0);
        }
    }
}

TEST_CASE("Phong term counts are one per sample per active light, the general kernel counts every light") {
    Scene scene = coloured_sphere_scene();
    scene.shader = Shader::phong;
    scene.lights.push_back({{0, -4, 2}, glm::vec3(0.0f)});  // dark: 2 active of 3
    const RenderStats special = render(scene).stats;
    REQUIRE(special.samples_shaded > 300);
    CHECK(special.ambient_evaluations == special.samples_shaded);
    CHECK(special.diffuse_evaluations == special.samples_shaded * 2);
    CHECK(special.specular_evaluations == special.samples_shaded * 2);
    CHECK(special.normal_interpolations == special.samples_shaded);

    RenderOptions general_options = RenderOptions::exact();
    general_options.specialize_effects = false;
    const RenderStats general = render(scene, general_options).stats;
    CHECK(general.samples_shaded == special.samples_shaded);
    CHECK(general.diffuse_evaluations == general.samples_shaded * 3);
    CHECK(general.specular_evaluations == general.samples_shaded * 3);
}

TEST_CASE("every triangle is accounted for exactly once, with and without culling") {
    Scene scene = coloured_sphere_scene();
    scene.camera.sensor_height = scene.camera.sensor_width = 0.8;  // the sphere crosses the border
    for (RenderOptions options : {RenderOptions::seed(), RenderOptions::exact()}) {
        for (BackFaces back : {BackFaces::draw, BackFaces::cull_when_hidden}) {
            options.back_faces = back;
            const RenderStats s = render(scene, options).stats;
            INFO("border " << (options.border == BorderPolicy::clip ? "clip" : "drop") << ", culling "
                           << (back == BackFaces::cull_when_hidden));
            CHECK(s.triangles_in == scene.mesh.triangles.size());
            CHECK(accounted(s) == s.triangles_in);
            if (options.border == BorderPolicy::clip) {
                CHECK(s.triangles_clipped > 0);
                CHECK(s.triangles_dropped == 0);
            } else {
                CHECK(s.triangles_dropped > 0);
                CHECK(s.triangles_clipped == 0);
            }
            // The seed's rule drops front faces that cross the border, which would
            // uncover back faces: culling is then switched off.
            const bool culls = back == BackFaces::cull_when_hidden && options.border == BorderPolicy::clip;
            CHECK(s.back_faces_culled == culls);
            CHECK(s.triangles_culled == (culls ? count_back_faces(scene.mesh, scene.camera.eye) : 0));
        }
    }
}

TEST_CASE("culling skips exactly the back faces, and the picture does not depend on threads") {
    Scene scene = coloured_sphere_scene();
    RenderOptions cull = RenderOptions::exact();
    cull.back_faces = BackFaces::cull_when_hidden;
    cull.threads = 1;
    const RenderResult one = render(scene, cull);
    REQUIRE(one.stats.back_faces_culled);
    CHECK(one.stats.triangles_culled == count_back_faces(scene.mesh, scene.camera.eye));
    cull.threads = 2;
    const RenderResult two = render(scene, cull);
    CHECK(two.stats.triangles_culled == one.stats.triangles_culled);
    CHECK(two.image.pixels == one.image.pixels);
}

TEST_CASE("meshes that are not a consistently oriented closed surface are never culled") {
    RenderOptions cull = RenderOptions::exact();
    cull.back_faces = BackFaces::cull_when_hidden;
    Scene scene = coloured_sphere_scene();
    scene.mesh.colors.clear();

    SECTION("one face flipped: closed, but not consistently oriented") {
        std::swap(scene.mesh.triangles[10][1], scene.mesh.triangles[10][2]);
        const RenderStats s = render(scene, cull).stats;
        CHECK_FALSE(s.back_faces_culled);
        CHECK(s.triangles_culled == 0);
    }
    SECTION("a face duplicated: every edge is used three times") {
        scene.mesh.triangles.push_back(scene.mesh.triangles[5]);
        CHECK_FALSE(render(scene, cull).stats.back_faces_culled);
    }
    SECTION("the eye exactly on the surface") {
        scene.camera.eye = scene.mesh.positions[7];
        scene.camera.lookat = {0, 0, 0};
        CHECK_FALSE(render(scene, cull).stats.back_faces_culled);
    }
}

// A two-sided sheet (every triangle also listed with the opposite winding)
// matches every edge and encloses no volume; rounding leaves ~1e-17 of it, so
// the volume test must have a tolerance relative to the terms it sums, or one
// side would be culled (and flat pixels would then change).
TEST_CASE("a two-sided sheet encloses nothing and is never culled") {
    RenderOptions cull = RenderOptions::exact();
    cull.back_faces = BackFaces::cull_when_hidden;
    Scene scene = coloured_sphere_scene();
    Mesh sheet;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) sheet.positions.push_back({0.3 * i - 0.75, 0.3 * j - 0.75, 0.05 * i * j});
    }
    for (std::uint32_t i = 0; i < 5; ++i) {
        for (std::uint32_t j = 0; j < 5; ++j) {
            const std::uint32_t a = i * 6 + j, b = a + 6, c = a + 7, d = a + 1;
            sheet.triangles.push_back({a, b, c});
            sheet.triangles.push_back({a, c, d});
        }
    }
    const std::size_t front = sheet.triangles.size();
    for (std::size_t t = 0; t < front; ++t) {
        sheet.triangles.push_back({sheet.triangles[t][0], sheet.triangles[t][2], sheet.triangles[t][1]});
    }
    scene.mesh = sheet;
    const RenderStats s = render(scene, cull).stats;
    CHECK_FALSE(s.back_faces_culled);
    CHECK(s.triangles_culled == 0);
}

TEST_CASE("two closed parts with the same orientation are culled, the changed pixels follow the depth buffer") {
    const Mesh ball = test_meshes::uv_sphere(12, 24, 0.5);
    Scene scene = coloured_sphere_scene();
    scene.mesh = Mesh{};
    append(scene.mesh, ball, {-0.35, 0, 0}, false);
    append(scene.mesh, ball, {0.35, 0, -0.6}, false);  // overlaps the first in the picture
    scene.shader = Shader::phong;
    const RenderStats s = [&] {
        RenderOptions cull = RenderOptions::exact();
        cull.back_faces = BackFaces::cull_when_hidden;
        return render(scene, cull).stats;
    }();
    REQUIRE(s.back_faces_culled);
    CHECK(s.triangles_culled == count_back_faces(scene.mesh, scene.camera.eye));
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        scene.shader = shader;
        const CullingChange change = compare_culling(scene, RenderOptions::exact());
        INFO(to_string(shader) << ": " << change.changed << " pixels changed by culling");
        CHECK(change.agree_with_depth == change.changed);
    }
}

// Two disjoint closed parts wound in opposite directions match every edge,
// give the eye a total winding number of 0 and a total volume of one sign;
// only a per-part orientation check keeps the smaller part from being culled
// on the wrong side.
TEST_CASE("two closed parts wound in opposite directions are not culled on the wrong side") {
    const Mesh ball = test_meshes::uv_sphere(12, 24, 0.5);
    Scene scene = coloured_sphere_scene();
    scene.mesh = Mesh{};
    append(scene.mesh, test_meshes::uv_sphere(12, 24, 0.6), {-0.4, 0, 0}, false);
    append(scene.mesh, ball, {0.5, 0, 0}, true);  // smaller, and inward-oriented
    scene.shader = Shader::phong;
    const CullingChange change = compare_culling(scene, RenderOptions::exact());
    INFO(change.changed << " pixels changed by culling, " << change.agree_with_depth
                        << " of them agree with the depth buffer");
    CHECK(change.agree_with_depth == change.changed);
}

// With the seed's border rule a front face that crosses the image border is
// dropped whole, so painter's order shows the back face behind it through the
// hole; culling it would turn the pixel to background, which is neither "a
// back face drawn over a front face" nor the depth-buffer picture. So culling
// is switched off whenever a front face may be dropped or cut.
TEST_CASE("with the seed's border rule, culling changes only pixels the depth buffer agrees with") {
    Scene scene = coloured_sphere_scene();
    scene.camera.sensor_height = scene.camera.sensor_width = 0.8;  // the sphere crosses the border
    scene.image = {64, 64, {0, 0, 0}};
    const CullingChange change = compare_culling(scene, RenderOptions::seed());
    INFO(change.changed << " pixels changed by culling, " << change.agree_with_depth
                        << " of them agree with the depth buffer");
    CHECK(change.agree_with_depth == change.changed);
}
