// libFuzzer target over the public C++ API, with no file in between: a Scene
// and RenderOptions built in memory from the input bytes, including
// out-of-range indices, enum values outside their enumerators, sizes past the
// limit or below 1, wrong array lengths, and non-finite or negative numbers;
// then calculate_normals, Image::at, validate_image, render() and a Renderer
// (moved from, and used again). The library must answer every input with a
// picture of finite pixels or one of its documented exceptions
// (std::invalid_argument, std::out_of_range, std::length_error,
// RenderCancelled); a crash, a sanitizer report, another exception or a
// non-finite pixel is a finding. Run by .ci/fuzz.sh under ASan and UBSan.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "phongrast/image.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/render.hpp"

namespace {

using namespace phongrast;

/// A double that is often ordinary and sometimes one of the values that break
/// arithmetic: 0, -0, tiny, huge, infinite, NaN.
double any_double(FuzzedDataProvider& in) {
    static const double special[] = {0.0,
                                     -0.0,
                                     1.0,
                                     -1.0,
                                     1e-300,
                                     1e300,
                                     -1e300,
                                     3.5e38,
                                     std::numeric_limits<double>::denorm_min(),
                                     std::numeric_limits<double>::infinity(),
                                     -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::quiet_NaN()};
    if (in.ConsumeIntegralInRange<int>(0, 7) == 0) return in.PickValueInArray(special);
    return in.ConsumeFloatingPointInRange<double>(-10.0, 10.0);
}

float any_float(FuzzedDataProvider& in) { return static_cast<float>(any_double(in)); }
glm::dvec3 any_dvec3(FuzzedDataProvider& in) { return {any_double(in), any_double(in), any_double(in)}; }
glm::vec3 any_vec3(FuzzedDataProvider& in) { return {any_float(in), any_float(in), any_float(in)}; }

/// An enum from any int near its range (-1 up to two past its last value).
template <typename Enum>
Enum any_enum(FuzzedDataProvider& in, int count) {
    return static_cast<Enum>(in.ConsumeIntegralInRange<int>(-1, count + 1));
}

/// Image sides: small ones to render, and the edges of the size limit.
int any_side(FuzzedDataProvider& in) {
    static const int special[] = {-1, 0, kMaxImageSide, kMaxImageSide + 1, 100000, std::numeric_limits<int>::max(),
                                  std::numeric_limits<int>::min()};
    if (in.ConsumeIntegralInRange<int>(0, 7) == 0) return in.PickValueInArray(special);
    return in.ConsumeIntegralInRange<int>(1, 12);
}

std::uint32_t any_index(FuzzedDataProvider& in, std::size_t vertices) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
        return in.PickValueInArray({std::uint32_t(vertices), std::uint32_t(vertices + 1), 0xfffffffeu, kNoIndex});
    }
    return in.ConsumeIntegralInRange<std::uint32_t>(0, vertices == 0 ? 0 : std::uint32_t(vertices - 1));
}

Mesh any_mesh(FuzzedDataProvider& in) {
    Mesh mesh;
    const std::size_t vertices = in.ConsumeIntegralInRange<std::size_t>(0, 12);
    for (std::size_t i = 0; i < vertices; ++i) mesh.positions.push_back(any_dvec3(in));
    const std::size_t triangles = in.ConsumeIntegralInRange<std::size_t>(0, 16);
    for (std::size_t t = 0; t < triangles; ++t) {
        mesh.triangles.push_back({any_index(in, vertices), any_index(in, vertices), any_index(in, vertices)});
    }
    // Colours and normals: none, one per vertex, or a wrong count.
    const int colours = in.ConsumeIntegralInRange<int>(0, 3);
    if (colours > 0) {
        const std::size_t count = colours == 1 ? vertices : vertices + std::size_t(colours) - 2;
        for (std::size_t i = 0; i < count; ++i) mesh.colors.push_back(any_vec3(in));
    }
    const int normals = in.ConsumeIntegralInRange<int>(0, 3);
    if (normals > 0) {
        const std::size_t count = normals == 1 ? vertices : vertices + std::size_t(normals) - 2;
        for (std::size_t i = 0; i < count; ++i) {
            mesh.normals.push_back(in.ConsumeBool() ? glm::vec3(0.0f) : any_vec3(in));
        }
    }
    return mesh;
}

