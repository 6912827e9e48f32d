// phongrast's exact mode against Mesa's llvmpipe (OSMesa) on a small scene: an
// independent implementation of the same contract must give the same picture,
// up to pixels on triangle edges and float rounding.
#include <catch2/catch.hpp>

#include "support/image_compare.hpp"
#include "support/llvmpipe_renderer.hpp"
#include "support/scenes.hpp"

namespace {

namespace support = phongrast::support;

support::ImageAgreement agreement_for(phongrast::Shader shader) {
    // 720 triangles with concave dents, 64 x 64 pixels: the sphere fills about half the image.
    support::NamedScene named = support::icosphere_scene("small", 6, 64);
    named.scene.shader = shader;
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = 1;
    const phongrast::Image ours = phongrast::render(named.scene, options).image;

    support::LlvmpipeRenderer llvmpipe;
    llvmpipe.load(named.scene);
    llvmpipe.draw();
    const support::ImageAgreement agreement =
        support::agreement(ours, llvmpipe.image(), named.scene.image.background);
    INFO(llvmpipe.description() << ": " << support::summary(agreement));
    CHECK(agreement.covered_in_both > agreement.pixels / 4);
    return agreement;
}

}  // namespace

TEST_CASE("phongrast exact and llvmpipe agree on a small icosphere") {
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        INFO("shader " << phongrast::to_string(shader));
        const support::ImageAgreement agreement = agreement_for(shader);
        INFO(support::summary(agreement));
        // Fewer than 1% of the pixels may differ by more than 2/255 (edge pixels and rounding).
        CHECK(agreement.above_2 < agreement.pixels / 100);
        CHECK(agreement.only_in_first + agreement.only_in_second < agreement.pixels / 100);
        // Away from the silhouette, no pixel may be visibly different.
        CHECK(agreement.interior_above_8 <= agreement.interior_pixels / 100);
    }
}

TEST_CASE("the comparison notices a wrong picture") {
    // The same check must fail when the two sides really differ: here a light moved.
    support::NamedScene named = support::icosphere_scene("small", 6, 64);
    named.scene.shader = phongrast::Shader::phong;
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = 1;
    const phongrast::Image ours = phongrast::render(named.scene, options).image;

    named.scene.lights[0].position.x = -named.scene.lights[0].position.x;
    support::LlvmpipeRenderer llvmpipe;
    llvmpipe.load(named.scene);
    llvmpipe.draw();
    const support::ImageAgreement agreement =
        support::agreement(ours, llvmpipe.image(), named.scene.image.background);
    INFO(support::summary(agreement));
    CHECK(agreement.above_2 > agreement.pixels / 10);
}
