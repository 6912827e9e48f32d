// Two renders that must count alike (two paths to one picture: a Renderer
// and render(), painter's fill and the fill in mesh order): every counter
// of RenderStats but the times.
#ifndef PHONGRAST_TESTS_SAME_RENDER_STATS_HPP
#define PHONGRAST_TESTS_SAME_RENDER_STATS_HPP

#include <catch2/catch.hpp>

#include "phongrast/render.hpp"

inline void check_same_render_stats(const phongrast::RenderStats& a, const phongrast::RenderStats& b) {
    CHECK(a.triangles_in == b.triangles_in);
    CHECK(a.triangles_culled == b.triangles_culled);
    CHECK(a.triangles_degenerate == b.triangles_degenerate);
    CHECK(a.triangles_dropped == b.triangles_dropped);
    CHECK(a.triangles_clipped == b.triangles_clipped);
    CHECK(a.triangles_outside == b.triangles_outside);
    CHECK(a.triangles_out_of_range == b.triangles_out_of_range);
    CHECK(a.triangles_between_samples == b.triangles_between_samples);
    CHECK(a.triangles_drawn == b.triangles_drawn);
    CHECK(a.triangles_sorted == b.triangles_sorted);
    CHECK(a.samples_covered == b.samples_covered);
    CHECK(a.samples_shaded == b.samples_shaded);
    CHECK(a.nonfinite_values_replaced == b.nonfinite_values_replaced);
    CHECK(a.ambient_evaluations == b.ambient_evaluations);
    CHECK(a.diffuse_evaluations == b.diffuse_evaluations);
    CHECK(a.specular_evaluations == b.specular_evaluations);
    CHECK(a.normal_interpolations == b.normal_interpolations);
}

#endif  // PHONGRAST_TESTS_SAME_RENDER_STATS_HPP