Scene any_scene(FuzzedDataProvider& in) {
    Scene scene;
    scene.mesh = any_mesh(in);
    scene.camera.eye = in.ConsumeBool() ? glm::dvec3(0.3, 0.4, 5.0) : any_dvec3(in);
    if (in.ConsumeBool()) scene.camera.lookat = any_dvec3(in);
    if (in.ConsumeBool()) scene.camera.up = any_dvec3(in);
    if (in.ConsumeBool()) scene.camera.focal = any_double(in);
    if (in.ConsumeBool()) scene.camera.sensor_height = any_double(in);
    if (in.ConsumeBool()) scene.camera.sensor_width = any_double(in);
    scene.image.rows = any_side(in);
    scene.image.columns = any_side(in);
    if (in.ConsumeBool()) scene.image.background = any_vec3(in);
    if (in.ConsumeBool()) {
        scene.material.ka = any_vec3(in);
        scene.material.kd = any_vec3(in);
        scene.material.ks = any_vec3(in);
        scene.material.n = any_float(in);
    }
    if (in.ConsumeBool()) scene.ambient = any_vec3(in);
    const int lights = in.ConsumeIntegralInRange<int>(0, 3);
    for (int i = 0; i < lights; ++i) scene.lights.push_back({any_dvec3(in), any_vec3(in)});
    scene.shader = any_enum<Shader>(in, 3);
    scene.lighting = {in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool()};
    return scene;
}

RenderOptions any_options(FuzzedDataProvider& in) {
    RenderOptions options = in.ConsumeBool() ? RenderOptions::seed() : RenderOptions::exact();
    if (in.ConsumeBool()) {
        options.light_vectors = any_enum<LightVectors>(in, 2);
        options.interpolation = any_enum<Interpolation>(in, 2);
        options.border = any_enum<BorderPolicy>(in, 2);
        options.visibility = any_enum<Visibility>(in, 2);
        options.overdraw = any_enum<Overdraw>(in, 3);
        options.precision = any_enum<Precision>(in, 2);
        options.sample_pattern = any_enum<SamplePattern>(in, 2);
        options.back_faces = any_enum<BackFaces>(in, 2);
    }
    options.samples_per_axis = in.ConsumeIntegralInRange<int>(-1, 17);
    options.threads = in.PickValueInArray({-1, 1, 1, 2, 1000});
    options.specialize_effects = in.ConsumeBool();
    options.aovs = {in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool()};
    // Cancel after some reports, sometimes.
    const int cancel_after = in.ConsumeIntegralInRange<int>(-1, 3);
    if (cancel_after >= 0) {
        options.progress = [calls = 0, cancel_after](double) mutable { return calls++ < cancel_after; };
    }
    return options;
}

void require_finite(const RenderResult& result) {
    for (const glm::vec3& p : result.image.pixels) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
    }
    if (result.stats.nonfinite_values_replaced != 0) std::abort();
    if (result.stats.empty_scene != (result.stats.triangles_in == 0)) std::abort();
}

/// `call`, with the documented answers to bad input caught (and nothing else).
template <typename Call>
void expecting_documented_errors(Call call) {
    try {
        call();
    } catch (const std::invalid_argument&) {
    } catch (const std::out_of_range&) {
    } catch (const std::length_error&) {
    } catch (const RenderCancelled&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const Scene scene = any_scene(in);
    const RenderOptions options = any_options(in);

    expecting_documented_errors([&] { calculate_normals(scene.mesh.positions, scene.mesh.triangles); });
    expecting_documented_errors([&] { validate_mesh(scene.mesh); });
    expecting_documented_errors([&] {
        // Small images only: the limit's edges are the size checks' job, not the allocator's.
        const int rows = std::min(scene.image.rows, 64), columns = std::min(scene.image.columns, 64);
        Image image(rows, columns);
        if (in.ConsumeBool() && !image.pixels.empty()) image.pixels.pop_back();
        validate_image(image);
        (void)image.at(in.ConsumeIntegralInRange<int>(-2, 70), in.ConsumeIntegralInRange<int>(-2, 70));
    });
    expecting_documented_errors([&] { validate_render(scene, options); });
    // Render only what stays fast; larger sizes have met the size checks above.
    const double samples_per_pixel = std::max(1, options.samples_per_axis) * std::max(1, options.samples_per_axis);
    if (double(scene.image.rows) * double(scene.image.columns) * samples_per_pixel > 20000.0) return 0;
    expecting_documented_errors([&] { require_finite(render(scene, options)); });
    expecting_documented_errors([&] {
        Renderer renderer(options);
        if (in.ConsumeBool()) {
            Renderer other(std::move(renderer));
            expecting_documented_errors([&] { require_finite(other.render(scene)); });
        }
        // Possibly moved from: must work like a new Renderer().
        require_finite(renderer.render(scene));
    });
    return 0;
}
