// phongrast's exact mode against Mesa's llvmpipe (OSMesa) on a small scene: an
// independent implementation of the same contract must give the same picture,
// up to pixels on triangle edges and float rounding. The look-at, OpenCV
// (off-centre, skewed, fx != fy) and orthographic cameras, and textured faces
// (each wrap mode, magnified, mixed with untextured faces of another material).
#include <cmath>
#include <memory>

#include <catch2/catch.hpp>

#include "support/image_compare.hpp"
#include "support/llvmpipe_renderer.hpp"
#include "support/scenes.hpp"

namespace {

namespace support = phongrast::support;

/// phongrast (exact, one thread) on `ours` against llvmpipe on `theirs`
/// (the same scene, or a deliberately different one for a negative control).
support::ImageAgreement agreement_between(const phongrast::Scene& ours, const phongrast::Scene& theirs) {
    phongrast::RenderOptions options = phongrast::RenderOptions::exact();
    options.threads = 1;
    const phongrast::Image image = phongrast::render(ours, options).image;

    support::LlvmpipeRenderer llvmpipe;
    llvmpipe.load(theirs);
    llvmpipe.draw();
    const support::ImageAgreement agreement = support::agreement(image, llvmpipe.image(), ours.image.background);
    INFO(llvmpipe.description() << ": " << support::summary(agreement));
    return agreement;
}

/// phongrast and llvmpipe on the same scene, which must cover a quarter of the image.
support::ImageAgreement compare(const phongrast::Scene& scene) {
    const support::ImageAgreement agreement = agreement_between(scene, scene);
    CHECK(agreement.covered_in_both > agreement.pixels / 4);
    return agreement;
}

/// 720 triangles with concave dents, 64 x 64 pixels: the sphere fills about half the image.
phongrast::Scene small_sphere(phongrast::Shader shader) {
    support::NamedScene named = support::icosphere_scene("small", 6, 64);
    named.scene.shader = shader;
    return named.scene;
}

support::ImageAgreement agreement_for(phongrast::Shader shader) { return compare(small_sphere(shader)); }

/// The thresholds every agreeing picture meets.
void check_agreement(const support::ImageAgreement& agreement) {
    INFO(support::summary(agreement));
    // Fewer than 1% of the pixels may differ by more than 2/255 (edge pixels and rounding).
    CHECK(agreement.above_2 < agreement.pixels / 100);
    CHECK(agreement.only_in_first + agreement.only_in_second < agreement.pixels / 100);
    // Away from the silhouette, no pixel may be visibly different.
    CHECK(agreement.interior_above_8 <= agreement.interior_pixels / 100);
}

/// The look-at camera's OpenCV form with the principal point moved off
/// centre, skew, and different focal lengths along rows and columns.
phongrast::Camera skewed_opencv_camera(const phongrast::Scene& scene) {
    const phongrast::OpenCvCamera cv = phongrast::opencv_form(scene.camera, scene.image.rows, scene.image.columns);
    const phongrast::Matrix3x3 K{{{1.1 * cv.fx, 0.08 * cv.fx, cv.cx + 3.3}, {0.0, 0.95 * cv.fy, cv.cy - 2.2}, {0.0, 0.0, 1.0}}};
    return phongrast::Camera::from_opencv(K, cv.world_to_camera);
}

/// A smooth but uneven 12 x 16 texture with values in [0.2, 1]: magnified
/// about 4 times on the sphere, so the bilinear blend of each texel quad shows.
std::shared_ptr<const phongrast::TextureImage> wavy_texture() {
    auto image = std::make_shared<phongrast::TextureImage>();
    image->rows = 12;
    image->columns = 16;
    image->name = "wavy";
    for (int i = 0; i < image->rows; ++i) {
        for (int j = 0; j < image->columns; ++j) {
            const float a = float(i), b = float(j);
            image->texels.push_back(glm::vec3(0.6f + 0.4f * std::sin(0.9f * a + 0.3f * b),
                                              0.6f + 0.4f * std::cos(0.5f * a - 0.7f * b),
                                              0.2f + 0.8f * float((i * 7 + j * 3) % 5) / 4.0f));
        }
    }
    return image;
}

/// The small sphere with a planar (s, t) = 0.8 (x, y) + 0.5, which leaves
/// [0, 1] near the rim so `wrap` shows. Faces with x > 0 (by centroid) use
/// material 0: textured, with their own kd and n; the others material 1:
/// untextured, with a glTF-style colour factor and their own ks.
phongrast::Scene textured_sphere(phongrast::Shader shader, phongrast::TextureWrap wrap) {
    phongrast::Scene scene = small_sphere(shader);
    phongrast::Mesh& mesh = scene.mesh;
    for (const glm::dvec3& p : mesh.positions) {
        mesh.texcoords.push_back(glm::vec2(float(0.8 * p.x + 0.5), float(0.8 * p.y + 0.5)));
    }
    mesh.texcoord_triangles = mesh.triangles;
    phongrast::FaceMaterial textured;
    textured.name = "textured";
    textured.coefficients.kd = glm::vec3(0.9f, 0.85f, 0.8f);
    textured.coefficients.n = 8.0f;
    textured.texture = phongrast::TextureMap{wavy_texture(), wrap, wrap};
    phongrast::FaceMaterial painted;
    painted.name = "painted";
    painted.coefficients.ks = glm::vec3(0.2f);
    painted.color_factor = glm::vec3(0.9f, 0.5f, 0.3f);
    mesh.materials = {textured, painted};
    for (const phongrast::Triangle& t : mesh.triangles) {
        const double x = mesh.positions[t[0]].x + mesh.positions[t[1]].x + mesh.positions[t[2]].x;
        mesh.face_materials.push_back(x > 0.0 ? 0u : 1u);
    }
    return scene;
}

}  // namespace

