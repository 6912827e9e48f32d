// What the tests that compare two ways of rendering share (test_overdraw,
// test_kernel_isa, test_renderer): a bit-for-bit image comparison and the
// grid of options every such comparison must cover.
#ifndef PHONGRAST_TESTS_TEST_RENDER_MODES_HPP
#define PHONGRAST_TESTS_TEST_RENDER_MODES_HPP

#include <cstring>
#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace test_render_modes {

/// Same size and the same bytes: equal floats, and -0 told from +0.
inline bool same_bits(const phongrast::Image& a, const phongrast::Image& b) {
    return a.rows == b.rows && a.columns == b.columns && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

/// One point of the grid: a preset, a precision, specialised or general kernel.
struct RenderMode {
    phongrast::RenderOptions options;
    std::string name;
};

/// seed/exact x float/double x specialised/general kernels.
inline std::vector<RenderMode> preset_precision_kernel_modes() {
    std::vector<RenderMode> modes;
    for (bool seed_mode : {false, true}) {
        for (phongrast::Precision precision : {phongrast::Precision::single_float, phongrast::Precision::double_float}) {
            for (bool specialize : {true, false}) {
                phongrast::RenderOptions options =
                    seed_mode ? phongrast::RenderOptions::seed() : phongrast::RenderOptions::exact();
                options.precision = precision;
                options.specialize_effects = specialize;
                modes.push_back({options, std::string(seed_mode ? "seed mode" : "exact") +
                                              (precision == phongrast::Precision::double_float ? ", double" : ", float") +
                                              (specialize ? ", specialised" : ", general")});
            }
        }
    }
    return modes;
}

}  // namespace test_render_modes

#endif  // PHONGRAST_TESTS_TEST_RENDER_MODES_HPP
