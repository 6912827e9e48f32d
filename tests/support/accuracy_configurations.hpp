// The configurations the accuracy report renders: a shader plus the accuracy
// switches of RenderOptions (header-only; the report and its tests use them).
//
//   axis            values
//   shader          flat, gouraud, phong
//   light vectors   centroid (seed), point (at each vertex for Gouraud, each sample for Phong)
//   interpolation   affine (seed), perspective
//   visibility      painter (the contract), depth buffer
//   border          drop (seed), clip
//   sampling        1, 2x2 or 4x4 samples per pixel, ordered or rotated grid
//   precision       float, double
//
// The reference is the most accurate setting the library has: Phong, the
// exact preset, a depth buffer, 8x8 ordered samples and double precision.
#ifndef PHONGRAST_SUPPORT_ACCURACY_CONFIGURATIONS_HPP
#define PHONGRAST_SUPPORT_ACCURACY_CONFIGURATIONS_HPP

#include <functional>
#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast::support {

struct Configuration {
    Shader shader = Shader::phong;
    RenderOptions options;  ///< threads is set by whoever times it
};

inline bool same_accuracy(const Configuration& a, const Configuration& b) {
    const RenderOptions& x = a.options;
    const RenderOptions& y = b.options;
    const bool one_sample = x.samples_per_axis == 1 && y.samples_per_axis == 1;
    return a.shader == b.shader && x.light_vectors == y.light_vectors && x.interpolation == y.interpolation &&
           x.visibility == y.visibility && x.border == y.border && x.samples_per_axis == y.samples_per_axis &&
           (one_sample || x.sample_pattern == y.sample_pattern) && x.precision == y.precision;
}

inline std::string sampling_name(const RenderOptions& o) {
    if (o.samples_per_axis == 1) return "1spp";
    const std::string n = std::to_string(o.samples_per_axis);
    return n + "x" + n + (o.sample_pattern == SamplePattern::rotated_grid ? "rot" : "ord");
}

/// A compact unique name: shader/vectors/interpolation/visibility/border/sampling/precision.
inline std::string key(const Configuration& c) {
    const RenderOptions& o = c.options;
    return std::string(to_string(c.shader)) + "/" +
           (o.light_vectors == LightVectors::triangle_centroid ? "centroid" : "point") + "/" +
           (o.interpolation == Interpolation::screen_affine ? "affine" : "persp") + "/" +
           (o.visibility == Visibility::painter ? "painter" : "zbuf") + "/" +
           (o.border == BorderPolicy::drop_triangle ? "drop" : "clip") + "/" + sampling_name(o) + "/" +
           (o.precision == Precision::single_float ? "float" : "double");
}

inline Configuration seed_configuration(Shader shader) { return {shader, RenderOptions::seed()}; }
inline Configuration exact_configuration(Shader shader) { return {shader, RenderOptions::exact()}; }

inline Configuration reference_configuration() {
    Configuration c{Shader::phong, RenderOptions::exact()};
    c.options.visibility = Visibility::depth_buffer;
    c.options.samples_per_axis = 8;
    c.options.precision = Precision::double_float;
    return c;
}

/// One value of one axis: its name and how to set it.
struct Switch {
    std::string name;
    std::function<void(Configuration&)> apply;
};

inline std::vector<std::vector<Switch>> axes() {
    const auto sampling = [](int per_axis, SamplePattern pattern) {
        return [per_axis, pattern](Configuration& c) {
            c.options.samples_per_axis = per_axis;
            c.options.sample_pattern = pattern;
        };
    };
    return {
        {{"flat", [](Configuration& c) { c.shader = Shader::flat; }},
         {"gouraud", [](Configuration& c) { c.shader = Shader::gouraud; }},
         {"phong", [](Configuration& c) { c.shader = Shader::phong; }}},
        {{"centroid vectors", [](Configuration& c) { c.options.light_vectors = LightVectors::triangle_centroid; }},
         {"per-point vectors", [](Configuration& c) { c.options.light_vectors = LightVectors::shaded_point; }}},
        {{"affine", [](Configuration& c) { c.options.interpolation = Interpolation::screen_affine; }},
         {"perspective", [](Configuration& c) { c.options.interpolation = Interpolation::perspective_correct; }}},
        {{"painter", [](Configuration& c) { c.options.visibility = Visibility::painter; }},
         {"depth buffer", [](Configuration& c) { c.options.visibility = Visibility::depth_buffer; }}},
        {{"drop at border", [](Configuration& c) { c.options.border = BorderPolicy::drop_triangle; }},
         {"clip at border", [](Configuration& c) { c.options.border = BorderPolicy::clip; }}},
        {{"1 sample", sampling(1, SamplePattern::ordered_grid)},
         {"2x2 ordered", sampling(2, SamplePattern::ordered_grid)},
         {"4x4 ordered", sampling(4, SamplePattern::ordered_grid)},
         {"2x2 rotated", sampling(2, SamplePattern::rotated_grid)},
         {"4x4 rotated", sampling(4, SamplePattern::rotated_grid)}},
        {{"float", [](Configuration& c) { c.options.precision = Precision::single_float; }},
         {"double", [](Configuration& c) { c.options.precision = Precision::double_float; }}},
    };
}

struct NamedConfiguration {
    std::string name;  ///< e.g. "seed", "seed + gouraud", "exact + 4x4 ordered"
    Configuration configuration;
};

/// `base` itself, then every configuration that differs from it in exactly one axis.
inline std::vector<NamedConfiguration> one_switch_away(const std::string& base_name, const Configuration& base) {
    std::vector<NamedConfiguration> result{{base_name, base}};
    for (const std::vector<Switch>& axis : axes()) {
        for (const Switch& value : axis) {
            Configuration changed = base;
            value.apply(changed);
            if (!same_accuracy(changed, base)) result.push_back({base_name + " + " + value.name, changed});
        }
    }
    return result;
}

/// Every combination of every axis (3 x 2 x 2 x 2 x 2 x 5 x 2 = 480).
inline std::vector<Configuration> every_combination() {
    std::vector<Configuration> result{Configuration{Shader::phong, RenderOptions::exact()}};
    for (const std::vector<Switch>& axis : axes()) {
        std::vector<Configuration> next;
        for (const Configuration& partial : result) {
            for (const Switch& value : axis) {
                Configuration c = partial;
                value.apply(c);
                next.push_back(c);
            }
        }
        result = std::move(next);
    }
    return result;
}

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_ACCURACY_CONFIGURATIONS_HPP
