// light() and its three terms against values computed by hand from the
// contract's formula (docs/scene-format.md, "Lighting").
#include <cmath>

#include <catch2/catch.hpp>

#include "phongrast/lighting.hpp"

using namespace phongrast;

namespace {

void check(const glm::vec3& actual, const glm::vec3& expected, float margin = 1e-6f) {
    CHECK(actual.x == Approx(expected.x).margin(margin));
    CHECK(actual.y == Approx(expected.y).margin(margin));
    CHECK(actual.z == Approx(expected.z).margin(margin));
}

PhongMaterial material(float ka, float kd, float ks, float n) {
    PhongMaterial m;
    m.ka = glm::vec3(ka);
    m.kd = glm::vec3(kd);
    m.ks = glm::vec3(ks);
    m.n = n;
    return m;
}

// A surface point at the origin facing +z; the eye straight above it.
const glm::vec3 kPoint(0.0f), kNormal(0.0f, 0.0f, 1.0f), kEye(0.0f, 0.0f, 10.0f);

}  // namespace

TEST_CASE("ambient term is ka * Ia * c per channel") {
    PhongMaterial m;
    m.ka = {0.5f, 0.25f, 1.0f};
    const glm::vec3 color(0.2f, 0.4f, 0.8f), ia(1.0f, 2.0f, 0.5f);
    check(ambient_term<float>(color, m, ia), {0.5f * 1.0f * 0.2f, 0.25f * 2.0f * 0.4f, 1.0f * 0.5f * 0.8f});
    check(light(kPoint, kNormal, color, kEye, m, {}, ia, Lighting::only_ambient()),
          {0.1f, 0.2f, 0.4f});
}

TEST_CASE("diffuse term is Ip * kd * c * N.L") {
    const PhongMaterial m = material(0.0f, 0.5f, 0.0f, 1.0f);
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    // Light at 60 degrees from the normal: N.L = cos 60 = 0.5.
    const double angle = M_PI / 3.0;
    const std::vector<PointLight> lights{{{std::sin(angle) * 5.0, 0.0, std::cos(angle) * 5.0}, {2.0f, 2.0f, 2.0f}}};
    const glm::vec3 result = light(kPoint, kNormal, color, kEye, m, lights, glm::vec3(1.0f), Lighting::only_diffuse());
    check(result, 2.0f * 0.5f * color * 0.5f, 1e-5f);
}

TEST_CASE("specular term is Ip * ks * (R.V)^n") {
    const PhongMaterial m = material(0.0f, 0.0f, 0.8f, 3.0f);
    // L at 45 degrees in the x-z plane; R mirrors it to (-1, 0, 1)/sqrt2.
    const std::vector<PointLight> lights{{{1.0, 0.0, 1.0}, {1.0f, 0.5f, 0.25f}}};
    SECTION("viewer along R sees the full highlight") {
        const glm::vec3 eye(-3.0f, 0.0f, 3.0f);
        check(light(kPoint, kNormal, glm::vec3(1.0f), eye, m, lights, glm::vec3(0.0f), Lighting::only_specular()),
              glm::vec3(0.8f, 0.4f, 0.2f), 1e-5f);
    }
    SECTION("viewer along N: R.V = cos 45, raised to n = 3") {
        const float r_dot_v = std::sqrt(0.5f);
        const float highlight = r_dot_v * r_dot_v * r_dot_v;
        check(light(kPoint, kNormal, glm::vec3(1.0f), kEye, m, lights, glm::vec3(0.0f), Lighting::only_specular()),
              glm::vec3(0.8f, 0.4f, 0.2f) * highlight, 1e-5f);
    }
    SECTION("the specular term ignores the surface colour") {
        check(light(kPoint, kNormal, glm::vec3(0.0f), glm::vec3(-3.0f, 0.0f, 3.0f), m, lights, glm::vec3(0.0f),
                    Lighting::only_specular()),
              glm::vec3(0.8f, 0.4f, 0.2f), 1e-5f);
    }
}

TEST_CASE("a light behind the surface gives no diffuse and no specular") {
    const PhongMaterial m = material(0.5f, 1.0f, 1.0f, 1.0f);
    const std::vector<PointLight> behind{{{0.0, 0.0, -5.0}, {1.0f, 1.0f, 1.0f}}};
    const glm::vec3 color(1.0f), ia(0.2f);
    check(light(kPoint, kNormal, color, kEye, m, behind, ia, Lighting::only_diffuse()), glm::vec3(0.0f));
    check(light(kPoint, kNormal, color, kEye, m, behind, ia, Lighting::only_specular()), glm::vec3(0.0f));
    // Only the ambient part survives the full formula.
    check(light(kPoint, kNormal, color, kEye, m, behind, ia, Lighting::full()), glm::vec3(0.1f));
}