TEST_CASE("phongrast exact and llvmpipe agree on a small icosphere") {
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        INFO("shader " << phongrast::to_string(shader));
        check_agreement(agreement_for(shader));
    }
}

TEST_CASE("phongrast exact and llvmpipe agree through an OpenCV camera with skew and an off-centre principal point") {
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        INFO("shader " << phongrast::to_string(shader));
        phongrast::Scene scene = small_sphere(shader);
        scene.image.columns = 80;  // not square: K is in pixels, columns and rows differ
        scene.camera = skewed_opencv_camera(scene);
        check_agreement(compare(scene));
    }
}

TEST_CASE("phongrast exact and llvmpipe agree through an orthographic camera") {
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        INFO("shader " << phongrast::to_string(shader));
        phongrast::Scene scene = small_sphere(shader);
        scene.image.columns = 80;
        scene.camera = phongrast::Camera::orthographic(scene.camera.eye, scene.camera.lookat, scene.camera.up, 2.4, 3.0);
        check_agreement(compare(scene));
    }
}

TEST_CASE("phongrast exact and llvmpipe agree on textured faces in each wrap mode") {
    for (phongrast::Shader shader : {phongrast::Shader::gouraud, phongrast::Shader::phong}) {
        for (phongrast::TextureWrap wrap : {phongrast::TextureWrap::repeat, phongrast::TextureWrap::clamp_to_edge,
                                            phongrast::TextureWrap::mirrored_repeat}) {
            INFO("shader " << phongrast::to_string(shader) << ", wrap " << phongrast::to_string(wrap));
            check_agreement(compare(textured_sphere(shader, wrap)));
        }
    }
}

TEST_CASE("phongrast exact and llvmpipe agree on a textured sphere through an OpenCV camera") {
    phongrast::Scene scene = textured_sphere(phongrast::Shader::phong, phongrast::TextureWrap::repeat);
    scene.camera = skewed_opencv_camera(scene);
    check_agreement(compare(scene));
}

TEST_CASE("the comparison notices a wrong picture") {
    // The same check must fail when the two sides really differ: here a light moved.
    const phongrast::Scene scene = small_sphere(phongrast::Shader::phong);
    phongrast::Scene moved = scene;
    moved.lights[0].position.x = -moved.lights[0].position.x;
    const support::ImageAgreement agreement = agreement_between(scene, moved);
    INFO(support::summary(agreement));
    CHECK(agreement.above_2 > agreement.pixels / 10);
}

TEST_CASE("the comparison notices a texture read upside down") {
    // llvmpipe gets the texture with t flipped (t -> 1 - t): the pictures must differ.
    const phongrast::Scene scene = textured_sphere(phongrast::Shader::phong, phongrast::TextureWrap::clamp_to_edge);
    phongrast::Scene flipped = scene;
    for (glm::vec2& st : flipped.mesh.texcoords) st.y = 1.0f - st.y;
    const support::ImageAgreement agreement = agreement_between(scene, flipped);
    INFO(support::summary(agreement));
    CHECK(agreement.interior_above_8 > agreement.interior_pixels / 10);
}

TEST_CASE("the comparison notices an orthographic picture lit from a viewer at the eye") {
    // The same orthographic camera drawn as a look-at one moves every
    // silhouette pixel and the highlights: the check must see it.
    const phongrast::Scene perspective = small_sphere(phongrast::Shader::phong);
    phongrast::Scene scene = perspective;
    scene.camera = phongrast::Camera::orthographic(scene.camera.eye, scene.camera.lookat, scene.camera.up, 2.7, 2.7);
    const support::ImageAgreement agreement = agreement_between(scene, perspective);
    INFO(support::summary(agreement));
    CHECK(agreement.above_2 > agreement.pixels / 10);
}
