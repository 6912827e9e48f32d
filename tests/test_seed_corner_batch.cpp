// Seed Gouraud lights the corners of up to 16 whole triangles at once
// (SeedCornerBatch, src/seed_corner_batch.hpp), in both fills: the sorted
// set-up lights a chunk's last partial batch at its end, the walk queues the
// triangles' draws until their corners are lit, then fills them in mesh
// order. The general kernel (specialize_effects = false) still lights each
// triangle's corners on its own, so the two images must agree bit for bit:
// whatever the lighting terms, the camera (the orthographic eye at infinity),
// the precision, the threads, the border (clipped triangles, lit at once,
// among the batched ones; or dropped), and
// chunks of set-up (4,096 triangles) ending inside a batch.
#include <string>

#include <catch2/catch.hpp>

#include "fill_driver.hpp"
#include "phongrast/render.hpp"
#include "test_meshes.hpp"
#include "test_render_modes.hpp"

using namespace phongrast;

namespace {

/// Sets the walk choice for one scope, then puts back what it was.
class WalkChoiceFor {
public:
    explicit WalkChoiceFor(detail::WalkChoice choice) : previous_(detail::set_mesh_order_walk_choice(choice)) {}
    ~WalkChoiceFor() { detail::set_mesh_order_walk_choice(previous_); }
    WalkChoiceFor(const WalkChoiceFor&) = delete;
    WalkChoiceFor& operator=(const WalkChoiceFor&) = delete;

private:
    detail::WalkChoice previous_;
};

/// 14,280 triangles (four chunks, the last one partial), coloured by
/// position, large enough in the image that its border clips some.
Scene sphere_across_the_border(bool orthographic) {
    Scene scene;
    scene.mesh = test_meshes::uv_sphere(60, 120, 1.0);
    test_meshes::color_by_position(scene.mesh);
    scene.camera = orthographic ? Camera::orthographic({0.4, 0.5, 2.6}, {0, 0, 0}, {0, 1, 0}, 1.6, 1.6)
                                : Camera::look_at({0.4, 0.5, 2.6}, {0, 0, 0}, {0, 1, 0}, 2, 1.4, 1.4);
    scene.image = {80, 96, {0.1f, 0.2f, 0.3f}};
    scene.shader = Shader::gouraud;
    scene.material.n = 20;
    scene.lights = {{{3, 3, 3}, {1, 1, 1}}, {{-3, 1, 2}, {0.4f, 0.3f, 0.2f}}, {{0, -3, 1}, {0.2f, 0.5f, 0.3f}}};
    return scene;
}

}  // namespace

TEST_CASE("seed Gouraud's corners lit in batches: the general kernel's image bit for bit") {
    int compared = 0;
    for (bool orthographic : {false, true}) {
        for (const char* lighting : {"full", "diffuse", "specular", "ambient+specular"}) {
            Scene scene = sphere_across_the_border(orthographic);
            scene.lighting = parse_lighting(lighting);
            for (int variant = 0; variant < 8; ++variant) {
                RenderOptions options = RenderOptions::seed();
                options.precision = (variant & 1) != 0 ? Precision::double_float : Precision::single_float;
                options.threads = (variant & 2) != 0 ? 2 : 1;
                // The seed's border drops what crosses it; clipped corners are lit at once, between batched ones.
                options.border = (variant & 4) != 0 ? BorderPolicy::clip : BorderPolicy::drop_triangle;
                for (detail::WalkChoice walk : {detail::WalkChoice::always, detail::WalkChoice::never}) {
                    WalkChoiceFor choice(walk);
                    options.specialize_effects = true;
                    const RenderResult batched = render(scene, options);
                    options.specialize_effects = false;
                    const RenderResult general = render(scene, options);
                    INFO((orthographic ? "orthographic, " : "perspective, ")
                         << lighting << (options.precision == Precision::double_float ? ", double, " : ", float, ")
                         << (options.border == BorderPolicy::clip ? "clipped, " : "dropped, ") << options.threads
                         << " threads, " << (walk == detail::WalkChoice::always ? "walk" : "sorted"));
                    REQUIRE(batched.stats.triangles_drawn > 4096);
                    REQUIRE((options.border == BorderPolicy::clip ? batched.stats.triangles_clipped
                                                                   : batched.stats.triangles_dropped) > 0);
                    CHECK(test_render_modes::same_bits(batched.image, general.image));
                    CHECK(batched.stats.samples_shaded == general.stats.samples_shaded);
                    ++compared;
                }
            }
        }
    }
    CHECK(compared == 2 * 4 * 8 * 2);
}