TEST_CASE("n = 0 gives a constant specular term wherever N.L > 0") {
    const PhongMaterial m = material(0.0f, 0.0f, 0.7f, 0.0f);
    const std::vector<PointLight> lights{{{1.0, 0.0, 1.0}, {1.0f, 1.0f, 1.0f}}};
    // Viewer far from R (R.V = 0 -> 0^0 = 1) and near it: the same constant.
    check(light(kPoint, kNormal, glm::vec3(1.0f), glm::vec3(5.0f, 0.0f, 0.001f), m, lights, glm::vec3(0.0f),
                Lighting::only_specular()),
          glm::vec3(0.7f));
    check(light(kPoint, kNormal, glm::vec3(1.0f), glm::vec3(-1.0f, 0.0f, 1.0f), m, lights, glm::vec3(0.0f),
                Lighting::only_specular()),
          glm::vec3(0.7f));
}

TEST_CASE("per-channel coefficients multiply each channel separately") {
    PhongMaterial m;
    m.ka = {1.0f, 0.0f, 0.0f};
    m.kd = {0.0f, 1.0f, 0.0f};
    m.ks = {0.0f, 0.0f, 1.0f};
    m.n = 1.0f;
    const std::vector<PointLight> overhead{{{0.0, 0.0, 5.0}, {1.0f, 1.0f, 1.0f}}};
    // N.L = 1, R = N, V = N: diffuse = kd, specular = ks, ambient = ka * 0.5.
    check(light(kPoint, kNormal, glm::vec3(1.0f), kEye, m, overhead, glm::vec3(0.5f), Lighting::full()),
          {0.5f, 1.0f, 1.0f});
}

TEST_CASE("lights add up and each term is selectable") {
    const PhongMaterial m = material(0.2f, 0.6f, 0.4f, 10.0f);
    const std::vector<PointLight> lights{{{0.0, 0.0, 5.0}, {1.0f, 0.0f, 0.0f}}, {{0.0, 0.0, 7.0}, {0.0f, 1.0f, 0.0f}}};
    const glm::vec3 color(0.5f), ia(1.0f);
    const glm::vec3 a = light(kPoint, kNormal, color, kEye, m, lights, ia, Lighting::only_ambient());
    const glm::vec3 d = light(kPoint, kNormal, color, kEye, m, lights, ia, Lighting::only_diffuse());
    const glm::vec3 s = light(kPoint, kNormal, color, kEye, m, lights, ia, Lighting::only_specular());
    check(a, glm::vec3(0.1f));
    check(d, {0.3f, 0.3f, 0.0f});
    check(s, {0.4f, 0.4f, 0.0f});
    check(light(kPoint, kNormal, color, kEye, m, lights, ia, Lighting::full()), a + d + s);
    check(light(kPoint, kNormal, color, kEye, m, lights, ia, parse_lighting("ambient+specular")), a + s);
}

TEST_CASE("a light or the eye exactly at the point contributes nothing, not NaN") {
    const PhongMaterial m = material(0.1f, 1.0f, 1.0f, 0.0f);
    const std::vector<PointLight> at_point{{{0.0, 0.0, 0.0}, {1.0f, 1.0f, 1.0f}}};
    check(light(kPoint, kNormal, glm::vec3(1.0f), kEye, m, at_point, glm::vec3(1.0f), Lighting::full()),
          glm::vec3(0.1f));
    const std::vector<PointLight> overhead{{{0.0, 0.0, 5.0}, {1.0f, 1.0f, 1.0f}}};
    // Eye at the point: diffuse stays, specular (which needs V) contributes nothing.
    check(light(kPoint, kNormal, glm::vec3(1.0f), kPoint, m, overhead, glm::vec3(1.0f), Lighting::full()),
          glm::vec3(1.1f));
}

TEST_CASE("lighting names parse as the contract spells them") {
    CHECK(parse_lighting("full") == Lighting::full());
    CHECK(parse_lighting("diffusion") == Lighting::only_diffuse());
    CHECK(parse_lighting("ambient+diffuse+specular") == Lighting::full());
    CHECK(to_string(parse_lighting("specular+ambient")) == "ambient+specular");
    CHECK_THROWS_WITH(parse_lighting("shiny"), Catch::Contains("shiny") && Catch::Contains("ambient"));
    CHECK_THROWS_AS(parse_lighting(""), std::invalid_argument);
    CHECK_THROWS_AS(parse_lighting("ambient+"), std::invalid_argument);
}
