// The renderer simulates only the effects a scene calls for (RenderStats says
// what it evaluated), and the specialised kernels change no pixel.
#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "phongrast/render.hpp"
#include "test_meshes.hpp"

using namespace phongrast;

namespace {

Scene sphere_scene() {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(16, 32, 1.0);
    for (const glm::dvec3& p : scene.mesh.positions) {
        scene.mesh.colors.push_back(glm::vec3(0.5 + 0.5 * p.x, 0.5 + 0.5 * p.y, 0.6f));
    }
    scene.camera.eye = {0.4, 0.5, 4};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.4;
    scene.image = {64, 64, {0, 0, 0}};
    scene.material.n = 12;
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}, {{-3, 1, 2}, {0.4f, 0.3f, 0.2f}}};
    return scene;
}

RenderResult render_with(const Scene& scene, RenderOptions options, bool specialized) {
    options.specialize_effects = specialized;
    return render(scene, options);
}

}  // namespace

TEST_CASE("specialised kernels give the general kernel's image bit for bit") {
    Scene base = sphere_scene();
    int compared = 0;
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        for (const char* lighting : {"ambient", "diffuse", "specular", "full", "ambient+specular", "diffuse+specular"}) {
            for (int variant = 0; variant < 4; ++variant) {
                Scene scene = base;
                scene.shader = shader;
                scene.lighting = parse_lighting(lighting);
                if (variant == 1) scene.material.ks = glm::vec3(0.0f);                 // nothing shiny
                if (variant == 2) scene.lights.push_back({{0, -4, 1}, glm::vec3(0)});  // a dark light
                if (variant == 3) scene.mesh.colors.assign(scene.mesh.positions.size(), {0.3f, 0.6f, 0.9f});
                for (RenderOptions options : {RenderOptions::seed(), RenderOptions::exact()}) {
                    INFO(to_string(shader) << " " << lighting << " variant " << variant);
                    const RenderResult general = render_with(scene, options, false);
                    const RenderResult special = render_with(scene, options, true);
                    CHECK(special.image.pixels == general.image.pixels);
                    CHECK(special.stats.samples_shaded == general.stats.samples_shaded);
                    ++compared;
                }
            }
        }
    }
    CHECK(compared == 3 * 6 * 4 * 2);
}

TEST_CASE("Gouraud lights its vertices alike with few and with many lights") {
    // Up to 8 active lights the vertex stage normalises light vectors many
    // vertices at a time; beyond, vertex by vertex: both give the general kernel's image.
    Scene scene = sphere_scene();
    scene.shader = Shader::gouraud;
    for (int extra = 0; extra < 9; ++extra) {
        scene.lights.push_back({{-3.0 + extra, 2.5, 3.0 - 0.5 * extra}, {0.05f * extra, 0.1f, 0.08f}});
        INFO(scene.lights.size() << " lights");
        CHECK(render_with(scene, RenderOptions::exact(), true).image.pixels ==
              render_with(scene, RenderOptions::exact(), false).image.pixels);
    }
}

TEST_CASE("no specular evaluations when nothing is shiny or specular is not selected") {
    Scene scene = sphere_scene();
    for (Shader shader : {Shader::flat, Shader::gouraud, Shader::phong}) {
        scene.shader = shader;
        scene.lighting = Lighting::full();
        const RenderResult full = render(scene);
        CHECK(full.stats.specular_evaluations > 0);
        CHECK(full.stats.effects.specular);

        scene.material.ks = glm::vec3(0.0f);
        const RenderResult matte = render(scene);
        CHECK(matte.stats.specular_evaluations == 0);
        CHECK_FALSE(matte.stats.effects.specular);
        CHECK(matte.stats.diffuse_evaluations > 0);
        scene.material.ks = glm::vec3(1.0f);

        scene.lighting = parse_lighting("ambient+diffuse");
        CHECK(render(scene).stats.specular_evaluations == 0);
    }
}

TEST_CASE("ambient-only Phong interpolates no normal and evaluates no light") {
    Scene scene = sphere_scene();
    scene.shader = Shader::phong;
    scene.lighting = Lighting::only_ambient();
    const RenderResult result = render(scene);
    REQUIRE(result.stats.samples_shaded > 500);
    CHECK(result.stats.normal_interpolations == 0);
    CHECK(result.stats.diffuse_evaluations == 0);
    CHECK(result.stats.specular_evaluations == 0);
    CHECK(result.stats.ambient_evaluations == result.stats.samples_shaded);
    CHECK_FALSE(result.stats.effects.normals);
    // The general kernel, for comparison, interpolates a normal at every sample.
    RenderOptions general = RenderOptions::exact();
    general.specialize_effects = false;
    CHECK(render(scene, general).stats.normal_interpolations == result.stats.samples_shaded);
}

