#include "aov_pass.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

// The baseline kernels' span_weights: the same operations as the fill.
#include "fill_kernels.hpp"
// VisibleLayer: the colour fill's owner buffers.
#include "fill_driver.hpp"
#include "phongrast/lighting.hpp"

namespace phongrast::detail {
namespace {

constexpr float kBackgroundDepth = std::numeric_limits<float>::infinity();
/// What a surface's depth and distance are capped at: in double precision a surface can lie
/// beyond float's range, and +infinity is the background's value.
constexpr double kLargestPlaneValue = std::numeric_limits<float>::max();

template <typename Real>
glm::vec3 world_from_camera(const CameraFrame& frame, const Vec3<Real>& camera_normal) {
    const glm::dvec3 n(camera_normal);
    return glm::vec3(frame.right * n.x + frame.up * n.y + frame.forward * n.z);
}

/// The id output of internal triangle `source`: the caller's index of it.
template <typename Real>
std::int32_t caller_id(const AovPassInput<Real>& in, std::uint32_t source) {
    return static_cast<std::int32_t>(in.original_triangle ? in.original_triangle[source] : source);
}

/// Whether a plane, or the depth buffer's test of which triangle painted a
/// sample, needs the fill's weights there. Coverage and the id alone do not.
bool needs_weights(const AovRequest& planes, const void* depth_buffer) {
    return depth_buffer != nullptr || planes.depth || planes.distance || planes.uv || planes.normal;
}

// write_triangle() when no plane needs the weights (needs_weights(); the
// thumbnail's alpha asks only for coverage): each span's samples are set,
// no weight computed.
template <typename Real>
void write_covered(const AovPassInput<Real>& in, const AovRequest& planes, const FillTriangle<Real>& draw,
                   std::uint32_t source, int row_begin, int row_end, AovSamples& out) {
    const std::size_t columns = static_cast<std::size_t>(out.columns);
    const std::int32_t id = caller_id(in, source);
    for_each_covered_span(draw.coverage, row_begin, row_end,
                          [&](int row, int first_column, int count, const std::int64_t*, const std::int64_t*) {
        const std::size_t start = static_cast<std::size_t>(row) * columns + static_cast<std::size_t>(first_column);
        std::fill_n(out.covered.begin() + static_cast<std::ptrdiff_t>(start), count, std::uint8_t{1});
        if (planes.id) std::fill_n(out.id.begin() + static_cast<std::ptrdiff_t>(start), count, id);
    });
}

// write_covered() for a whole band from the colour fill's owner buffer: a
// sample is covered where some triangle owns it, and its id is the owner's
// (the last triangle in painter's order to cover it, as the pass finds).
template <typename Real>
void write_owned(const AovPassInput<Real>& in, const AovRequest& planes, const FillTriangle<Real>* const* draws,
                 const VisibleLayer& layer, int row_begin, int row_end, AovSamples& out) {
    const std::size_t first = static_cast<std::size_t>(row_begin) * static_cast<std::size_t>(out.columns);
    const std::size_t count = static_cast<std::size_t>(row_end - row_begin) * static_cast<std::size_t>(out.columns);
    const std::uint32_t* owner = layer.owner.data();
    for (std::size_t s = 0; s < count; ++s) {
        if (owner[s] == kNoOwner) continue;
        out.covered[first + s] = 1;
        if (planes.id) {
            const std::uint32_t source = draws[owner[s]]->source;
            out.id[first + s] = caller_id(in, source);
        }
    }
}

// Writes one triangle's samples in one band. The colour fill's weights are
// recomputed with the same operations, so that with the depth buffer the
// sample's final depth identifies the triangle the fill let through: the
// last one (in painter's order) whose depth equals it, since the fill's test
// lets an equal depth overwrite.
template <typename Real, bool Perspective>
void write_triangle(const AovPassInput<Real>& in, const AovRequest& planes, const FillTriangle<Real>& draw,
                    std::uint32_t source, int row_begin, int row_end, AovSamples& out) {
    const Real inverse_area = Real(1) / static_cast<Real>(draw.coverage.area2());
    Real inverse_depth[3];
    inverse_depths(draw, inverse_depth);
    glm::vec3 flat_normal(0.0f);
    if (planes.normal && in.shader == Shader::flat) {
        const Triangle& tri = (*in.triangles)[source];
        const FrameVector<Varyings<Real>>& vertices = *in.vertices;
        flat_normal = world_from_camera(*in.frame, safe_normalize<Real>(vertices[tri[0]].normal +
                                                                        vertices[tri[1]].normal +
                                                                        vertices[tri[2]].normal));
    }
    const std::size_t columns = static_cast<std::size_t>(out.columns);
    const CameraFrame& frame = *in.frame;
    for_each_covered_span(draw.coverage, row_begin, row_end,
                          [&](int row, int first_column, int count, const std::int64_t* e, const std::int64_t* step) {
        Real q[3], dq[3];  // as the fill computes them
        span_weights<Real, Perspective>(e, step, inverse_area, inverse_depth, q, dq);
        const std::size_t row_start = static_cast<std::size_t>(row) * columns;
        for (int k = 0; k < count; ++k) {
            const std::size_t index = row_start + static_cast<std::size_t>(first_column + k);
            out.covered[index] = 1;
            // The fill's weights and depth for sample k (the same function), so that the depths compare equal.
            Real w[3];
            const Real fill_depth = sample_weights<Real, Perspective>(draw, q, dq, k, w);
            if (in.depth_buffer != nullptr && !(fill_depth == in.depth_buffer[index])) continue;
            if (planes.depth) {
                // The surface's true depth: perspective-correct whatever the shading's weights
                // (an orthographic camera's depth is affine in screen space: the fill's).
                Real surface_depth = fill_depth;
                if (!Perspective && in.frame->perspective()) {
                    Real sum = Real(0);
                    for (int i = 0; i < 3; ++i) sum += (static_cast<Real>(e[i]) + static_cast<Real>(step[i]) *
                                                        static_cast<Real>(k)) * inverse_area * inverse_depth[i];
                    surface_depth = Real(1) / sum;
                }
                out.depth[index] =
                    static_cast<float>(std::min(static_cast<double>(surface_depth), kLargestPlaneValue));
                if (planes.distance) {
                    // z_c along the ray through this sample's centre (AovPassInput::sample_offset).
                    const glm::dvec3 ray = frame.camera_ray(first_column + k + 0.5 + in.sample_offset.x,
                                                            row + 0.5 + in.sample_offset.y);
                    out.distance[index] = static_cast<float>(std::min(static_cast<double>(surface_depth) *
                                                                          glm::length(ray),
                                                                      kLargestPlaneValue));
                }
            }
            if (planes.id) {
                out.id[index] = caller_id(in, source);
            }
            if (planes.uv && in.uv_in_lit) {
                // As the textured kernels interpolate it: (w0 a + w1 b) + w2 c.
                for (int c = 0; c < 2; ++c) {
                    out.uv[index][c] = static_cast<float>((w[0] * draw.v[0]->lit[c] + w[1] * draw.v[1]->lit[c]) +
                                                          w[2] * draw.v[2]->lit[c]);
                }
            }
            if (planes.normal) {
                out.normal[index] =
                    in.shader == Shader::flat
                        ? flat_normal
                        : world_from_camera(*in.frame, safe_normalize<Real>(w[0] * draw.v[0]->normal +
                                                                            w[1] * draw.v[1]->normal +
                                                                            w[2] * draw.v[2]->normal));
            }
        }
    });
}

}  // namespace

void AovSamples::reset(int rows_, int columns_, const AovRequest& planes) {
    rows = rows_;
    columns = columns_;
    const std::size_t count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    covered.assign(count, 0);
    depth.assign(planes.depth ? count : 0, kBackgroundDepth);
    normal.assign(planes.normal ? count : 0, glm::vec3(0.0f));
    id.assign(planes.id ? count : 0, -1);
    uv.assign(planes.uv ? count : 0, glm::vec2(0.0f));
    distance.assign(planes.distance ? count : 0, kBackgroundDepth);
}

template <typename Real>
void run_aov_pass(const AovPassInput<Real>& in, const AovRequest& planes, AovSamples& out,
                  ProgressMonitor& progress) {
    const Bins<Real>& bins = *in.bins;
    const bool weighted = needs_weights(planes, in.depth_buffer);
    progress.begin_stage(0.9, 1.0, static_cast<std::size_t>(bins.bands));
    tbb::parallel_for(0, bins.bands, [&](int band) {
        if (progress.cancelled()) return;
        const int row_begin = band * kBandRows;
        const int row_end = std::min(out.rows, row_begin + kBandRows);
        const FillTriangle<Real>* const* draws = bins.band_draws(band);
        if (!weighted && in.band_layers != nullptr) {
            write_owned(in, planes, draws, in.band_layers[band], row_begin, row_end, out);
            progress.piece_done();
            return;
        }
        for (std::uint32_t i = 0; i < bins.band_size(band); ++i) {
            const FillTriangle<Real>& draw = *draws[i];
            if (!weighted) {
                write_covered(in, planes, draw, draw.source, row_begin, row_end, out);
            } else if (in.perspective) {
                write_triangle<Real, true>(in, planes, draw, draw.source, row_begin, row_end, out);
            } else {
                write_triangle<Real, false>(in, planes, draw, draw.source, row_begin, row_end, out);
            }
        }
        progress.piece_done();
    });
    progress.throw_if_cancelled();
}

template void run_aov_pass<float>(const AovPassInput<float>&, const AovRequest&, AovSamples&, ProgressMonitor&);
template void run_aov_pass<double>(const AovPassInput<double>&, const AovRequest&, AovSamples&, ProgressMonitor&);

AovRequest sample_planes_for(const AovRequest& requested, int factor) {
    AovRequest planes = requested;
    // Distance is z_c times the sample's ray length: it needs the depth even with one sample.
    if ((factor > 1 && (requested.normal || requested.id || requested.uv)) || requested.distance) planes.depth = true;
    return planes;
}

void reset_aov_planes(int rows, int columns, const AovRequest& planes, AovPlanes& out) {
    out.rows = rows;
    out.columns = columns;
    const std::size_t count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    out.depth.assign(planes.depth ? count : 0, kBackgroundDepth);
    out.normal.assign(planes.normal ? count : 0, glm::vec3(0.0f));
    out.id.assign(planes.id ? count : 0, -1);
    out.uv.assign(planes.uv ? count : 0, glm::vec2(0.0f));
    out.distance.assign(planes.distance ? count : 0, kBackgroundDepth);
    out.alpha.assign(planes.alpha ? count : 0, 0.0f);
}

void resolve_aovs(const AovSamples& samples, int factor, const AovRequest& planes, AovPlanes& out) {
    for (int row = 0; row < out.rows; ++row) {
        for (int column = 0; column < out.columns; ++column) {
            const std::size_t pixel = static_cast<std::size_t>(row) * static_cast<std::size_t>(out.columns) +
                                      static_cast<std::size_t>(column);
            // What earlier rotated-grid passes found stays unless a sample is strictly nearer.
            float nearest = out.depth.empty() ? kBackgroundDepth : out.depth[pixel];
            std::size_t chosen = SIZE_MAX;
            int covered = 0;
            for (int dy = 0; dy < factor; ++dy) {
                for (int dx = 0; dx < factor; ++dx) {
                    const std::size_t sample =
                        static_cast<std::size_t>(row * factor + dy) * static_cast<std::size_t>(samples.columns) +
                        static_cast<std::size_t>(column * factor + dx);
                    if (!samples.covered[sample]) continue;
                    ++covered;
                    // No depth plane: one sample per pixel and one pass (sample_planes_for), so it is the nearest.
                    if (samples.depth.empty() || samples.depth[sample] < nearest) {
                        nearest = samples.depth.empty() ? nearest : samples.depth[sample];
                        chosen = sample;
                    }
                }
            }
            if (planes.alpha) out.alpha[pixel] += static_cast<float>(covered);  // a count until finish_aovs
            if (chosen == SIZE_MAX) continue;
            if (planes.depth) out.depth[pixel] = samples.depth[chosen];
            if (planes.normal) out.normal[pixel] = samples.normal[chosen];
            if (planes.id) out.id[pixel] = samples.id[chosen];
            if (planes.uv) out.uv[pixel] = samples.uv[chosen];
            if (planes.distance) out.distance[pixel] = samples.distance[chosen];
        }
    }
}

void finish_aovs(const AovRequest& requested, int samples_per_pixel, AovPlanes& out) {
    // Counts are whole numbers below 2^24: one division gives the exact nearest fraction.
    for (float& alpha : out.alpha) alpha /= static_cast<float>(samples_per_pixel);
    if (!requested.depth) out.depth.clear();  // used only to choose the nearest sample
}

}  // namespace phongrast::detail
