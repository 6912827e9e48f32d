// RenderStats' sums and the table of its counters.
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast {

const std::vector<RenderCounter>& render_counters() {
    static const std::vector<RenderCounter> counters = {
        {"triangles_in", &RenderStats::triangles_in, true},
        {"triangles_culled", &RenderStats::triangles_culled, true},
        {"triangles_degenerate", &RenderStats::triangles_degenerate, true},
        {"triangles_dropped", &RenderStats::triangles_dropped, true},
        {"triangles_clipped", &RenderStats::triangles_clipped, true},
        {"triangles_outside", &RenderStats::triangles_outside, true},
        {"triangles_out_of_range", &RenderStats::triangles_out_of_range, true},
        {"triangles_between_samples", &RenderStats::triangles_between_samples, true},
        {"triangles_drawn", &RenderStats::triangles_drawn, true},
        {"triangles_sorted", &RenderStats::triangles_sorted, true},
        {"samples_covered", &RenderStats::samples_covered, false},
        {"samples_shaded", &RenderStats::samples_shaded, false},
        {"nonfinite_values_replaced", &RenderStats::nonfinite_values_replaced, false},
        {"ambient_evaluations", &RenderStats::ambient_evaluations, false},
        {"diffuse_evaluations", &RenderStats::diffuse_evaluations, false},
        {"specular_evaluations", &RenderStats::specular_evaluations, false},
        {"normal_interpolations", &RenderStats::normal_interpolations, false},
    };
    return counters;
}

RenderStats& RenderStats::operator+=(const RenderStats& other) {
    for (const RenderCounter& counter : render_counters()) this->*counter.field += other.*counter.field;
    seconds += other.seconds;
    return *this;
}

}  // namespace phongrast