TEST_CASE("a picture painter's order cannot change is not sorted") {
    Scene scene = sphere_scene();  // seen from outside: back faces lie under front faces
    scene.lighting = Lighting::only_ambient();
    scene.mesh.colors.assign(scene.mesh.positions.size(), {0.3f, 0.6f, 0.9f});
    for (Shader shader : {Shader::flat, Shader::phong}) {
        INFO(to_string(shader));
        scene.shader = shader;
        const RenderResult unsorted = render(scene);
        REQUIRE(unsorted.stats.triangles_drawn > 500);
        CHECK(unsorted.stats.triangles_sorted == 0);
        // The general kernel sorts (it evaluates every term), and paints the same picture.
        const RenderResult sorted = render_with(scene, RenderOptions::exact(), false);
        CHECK(sorted.stats.triangles_sorted == sorted.stats.triangles_drawn);
        CHECK(unsorted.image.pixels == sorted.image.pixels);
        CHECK(unsorted.stats.samples_shaded == sorted.stats.samples_shaded);
    }
    SECTION("Gouraud interpolates its corner colours, which may differ in the last bit: sorted") {
        scene.shader = Shader::gouraud;
        const RenderResult result = render(scene);
        CHECK(result.stats.triangles_sorted == result.stats.triangles_drawn);
    }
    SECTION("varying colours: sorted") {
        scene = sphere_scene();
        scene.shader = Shader::phong;
        scene.lighting = Lighting::only_ambient();
        const RenderResult result = render(scene);
        CHECK(result.stats.triangles_sorted == result.stats.triangles_drawn);
    }
    SECTION("an extra output that names the last triangle: sorted") {
        scene.shader = Shader::phong;
        RenderOptions options = RenderOptions::exact();
        options.aovs.id = true;
        const RenderResult result = render(scene, options);
        CHECK(result.stats.triangles_sorted == result.stats.triangles_drawn);
    }
    SECTION("the depth buffer: sorted") {
        scene.shader = Shader::phong;
        RenderOptions options = RenderOptions::exact();
        options.visibility = Visibility::depth_buffer;
        const RenderResult result = render(scene, options);
        CHECK(result.stats.triangles_sorted == result.stats.triangles_drawn);
    }
}

TEST_CASE("a light of zero intensity costs no evaluation") {
    Scene scene = sphere_scene();
    scene.shader = Shader::phong;
    scene.lights = {{{3, 3, 3}, glm::vec3(0.0f)}};
    const RenderResult dark = render(scene);
    CHECK(dark.stats.effects.active_lights == 0);
    CHECK(dark.stats.diffuse_evaluations == 0);
    CHECK(dark.stats.specular_evaluations == 0);
    scene.lights.push_back({{-3, 3, 3}, glm::vec3(1.0f)});
    const RenderResult one = render(scene);
    CHECK(one.stats.effects.active_lights == 1);
    CHECK(one.stats.diffuse_evaluations == one.stats.samples_shaded);  // one light, not two
}

TEST_CASE("Gouraud lights each vertex once, flat lights each triangle once") {
    Scene scene = sphere_scene();
    scene.lighting = Lighting::only_diffuse();
    scene.shader = Shader::gouraud;
    const RenderResult gouraud = render(scene, RenderOptions::exact());
    CHECK(gouraud.stats.diffuse_evaluations == scene.mesh.positions.size() * 2);  // two lights
    scene.shader = Shader::flat;
    const RenderResult flat = render(scene, RenderOptions::exact());
    CHECK(flat.stats.triangles_drawn < flat.stats.triangles_in);  // some cover no pixel centre
    CHECK(flat.stats.diffuse_evaluations == flat.stats.triangles_drawn * 2);
}

TEST_CASE("back faces are culled only for a closed mesh with the eye outside") {
    RenderOptions cull = RenderOptions::exact();
    cull.back_faces = BackFaces::cull_when_hidden;
    Scene scene = sphere_scene();

    const RenderResult closed = render(scene, cull);
    CHECK(closed.stats.back_faces_culled);
    CHECK(closed.stats.triangles_culled > closed.stats.triangles_in / 3);
    CHECK(render(scene).stats.triangles_culled == 0);  // the default draws everything

    SECTION("an open mesh keeps every face") {
        scene.mesh.triangles.pop_back();
        const RenderResult open = render(scene, cull);
        CHECK_FALSE(open.stats.back_faces_culled);
        CHECK(open.stats.triangles_culled == 0);
    }
    SECTION("an eye inside the mesh keeps every face") {
        scene.camera.eye = {0.1, 0.2, 0.3};
        scene.camera.lookat = {0, 0, -1};
        const RenderResult inside = render(scene, cull);
        CHECK_FALSE(inside.stats.back_faces_culled);
        CHECK(inside.stats.triangles_culled == 0);
    }
    SECTION("an inward-oriented closed mesh culls the other winding") {
        for (Triangle& t : scene.mesh.triangles) std::swap(t[1], t[2]);
        const RenderResult inward = render(scene, cull);
        CHECK(inward.stats.back_faces_culled);
        // The same faces are hidden as before, whatever their winding.
        CHECK(inward.stats.triangles_culled == closed.stats.triangles_culled);
    }
}

TEST_CASE("culling changes only pixels where painter's order showed a back face, towards the depth buffer") {
    Scene scene;
    scene.mesh = test_meshes::torus(48, 24, 1.0, 0.4);
    scene.camera.eye = {0.0, 2.2, 2.6};
    scene.camera.focal = 2;
    scene.camera.sensor_height = scene.camera.sensor_width = 1.8;
    scene.image = {96, 96, {0, 0, 0}};
    scene.lights = {{{2, 4, 3}, {1, 1, 1}}};
    scene.shader = Shader::phong;

    RenderOptions painter = RenderOptions::exact();
    RenderOptions culled = painter;
    culled.back_faces = BackFaces::cull_when_hidden;
    RenderOptions depth = painter;
    depth.visibility = Visibility::depth_buffer;

    const RenderResult a = render(scene, painter), b = render(scene, culled), z = render(scene, depth);
    REQUIRE(b.stats.back_faces_culled);
    int changed = 0, agree_with_depth = 0;
    for (std::size_t i = 0; i < a.image.pixels.size(); ++i) {
        if (a.image.pixels[i] == b.image.pixels[i]) continue;
        ++changed;
        const glm::vec3 d = glm::abs(b.image.pixels[i] - z.image.pixels[i]);
        agree_with_depth += std::max(d.x, std::max(d.y, d.z)) < 1e-5f;
    }
    INFO(changed << " pixels changed by culling");
    CHECK(changed > 0);  // the torus's inner back faces are painted over front faces somewhere
    CHECK(agree_with_depth == changed);
}
