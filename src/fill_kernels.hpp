// Fill kernels: one per shader and effect set, chosen once per render
// (internal header).
//
// A kernel walks the covered samples of one triangle in one band of rows,
// computes its interpolation weights and writes a colour. The lighting terms
// a kernel evaluates are template parameters, so no per-sample branch asks
// which terms are on; the general kernel (RenderOptions::specialize_effects =
// false) does ask, and exists to prove the specialised ones change nothing.
#ifndef PHONGRAST_SRC_FILL_KERNELS_HPP
#define PHONGRAST_SRC_FILL_KERNELS_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "fill_dispatch.hpp"

// This header is compiled once per instruction set: fill_kernels_baseline.hpp
// includes it as it is; fill_kernels_avx2.hpp defines these two macros and
// compiles it again for AVX2. Each compilation lives in its own namespace, so
// no kernel of one instruction set can stand in for another's at link time.
#ifndef PHONGRAST_FILL_ISA
#define PHONGRAST_FILL_ISA baseline
#endif
#ifndef PHONGRAST_FILL_VECTOR_BYTES
#define PHONGRAST_FILL_VECTOR_BYTES 16  // SSE2
#endif

#include "fill_phong_lanes.hpp"
#include "fill_span_writers.hpp"

namespace phongrast::detail {
inline namespace PHONGRAST_FILL_ISA {

/// 1 / depth of each corner, for perspective-correct weights.
template <typename Real>
PHONGRAST_FILL_INLINE void inverse_depths(const FillTriangle<Real>& draw, Real* inverse) {
    for (int i = 0; i < 3; ++i) inverse[i] = Real(1) / draw.depth[i];
}

/// A vertex's interpolation weight where its edge value is `edge` (or its
/// change per column where `edge` is the edge's step): the screen-space
/// weight, divided by the vertex's depth when perspective-correct.
template <typename Real, bool Perspective>
inline Real edge_weight(std::int64_t edge, Real inverse_area, Real inverse_depth) {
    Real q = static_cast<Real>(edge) * inverse_area;
    if constexpr (Perspective) q *= inverse_depth;
    return q;
}

/// The interpolation weights q at a span's first sample and their step dq per
/// column, from the exact edge values e and steps.
template <typename Real, bool Perspective>
inline void span_weights(const std::int64_t* e, const std::int64_t* step, Real inverse_area,
                         const Real* inverse_depth, Real* q, Real* dq) {
    for (int i = 0; i < 3; ++i) {
        q[i] = edge_weight<Real, Perspective>(e[i], inverse_area, inverse_depth[i]);
        dq[i] = edge_weight<Real, Perspective>(step[i], inverse_area, inverse_depth[i]);
    }
}

/// The interpolation weights w of sample k of a span (q and dq from
/// span_weights()) and the sample's depth: perspective-correct weights are
/// renormalised by their sum, whose inverse is the depth. The fill and the
/// extra outputs' pass both use it, so their depths compare equal.
template <typename Real, bool Perspective>
PHONGRAST_FILL_INLINE Real sample_weights(const Real* corner_depth, const Real* q, const Real* dq, int k, Real* w) {
    for (int i = 0; i < 3; ++i) w[i] = q[i] + dq[i] * static_cast<Real>(k);
    if constexpr (Perspective) {
        const Real depth = Real(1) / (w[0] + w[1] + w[2]);
        for (int i = 0; i < 3; ++i) w[i] *= depth;
        return depth;
    } else {
        return w[0] * corner_depth[0] + w[1] * corner_depth[1] + w[2] * corner_depth[2];
    }
}
template <typename Real, bool Perspective>
PHONGRAST_FILL_INLINE Real sample_weights(const FillTriangle<Real>& draw, const Real* q, const Real* dq, int k,
                                          Real* w) {
    return sample_weights<Real, Perspective>(draw.depth, q, dq, k, w);
}

/// span_weights() for the kernels: dq is the same for every span of a
/// triangle, so it is computed once, and the kernels set it up at the first
/// covered span, so that the many tiny triangles that cover no sample pay
/// none of its divisions. (Set up by a call, not held in a std::optional,
/// whose code is compiled for the baseline instruction set.)
template <typename Real, bool Perspective>
class SpanWeights {
public:
    PHONGRAST_FILL_INLINE void set_up(const FillTriangle<Real>& draw, const std::int64_t* step) {
        inverse_area_ = Real(1) / static_cast<Real>(draw.coverage.area2());
        if constexpr (Perspective) inverse_depths(draw, inverse_depth_);
        for (int i = 0; i < 3; ++i) {
            dq_[i] = edge_weight<Real, Perspective>(step[i], inverse_area_, inverse_depth_[i]);
        }
    }
    /// The weights at a span's first sample, whose edge values are e.
    PHONGRAST_FILL_INLINE void at(const std::int64_t* e, Real* q) const {
        for (int i = 0; i < 3; ++i) {
            q[i] = edge_weight<Real, Perspective>(e[i], inverse_area_, inverse_depth_[i]);
        }
    }
    const Real* step() const { return dq_; }

private:
    Real inverse_area_ = Real(0);
    Real inverse_depth_[3] = {Real(1), Real(1), Real(1)};
    Real dq_[3] = {};
};

/// for_each_weighted_span() for a triangle that is not tiny: row by row, each
/// span solved from the edge functions (by masks, the rows' values carried
/// from row to row: in-process A/B, 1 thread, 512²: Gouraud 0.95-0.97, flat
/// 0.92, Phong 0.98-1.00; 125k 0.97-0.98). Kept out of line, so that the
/// tiny triangles' path keeps its values in registers.
template <typename Real, bool Perspective, typename Visit>
PHONGRAST_NOINLINE void for_each_weighted_row(const CoveredRows& rows, const FillTriangle<Real>& draw,
                                              Visit& visit) {
    SpanWeights<Real, Perspective> weights;
    bool weights_set_up = false;
    Real q[3];
    const auto visit_span = [&](const CoveredSpan& span) PHONGRAST_INLINE_LAMBDA {
        if (!weights_set_up) {
            weights.set_up(draw, rows.step());
            weights_set_up = true;
        }
        weights.at(span.e, q);
        visit(span.row, span.first_column, span.count, q, weights.step());
    };
#if PHONGRAST_ROW_MASKS
    if (rows.solves_rows_by_masks()) {
        CoveredRows::MaskedRows masked(rows);
        for (int row = rows.first_row(); row <= rows.last_row(); ++row) {
            CoveredSpan span;
            if (masked.solve_and_advance(row, span)) visit_span(span);
        }
        return;
    }
#endif
    for (int row = rows.first_row(); row <= rows.last_row(); ++row) {
        CoveredSpan span;
        if (rows.solve(row, span)) visit_span(span);
    }
}

/// Calls visit(row, first_column, count, q, dq) for every span of samples
/// the triangle covers in the target's rows, with SpanWeights' q and dq.
/// Defined here, not in raster.hpp, so that it is compiled with the kernels'
/// instruction set and the kernel's visitor inlines into it. A triangle whose
/// bounding box holds at most 2 x 2 samples (most triangles of a large mesh)
/// has them tested directly.
template <typename Real, bool Perspective, typename Visit>
PHONGRAST_FILL_INLINE void for_each_weighted_span(const FillTriangle<Real>& draw,
                                                  const FillTarget<Real>& target, Visit&& visit) {
    const CoveredRows rows(draw.coverage, target.row_begin, target.row_end);
    if (rows.empty()) return;
    if (!rows.tiny()) {
        for_each_weighted_row<Real, Perspective>(rows, draw, visit);
        return;
    }
    CoveredSpan spans[2];
    const int found = rows.tiny_spans(spans);
    if (found == 0) return;
    SpanWeights<Real, Perspective> weights;
    weights.set_up(draw, rows.step());
    Real q[3];
    for (int s = 0; s < found; ++s) {
        weights.at(spans[s].e, q);
        visit(spans[s].row, spans[s].first_column, spans[s].count, q, weights.step());
    }
}

/// fill_samples()' shade_lanes, or paint_span, for a kernel without them:
/// flat has no batches (the batches' weights would cost more than they save
/// on its one colour; measured on the teapot), and only the kernels of
/// fill_span_writers.hpp's writers (AVX2, float) have span writers.
struct NoLanes {};

/// Lanes a batch's loops run over: the batch's samples rounded up to a whole
/// number of vector groups (8 floats for AVX2), so that each loop is whole
/// vectors with no remainder code, whose branches on the varying span
/// lengths cost more than the few lanes computed for nothing.
constexpr int kLaneGroup = 8;
inline int padded_lanes(int n) { return (n + kLaneGroup - 1) / kLaneGroup * kLaneGroup; }
static_assert(kSampleBatch % kLaneGroup == 0, "a batch is whole lane groups");

/// Whether any of the first n of a batch's `lanes` pixels (float channels)
/// is not finite: std::isfinite(sum), as finite_or_replaced() asks, written
/// as a compare that vectorises.
PHONGRAST_FILL_INLINE bool any_nonfinite(int lanes, int n, const float (*channel)[kSampleBatch]) {
    int nonfinite = 0;
    for (int l = 0; l < lanes; ++l) {
        const float sum = channel[0][l] + channel[1][l] + channel[2][l];
        nonfinite |= int(l < n) & int(!(std::abs(sum) <= std::numeric_limits<float>::max()));
    }
    return nonfinite != 0;
}

/// Shades `count` samples of one span, starting at `pixels`, in batches:
/// the weights of sample k are fill_samples()'s (q + dq k, renormalised when
/// perspective-correct: the same operations in the same order, lane by
/// lane), then shade_lanes(n, w, out), then the pixels are written as
/// fill_samples() writes them. The lanes past the span's end (up to
/// padded_lanes()) are computed like the others and never read: whatever
/// they hold (their weights may even divide by zero) is neither written nor
/// counted. All lanes finite (the case that should always hold) is checked
/// in a vector loop first. Out of line, so that the sample-by-sample loop of
/// the short spans keeps its registers.
template <typename Real, bool Perspective, typename ShadeLanes, typename Store>
PHONGRAST_FILL_INLINE void shade_span_lanes(const Real* q, const Real* dq, int count, ShadeLanes& shade_lanes,
                                            Store&& store) {
    Lanes<Real> w[3], out[3];
    for (int start = 0; start < count; start += kSampleBatch) {
        const int n = std::min(kSampleBatch, count - start);
        const int lanes = padded_lanes(n);
        for (int l = 0; l < lanes; ++l) {
            const Real step_count = static_cast<Real>(start + l);
            w[0][l] = q[0] + dq[0] * step_count;
            w[1][l] = q[1] + dq[1] * step_count;
            w[2][l] = q[2] + dq[2] * step_count;
        }
        if constexpr (Perspective) {
            for (int l = 0; l < lanes; ++l) {
                const Real depth = Real(1) / (w[0][l] + w[1][l] + w[2][l]);
                w[0][l] *= depth;
                w[1][l] *= depth;
                w[2][l] *= depth;
            }
        }
        shade_lanes(lanes, static_cast<const Lanes<Real>*>(w), out);
        if constexpr (std::is_same_v<Real, float>) {
            // The shaded lanes are the pixels' floats already: handed on as they are. (A copy to a
            // channel array, as double needs, became three `rep movsq` of up to 128 bytes each, whose
            // start-up cost was 10% of a 512² Gouraud frame.)
            store(start, n, static_cast<const float(*)[kSampleBatch]>(out), any_nonfinite(lanes, n, out));
        } else {
            float channel[3][kSampleBatch];
            for (int c = 0; c < 3; ++c) {
                for (int l = 0; l < lanes; ++l) channel[c][l] = static_cast<float>(out[c][l]);
            }
            store(start, n, static_cast<const float(*)[kSampleBatch]>(channel), any_nonfinite(lanes, n, channel));
        }
    }
}


/// Shades a span in batches (shade_span_lanes()) and writes every sample,
/// or, given `owners` (the span's owner row, nearest first), only those it
/// has claimed: whose owner is `self`.
template <typename Real, bool Perspective, typename ShadeLanes>
PHONGRAST_NOINLINE void fill_span_lanes(const Real* q, const Real* dq, int count, glm::vec3* pixels,
                                        std::uint64_t& replaced, ShadeLanes& shade_lanes,
                                        const std::uint32_t* owners = nullptr, std::uint32_t self = 0) {
    shade_span_lanes<Real, Perspective>(
        q, dq, count, shade_lanes,
        [&](int start, int n, const float (*channel)[kSampleBatch], bool nonfinite) PHONGRAST_INLINE_LAMBDA {
        glm::vec3* batch_pixels = pixels + start;
        if (!nonfinite && owners == nullptr) {
#if PHONGRAST_FILL_VECTOR_BYTES == 32
            store_pixels_interleaved(batch_pixels, n, channel);
#else
            for (int l = 0; l < n; ++l) batch_pixels[l] = glm::vec3(channel[0][l], channel[1][l], channel[2][l]);
#endif
        } else {
            for (int l = 0; l < n; ++l) {
                if (owners != nullptr && owners[start + l] != self) continue;
                batch_pixels[l] =
                    finite_or_replaced(glm::vec3(channel[0][l], channel[1][l], channel[2][l]), replaced);
            }
        }
    });
}

/// fill_ranked_span()'s loop (`Ties`: write_ranked()).
template <bool Ties, typename Real, bool Perspective, typename Shade>
PHONGRAST_FILL_INLINE void fill_ranked_samples(const Real* corner_depth, FillTarget<Real>& target,
                                               std::size_t start, int count, const Real* q, const Real* dq,
                                               Shade& shade) {
    write_ranked<Ties>(target, start, count, [&](int k) PHONGRAST_INLINE_LAMBDA {
        Real w[3];
        sample_weights<Real, Perspective>(corner_depth, q, dq, k, w);
        return finite_or_replaced(glm::vec3(shade(w)), target.replaced);
    });
}

/// fill_ranked_span()'s long spans: shaded in batches as fill_span_lanes()
/// shades them (the same bits as sample by sample), each sample then written
/// by write_ranked().
template <bool Ties, typename Real, bool Perspective, typename ShadeLanes>
PHONGRAST_NOINLINE void fill_ranked_span_lanes(FillTarget<Real>& target, std::size_t start, int count,
                                               const Real* q, const Real* dq, ShadeLanes& shade_lanes) {
    shade_span_lanes<Real, Perspective>(
        q, dq, count, shade_lanes,
        [&](int batch, int n, const float (*channel)[kSampleBatch], bool nonfinite) PHONGRAST_INLINE_LAMBDA {
        write_ranked<Ties>(target, start + static_cast<std::size_t>(batch), n, [&](int l) PHONGRAST_INLINE_LAMBDA {
            const glm::vec3 colour(channel[0][l], channel[1][l], channel[2][l]);
            return nonfinite ? finite_or_replaced(colour, target.replaced) : colour;
        });
    });
    target.samples += static_cast<std::uint64_t>(count);
}

/// One span of fill_samples() when painter's order is a test per sample
/// (FillTarget::rank_keys): every sample is shaded as painter's fill shades
/// it (the same weights, counted alike), and written only where this draw's
/// rank is higher than the rank of the colour the sample holds, so that each
/// sample ends with the colour of the triangle painter's order draws there
/// last, whatever order the draws come in. Kept out of line: the painter's
/// fill does not carry its registers.
template <typename Real, bool Perspective, typename Shade>
PHONGRAST_NOINLINE void fill_ranked_span(const Real* corner_depth, FillTarget<Real>& target,
                                         std::size_t row_start, int first_column, int count, const Real* q,
                                         const Real* dq, Shade& shade) {
    const std::size_t start = row_start + static_cast<std::size_t>(first_column);
    if (target.rank_ties != nullptr) {
        fill_ranked_samples<true, Real, Perspective>(corner_depth, target, start, count, q, dq, shade);
    } else {
        fill_ranked_samples<false, Real, Perspective>(corner_depth, target, start, count, q, dq, shade);
    }
    target.samples += static_cast<std::uint64_t>(count);
}

/// Visits the triangle's covered samples in the target's rows with
/// interpolation weights w (summing to 1 up to rounding) and writes shade(w)
/// there. Each span starts from weights derived from exact edge values and
/// steps them by a constant per column. Long spans painted whole go through
/// shade_lanes(n, w, out) instead (fill_span_lanes()), which must give lane
/// for lane what shade(w) gives. A kernel with span writers of its own
/// (`paint_span`, NoLanes if none: fill_span_writers.hpp) hands them every
/// span painted whole, of any length (whole()), and in the fill in mesh order
/// every span first (ranked(), which may decline: the paths below then take
/// it), with the same duty.
template <typename Real, bool Perspective, typename Shade, typename ShadeLanes, typename PaintSpan = NoLanes>
PHONGRAST_FILL_INLINE void fill_samples(const FillTriangle<Real>& draw, FillTarget<Real>& target, Shade&& shade,
                                        ShadeLanes&& shade_lanes, PaintSpan&& paint_span = PaintSpan{}) {
    Image& image = target.image;
    for_each_weighted_span<Real, Perspective>(
        draw, target,
        [&](int row, int first_column, int count, const Real* q, const Real* dq) PHONGRAST_INLINE_LAMBDA {
        const std::size_t row_start = static_cast<std::size_t>(row) * static_cast<std::size_t>(image.columns);
        std::uint32_t* owners = owner_row(target, row);
        target.covered += static_cast<std::uint64_t>(count);
        if (target.rank_keys != nullptr) {
            if constexpr (!std::is_same_v<std::decay_t<PaintSpan>, NoLanes>) {
                const std::size_t start = row_start + static_cast<std::size_t>(first_column);
                if (target.rank_ties != nullptr ? paint_span.template ranked<true>(target, start, count, q, dq)
                                                : paint_span.template ranked<false>(target, start, count, q, dq)) {
                    return;
                }
            }
            if constexpr (!std::is_same_v<std::decay_t<ShadeLanes>, NoLanes>) {
                if (count >= kMinLanesSpan) {
                    const std::size_t start = row_start + static_cast<std::size_t>(first_column);
                    if (target.rank_ties != nullptr) {
                        fill_ranked_span_lanes<true, Real, Perspective>(target, start, count, q, dq, shade_lanes);
                    } else {
                        fill_ranked_span_lanes<false, Real, Perspective>(target, start, count, q, dq, shade_lanes);
                    }
                    return;
                }
            }
            fill_ranked_span<Real, Perspective>(draw.depth, target, row_start, first_column, count, q, dq, shade);
            return;
        }
        if constexpr (!std::is_same_v<std::decay_t<PaintSpan>, NoLanes>) {
            if (owners == nullptr && !target.depth_test) {
                glm::vec3* pixels = &image.pixels[row_start + static_cast<std::size_t>(first_column)];
                paint_span.whole(q, dq, count, pixels, target.replaced);
                target.samples += static_cast<std::uint64_t>(count);
                return;
            }
        }
        if constexpr (!std::is_same_v<std::decay_t<ShadeLanes>, NoLanes>) {
            if (owners == nullptr && !target.depth_test && count >= kMinLanesSpan) {
                glm::vec3* pixels = &image.pixels[row_start + static_cast<std::size_t>(first_column)];
                fill_span_lanes<Real, Perspective>(q, dq, count, pixels, target.replaced, shade_lanes);
                target.samples += static_cast<std::uint64_t>(count);
                return;
            }
            if (owners != nullptr && count >= kMinLanesSpan) {
                // The samples no nearer draw has claimed: a span hidden whole costs no shading.
                std::uint32_t* span_owners = owners + first_column;
                const int claimed = claim_span(span_owners, count, target.self);
                if (claimed == 0) return;
                glm::vec3* pixels = &image.pixels[row_start + static_cast<std::size_t>(first_column)];
                fill_span_lanes<Real, Perspective>(q, dq, count, pixels, target.replaced, shade_lanes,
                                                   claimed == count ? nullptr : span_owners, target.self);
                target.samples += static_cast<std::uint64_t>(claimed);
                return;
            }
        }
        std::uint64_t written = 0;
        for (int k = 0; k < count; ++k) {
            // Painted over later: skipped. The weights below depend on k only, not on what was skipped.
            if (owners != nullptr && !claims_sample(owners, first_column + k, target.self)) continue;
            Real w[3];
            const Real depth = sample_weights<Real, Perspective>(draw, q, dq, k, w);
            const std::size_t index = row_start + static_cast<std::size_t>(first_column + k);
            if (target.depth_test) {
                // <= lets a later triangle at equal depth win, as in painter's order.
                if (!(depth <= target.depth_buffer[index])) continue;
                target.depth_buffer[index] = depth;
            }
            image.pixels[index] = finite_or_replaced(glm::vec3(shade(w)), target.replaced);
            ++written;
        }
        target.samples += written;
    });
}

template <typename Real>
Vec3<Real> interpolate_lit(const FillTriangle<Real>& d, const Real* w) {
    return w[0] * d.lit[0] + w[1] * d.lit[1] + w[2] * d.lit[2];
}

/// interpolate_lit() for a batch: lane by lane the same products and sums
/// ((w0 a + w1 b) + w2 c per channel).
template <typename Real>
PHONGRAST_FILL_INLINE void interpolate_lit_lanes(const FillTriangle<Real>& d, int n, const Lanes<Real>* w,
                                                 Lanes<Real>* out) {
    for (int c = 0; c < 3; ++c) interpolate_lanes(n, w, d.lit[0][c], d.lit[1][c], d.lit[2][c], out[c]);
}


/// Gouraud: the colour was lit per vertex; interpolate it. The AVX2 kernels
/// in float paint whole spans with their own vector code (spans of 1-3
/// samples in four lanes, longer ones eight at a time), which GCC's code of
/// the generic batches (fill_span_lanes()) and sample-by-sample loop did not
/// match: in-process A/B, alternating frames, 512x512, 1 thread: 0.95-0.97
/// for the short spans, then 0.94-0.98 for the long ones.
template <typename Real, bool Perspective>
void fill_lit(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
              const FillConstants<Real>&) {
    const auto shade = [&](const Real* w) { return interpolate_lit(draw, w); };
    const auto shade_lanes = [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        interpolate_lit_lanes(draw, n, w, out);
    };
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        const InterpolatedSpans<Perspective, false> spans{{{&draw.lit[0], &draw.lit[1], &draw.lit[2]}}};
        fill_samples<Real, Perspective>(draw, target, shade, shade_lanes, spans);
        return;
    }
#endif
    fill_samples<Real, Perspective>(draw, target, shade, shade_lanes);
}

/// Flat: the triangle's one colour, written as is. (Interpolating it like
/// Gouraud would give weights summing to 1 only up to rounding, so the colour
/// would wander by an ulp across the triangle.)
template <typename Real, bool Perspective>
void fill_flat(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
               const FillConstants<Real>&) {
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        fill_samples<Real, Perspective>(draw, target, [&](const Real*) { return draw.lit[0]; }, NoLanes{},
                                        FlatSpans{draw.lit[0]});
        return;
    }
#endif
    fill_samples<Real, Perspective>(draw, target, [&](const Real*) { return draw.lit[0]; }, NoLanes{});
}

/// Visits the triangle's covered samples in the target's rows (only those
/// it owns, with an owner buffer), gathering up to room() of them (across
/// rows) with their weights as fill_samples computes them, renormalised, and
/// their depths, then calls commit(n, w, depth, index) and gathers again.
/// Gathering across a triangle's rows keeps batches full for small
/// triangles, whose spans are only a few samples long.
template <typename Real, bool Perspective, typename Room, typename Commit>
PHONGRAST_FILL_INLINE void gather_sample_batches(const FillTriangle<Real>& draw, FillTarget<Real>& target, Room&& room,
                                                 Commit&& commit) {
    const Image& image = target.image;
    Lanes<Real> w[3], depth;
    std::size_t index[kSampleBatch];
    // A batch's first kGatherGroup lanes hold values, samples or zeros, so that
    // a small batch can be read as a whole vector group (add_pending_samples()).
    for (int l = 0; l < kGatherGroup; ++l) {
        w[0][l] = w[1][l] = w[2][l] = depth[l] = Real(0);
        index[l] = 0;
    }
    int n = 0;
    int limit = room();
    const auto flush = [&] {
        if constexpr (Perspective) {
            // Weights linear in the triangle's plane: renormalise the depth-divided ones.
            for (int l = 0; l < n; ++l) {
                depth[l] = Real(1) / (w[0][l] + w[1][l] + w[2][l]);
                w[0][l] *= depth[l];
                w[1][l] *= depth[l];
                w[2][l] *= depth[l];
            }
        } else {
            for (int l = 0; l < n; ++l) {
                depth[l] = w[0][l] * draw.depth[0] + w[1][l] * draw.depth[1] + w[2][l] * draw.depth[2];
            }
        }
        commit(n, static_cast<const Lanes<Real>*>(w), static_cast<const Real*>(depth),
               static_cast<const std::size_t*>(index));
        n = 0;
        limit = room();
    };
    for_each_weighted_span<Real, Perspective>(
        draw, target,
        [&](int row, int first_column, int count, const Real* q, const Real* dq) PHONGRAST_INLINE_LAMBDA {
        const std::size_t row_start = static_cast<std::size_t>(row) * static_cast<std::size_t>(image.columns) +
                                      static_cast<std::size_t>(first_column);
        std::uint32_t* owners = owner_row(target, row);
        if (owners != nullptr) owners += first_column;
        target.covered += static_cast<std::uint64_t>(count);
        for (int k = 0; k < count; ++k) {
            // Painted over later: skipped. A sample's weights depend on k only, not on the batch it joins.
            if (owners != nullptr && !claims_sample(owners, k, target.self)) continue;
            const Real step_count = static_cast<Real>(k);
            w[0][n] = q[0] + dq[0] * step_count;
            w[1][n] = q[1] + dq[1] * step_count;
            w[2][n] = q[2] + dq[2] * step_count;
            index[n] = row_start + static_cast<std::size_t>(k);
            if (++n == limit) flush();
        }
    });
    if (n > 0) flush();
}

/// Writes n shaded samples (out) at `index`, with the depth test when the
/// target has one, counting them; lane order is write order.
template <typename Real>
PHONGRAST_FILL_INLINE void write_shaded(FillTarget<Real>& target, int n, const Real* depth, const std::size_t* index,
                                        const Lanes<Real>* out) {
    Image& image = target.image;
    for (int l = 0; l < n; ++l) {
        if (target.depth_test) {
            // <= lets a later triangle at equal depth win, as in painter's order.
            if (!(depth[l] <= target.depth_buffer[index[l]])) continue;
            target.depth_buffer[index[l]] = depth[l];
        }
        const glm::vec3 pixel(static_cast<float>(out[0][l]), static_cast<float>(out[1][l]),
                              static_cast<float>(out[2][l]));
        image.pixels[index[l]] = finite_or_replaced(pixel, target.replaced);
        ++target.samples;
    }
}

/// Gathers the triangle's samples kSampleBatch at a time (gather_sample_batches()),
/// calls shade_batch(n, w, out) on each batch and writes it.
template <typename Real, bool Perspective, typename ShadeBatch>
void fill_sample_batches(const FillTriangle<Real>& draw, FillTarget<Real>& target, ShadeBatch&& shade_batch) {
    gather_sample_batches<Real, Perspective>(
        draw, target, [] { return kSampleBatch; },
        [&](int n, const Lanes<Real>* w, const Real* depth, const std::size_t* index) {
            Lanes<Real> out[3];
            shade_batch(n, w, out);
            write_shaded(target, n, depth, index, out);
        });
}

/// Gouraud on a textured face, n samples at a time (structure of arrays, as
/// shade_phong_batch() shades): (s, t), S and A interpolated in vector
/// loops, then T (filtered_texel_lanes()) and T x A + S in vector loops. Per lane the same operations in the
/// same order as one sample at a time: (w0 a + w1 b) + w2 c for each
/// attribute, T[c] * A[c] + S[c].
template <typename Real>
PHONGRAST_FILL_INLINE void shade_lit_textured_lanes(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w,
                                                    const KernelTexture& texture, Lanes<Real>* out) {
    Lanes<Real> s, t, specular[3];
    interpolate_lanes(n, w, draw.v[0]->lit[0], draw.v[1]->lit[0], draw.v[2]->lit[0], s);
    interpolate_lanes(n, w, draw.v[0]->lit[1], draw.v[1]->lit[1], draw.v[2]->lit[1], t);
    for (int c = 0; c < 3; ++c) {
        interpolate_lanes(n, w, draw.v[0]->color[c], draw.v[1]->color[c], draw.v[2]->color[c], specular[c]);
        interpolate_lanes(n, w, draw.lit[0][c], draw.lit[1][c], draw.lit[2][c], out[c]);  // A
    }
    Lanes<Real> texel[3];
    filtered_texel_lanes(draw, n, w, s, t, texture, texel);
    for (int c = 0; c < 3; ++c) {
        for (int l = 0; l < n; ++l) out[c][l] = texel[c][l] * out[c][l] + specular[c][l];
    }
}

/// Gouraud on a textured face (contract "Texture maps"): A and S lit at the
/// corners and interpolated, the pixel T x A + S, with T at the sample's
/// (s, t) interpolated alike. Set-up put A in the draw's lit[i], S in the
/// corners' `color` and (s, t) in their `lit`. The samples go through in
/// batches (fill_sample_batches(): the same weights and depths as
/// fill_samples() computes). A face without a texture carries its whole lit
/// colour in lit[i] and is filled as fill_lit() fills it.
template <typename Real, bool Perspective>
void fill_lit_textured(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                       const FillConstants<Real>& constants) {
    const KernelTexture& texture = constants.textures[draw.surface];
    if (texture.texels == nullptr) {
        fill_lit<Real, Perspective>(draw, target, vectors, constants);
        return;
    }
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        shade_lit_textured_lanes(draw, n, w, texture, out);
    });
}

/// Flat on a textured face: the triangle's colour-carrying part A (lit[0])
/// times T at the sample, plus its specular part S (lit[1]); in batches, as
/// fill_lit_textured() goes, with (s, t) interpolated in vector loops and
/// per lane T[c] * A[c] + S[c], as one sample at a time. A face without a
/// texture writes its one colour as fill_flat() does (set-up put it in lit[0]).
template <typename Real, bool Perspective>
void fill_flat_textured(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                        const FillConstants<Real>& constants) {
    const KernelTexture& texture = constants.textures[draw.surface];
    if (texture.texels == nullptr) {
        fill_flat<Real, Perspective>(draw, target, vectors, constants);
        return;
    }
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        Lanes<Real> s, t;
        interpolate_lanes(n, w, draw.v[0]->lit[0], draw.v[1]->lit[0], draw.v[2]->lit[0], s);
        interpolate_lanes(n, w, draw.v[0]->lit[1], draw.v[1]->lit[1], draw.v[2]->lit[1], t);
        Lanes<Real> texel[3];
        filtered_texel_lanes(draw, n, w, s, t, texture, texel);
        for (int c = 0; c < 3; ++c) {
            const Real colour_part = draw.lit[0][c], specular_part = draw.lit[1][c];  // locals: see fill_phong_lanes.hpp
            for (int l = 0; l < n; ++l) out[c][l] = texel[c][l] * colour_part + specular_part;
        }
    });
}

/// Phong compiled for one effect set. Without diffuse or specular it interpolates no normal.
template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular, bool PerSampleVectors,
          bool UniformColor>
void fill_phong(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                const FillConstants<Real>& constants) {
    constexpr bool kNormals = Diffuse || Specular;
    const LightRig<Real>& rig = constants.rig_of(draw);
    if constexpr (kNormals && !PerSampleVectors) vectors.compute(rig.active_lights, draw.centroid(), Specular, rig.eye_at_infinity);
    const FixedTerms<Ambient, Diffuse, Specular> terms;
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        shade_phong_samples<Real, PerSampleVectors, UniformColor>(draw, n, w, terms, rig.active_lights, vectors, constants,
                                                                out);
    });
}

/// Shades the samples waiting in `pending` and writes them (in the order they joined).
template <typename Real, bool Ambient, bool Diffuse, bool Specular, bool UniformColor>
void shade_and_write_pending(PendingPhongSamples<Real>& pending, FillTarget<Real>& target) {
    Lanes<Real> out[3];
    shade_pending_phong<Real, UniformColor, FixedTerms<Ambient, Diffuse, Specular>>(pending, out);
    write_shaded(target, pending.count, pending.depth, pending.index, out);
    pending.count = 0;
}

/// fill_phong() with per-sample light vectors, its samples shaded together
/// with those of the triangles before and after it (PendingPhongSamples): the
/// same colours, written in the same order. A target with nowhere to keep
/// them (a caller filling one triangle at a time) has this triangle's
/// samples shaded and written before the call returns. CentroidVectors: the
/// seed's vectors, at the triangle's centroid, computed per sample (see
/// add_pending_samples(); fill_phong_seed() chooses which triangles).
template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular, bool UniformColor,
          bool CentroidVectors = false>
void fill_phong_pending(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                        const FillConstants<Real>& constants) {
    PendingPhongSamples<Real>* pending = target.pending;
    if (pending == nullptr) {
        PendingPhongSamples<Real> own;
        target.pending = &own;
        fill_phong_pending<Real, Perspective, Ambient, Diffuse, Specular, UniformColor, CentroidVectors>(
            draw, target, vectors, constants);
        finish_pending(target);
        target.pending = nullptr;
        return;
    }
    constexpr auto shade_and_write = &shade_and_write_pending<Real, Ambient, Diffuse, Specular, UniformColor>;
    if (pending->count > 0 && (pending->surface != draw.surface || pending->constants != &constants ||
                               pending->shade_and_write != shade_and_write)) {
        pending->shade_and_write(*pending, target);  // another material's (or kernel's) samples first
    }
    pending->surface = draw.surface;
    pending->constants = &constants;
    pending->vectors = &vectors;
    pending->shade_and_write = shade_and_write;
    gather_sample_batches<Real, Perspective>(
        draw, target, [&] { return kSampleBatch - pending->count; },
        [&](int n, const Lanes<Real>* w, const Real* depth, const std::size_t* index) {
            add_pending_samples<Real, UniformColor, CentroidVectors>(draw, n, w, depth, index, *pending);
            if (pending->count == kSampleBatch) shade_and_write(*pending, target);
        });
}

/// Boxes of at most this many sample centres go through the pending batches
/// with the seed's vectors computed per sample; larger ones compute them once.
/// Measured on the Xeon (seed Phong, 1 thread, the limit varied in one build,
/// alternating processes): 36 to 100 gained 15-20% on icosphere-125k and
/// armadillo; every box pending lost 2-7% against none on suzanne and
/// icosphere-9.7k at 2048x2048; on dolphins_colored (512x512) 100 lost 5%
/// against none, 36 nothing.
inline constexpr int kMaxSeedPendingBox = 36;

/// The seed's Phong (light vectors at the triangle's centroid). A small
/// triangle's few samples join the pending batch (fill_phong_pending() with
/// CentroidVectors), which shades 32 samples of many triangles at a time,
/// their vectors computed per sample; a larger one's samples, after those
/// waiting, are shaded with vectors computed once (fill_phong()). The same
/// colours either way, written in the same order.
template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular, bool UniformColor>
void fill_phong_seed(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                     const FillConstants<Real>& constants) {
    const SnappedTriangle& box = draw.coverage;
    const long centres = static_cast<long>(box.row_max - box.row_min + 1) * (box.column_max - box.column_min + 1);
    if (centres <= kMaxSeedPendingBox) {
        fill_phong_pending<Real, Perspective, Ambient, Diffuse, Specular, UniformColor, true>(draw, target, vectors,
                                                                                             constants);
        return;
    }
    finish_pending(target);
    fill_phong<Real, Perspective, Ambient, Diffuse, Specular, false, UniformColor>(draw, target, vectors, constants);
}

/// Phong with neither diffuse nor specular needs no normal and no light: per
/// sample it is the ambient term of the interpolated colour, which costs what
/// Gouraud's interpolation costs. It goes through fill_samples (long spans
/// in vector loops, short ones sample by sample; the AVX2 kernels in float
/// paint every span with the span writers of fill_span_writers.hpp, as
/// Gouraud does), skipping the batches' gathering, with shade_phong_batch's
/// operations in the same order (0 + factor * colour, colour interpolated as
/// (w0 a + w1 b) + w2 c), so the image is the general kernel's bit for bit.
/// With one colour, or no ambient term, every sample is the same colour.
template <typename Real, bool Perspective, bool Ambient, bool UniformColor>
void fill_phong_unlit(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
                      const FillConstants<Real>& constants) {
    const Vec3<Real> factor = constants.rig_of(draw).ambient_factor;
    const auto shade = [&](const Real* w) {
        Vec3<Real> out(Real(0));
        if constexpr (Ambient) {
            for (int c = 0; c < 3; ++c) {
                const Real color = UniformColor ? constants.color[c]
                                                : (w[0] * draw.v[0]->color[c] + w[1] * draw.v[1]->color[c]) +
                                                      w[2] * draw.v[2]->color[c];
                out[c] += factor[c] * color;
            }
        }
        return out;
    };
    const auto shade_lanes = [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        for (int c = 0; c < 3; ++c) {
            if constexpr (Ambient) {
                if constexpr (UniformColor) {
                    const Real uniform = constants.color[c];  // a local: see shade_ambient_lanes()
                    for (int l = 0; l < n; ++l) out[c][l] = Real(0) + factor[c] * uniform;
                } else {
                    interpolate_lanes(n, w, draw.v[0]->color[c], draw.v[1]->color[c], draw.v[2]->color[c], out[c]);
                    for (int l = 0; l < n; ++l) out[c][l] = Real(0) + factor[c] * out[c][l];
                }
            } else {
                for (int l = 0; l < n; ++l) out[c][l] = Real(0);
            }
        }
    };
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        if constexpr (UniformColor || !Ambient) {
            const Real none[3] = {};
            fill_samples<Real, Perspective>(draw, target, shade, shade_lanes, FlatSpans{shade(none)});
        } else {
            const InterpolatedSpans<Perspective, true> spans{
                {{&draw.v[0]->color, &draw.v[1]->color, &draw.v[2]->color}, factor}};
            fill_samples<Real, Perspective>(draw, target, shade, shade_lanes, spans);
        }
        return;
    }
#endif
    fill_samples<Real, Perspective>(draw, target, shade, shade_lanes);
}

/// fill_samples() for a TinyDraw (a whole triangle whose box of at most 2 x 2
/// centres the coverage screen tested): the spans tiny_spans() would find,
/// the screen's covered centres in the target's rows, with SpanWeights'
/// weights from the same exact edge values, then each sample as
/// fill_samples() shades and writes it, by the rank test or written as it
/// is. Only the fill in mesh order fills tiny draws: no owner buffer, no
/// depth buffer. Span writers (`paint_span`, as fill_samples() takes them)
/// paint each row's span first.
template <typename Real, bool Perspective, typename Shade, typename PaintSpan = NoLanes>
PHONGRAST_FILL_INLINE void fill_tiny_samples(const TinyDraw<Real>& draw, FillTarget<Real>& target, Shade&& shade,
                                             PaintSpan&& paint_span = PaintSpan{}) {
    assert(target.owner == nullptr && !target.depth_test);
    const TinyCoverage& c = draw.coverage;
    Real inverse_area = Real(0), inverse_depth[3] = {Real(1), Real(1), Real(1)}, dq[3] = {};
    bool weights_set_up = false;
    const std::size_t columns = static_cast<std::size_t>(target.image.columns);
    for (int r = 0; r < 2; ++r) {
        const unsigned in_row = (c.covered >> (2 * r)) & 3u;
        const int row = c.row_min + r;
        if (in_row == 0 || row < target.row_begin || row >= target.row_end) continue;
        if (!weights_set_up) {
            // SpanWeights::set_up(), at the first covered span as there.
            inverse_area = Real(1) / static_cast<Real>(static_cast<std::int64_t>(c.area2));
            if constexpr (Perspective) {
                for (int i = 0; i < 3; ++i) inverse_depth[i] = Real(1) / draw.depth[i];
            }
            for (int i = 0; i < 3; ++i) {
                dq[i] = edge_weight<Real, Perspective>(static_cast<std::int64_t>(c.column_step[i]), inverse_area,
                                                       inverse_depth[i]);
            }
            weights_set_up = true;
        }
        const int skip = (in_row & 1u) != 0 ? 0 : 1;  // the row's first covered column: the box's first or second
        const int count = in_row == 3u ? 2 : 1;
        Real q[3];
        for (int i = 0; i < 3; ++i) {
            const double e = c.e[i] + c.row_step[i] * r + c.column_step[i] * skip;  // exact: integers below 2^53
            q[i] = edge_weight<Real, Perspective>(static_cast<std::int64_t>(e), inverse_area, inverse_depth[i]);
        }
        const int first_column = c.column_min + skip;
        const std::size_t row_start = static_cast<std::size_t>(row) * columns;
        target.covered += static_cast<std::uint64_t>(count);
        if (target.rank_keys != nullptr) {
            if constexpr (!std::is_same_v<std::decay_t<PaintSpan>, NoLanes>) {
                const std::size_t start = row_start + static_cast<std::size_t>(first_column);
                if (target.rank_ties != nullptr ? paint_span.template ranked<true>(target, start, count, q, dq)
                                                : paint_span.template ranked<false>(target, start, count, q, dq)) {
                    continue;
                }
            }
            fill_ranked_span<Real, Perspective>(draw.depth, target, row_start, first_column, count, q, dq, shade);
            continue;
        }
        if constexpr (!std::is_same_v<std::decay_t<PaintSpan>, NoLanes>) {
            paint_span.whole(q, dq, count, &target.image.pixels[row_start + static_cast<std::size_t>(first_column)],
                             target.replaced);
            target.samples += static_cast<std::uint64_t>(count);
            continue;
        }
        for (int k = 0; k < count; ++k) {
            Real w[3];
            sample_weights<Real, Perspective>(draw.depth, q, dq, k, w);
            target.image.pixels[row_start + static_cast<std::size_t>(first_column + k)] =
                finite_or_replaced(glm::vec3(shade(w)), target.replaced);
        }
        target.samples += static_cast<std::uint64_t>(count);
    }
}

/// fill_flat() for a TinyDraw: corner[0] is the triangle's colour.
template <typename Real, bool Perspective>
void fill_tiny_flat(const TinyDraw<Real>& draw, FillTarget<Real>& target, const FillConstants<Real>&) {
    const auto shade = [&](const Real*) { return *draw.corner[0]; };
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        fill_tiny_samples<Real, Perspective>(draw, target, shade, FlatSpans{*draw.corner[0]});
        return;
    }
#endif
    fill_tiny_samples<Real, Perspective>(draw, target, shade);
}

/// fill_lit() for a TinyDraw: corner[i] is the lit colour.
template <typename Real, bool Perspective>
void fill_tiny_lit(const TinyDraw<Real>& draw, FillTarget<Real>& target, const FillConstants<Real>&) {
    const auto shade = [&](const Real* w) {
        return w[0] * *draw.corner[0] + w[1] * *draw.corner[1] + w[2] * *draw.corner[2];
    };
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        const InterpolatedSpans<Perspective, false> spans{{{draw.corner[0], draw.corner[1], draw.corner[2]}}};
        fill_tiny_samples<Real, Perspective>(draw, target, shade, spans);
        return;
    }
#endif
    fill_tiny_samples<Real, Perspective>(draw, target, shade);
}

/// fill_phong_unlit() with the ambient term and varying colours for a
/// TinyDraw: corner[i] is the vertex colour.
template <typename Real, bool Perspective>
void fill_tiny_ambient(const TinyDraw<Real>& draw, FillTarget<Real>& target, const FillConstants<Real>& constants) {
    const Vec3<Real> factor = constants.rig[draw.surface].ambient_factor;
    const auto shade = [&](const Real* w) {
        Vec3<Real> out(Real(0));
        for (int c = 0; c < 3; ++c) {
            const Real color =
                (w[0] * (*draw.corner[0])[c] + w[1] * (*draw.corner[1])[c]) + w[2] * (*draw.corner[2])[c];
            out[c] += factor[c] * color;
        }
        return out;
    };
#if PHONGRAST_FILL_VECTOR_BYTES == 32
    if constexpr (std::is_same_v<Real, float>) {
        const InterpolatedSpans<Perspective, true> spans{{{draw.corner[0], draw.corner[1], draw.corner[2]}, factor}};
        fill_tiny_samples<Real, Perspective>(draw, target, shade, spans);
        return;
    }
#endif
    fill_tiny_samples<Real, Perspective>(draw, target, shade);
}

/// Phong as a straightforward implementation writes it: every term checked per batch, every light.
/// Textured: the same with c multiplied by T(s, t) at each sample (the kernel of textured scenes).
template <typename Real, bool Perspective, bool PerSampleVectors, bool Textured = false>
void fill_phong_general(const FillTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                        const FillConstants<Real>& constants) {
    const LightRig<Real>& rig = constants.rig_of(draw);
    if (!PerSampleVectors) vectors.compute(rig.lights, draw.centroid(), true, rig.eye_at_infinity);
    std::conditional_t<Textured, SelectedTexturedTerms, SelectedTerms> terms;
    terms.lighting = rig.lighting;
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        if (constants.uniform_color) {
            shade_phong_samples<Real, PerSampleVectors, true>(draw, n, w, terms, rig.lights, vectors, constants, out);
        } else {
            shade_phong_samples<Real, PerSampleVectors, false>(draw, n, w, terms, rig.lights, vectors, constants, out);
        }
    });
}

template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular>
FillKernel<Real> pick_phong_vectors_color(const KernelChoice& c) {
    if (!Diffuse && !Specular) {
        // No normals and no light vectors: only the colour varies.
        return c.uniform_color ? &fill_phong_unlit<Real, Perspective, Ambient, true>
                               : &fill_phong_unlit<Real, Perspective, Ambient, false>;
    }
    if (c.per_sample_vectors) {
        return c.uniform_color ? &fill_phong_pending<Real, Perspective, Ambient, Diffuse, Specular, true>
                               : &fill_phong_pending<Real, Perspective, Ambient, Diffuse, Specular, false>;
    }
    return c.uniform_color ? &fill_phong_seed<Real, Perspective, Ambient, Diffuse, Specular, true>
                           : &fill_phong_seed<Real, Perspective, Ambient, Diffuse, Specular, false>;
}

template <typename Real, bool Perspective>
FillKernel<Real> pick_kernel_for_projection(const KernelChoice& c) {
    if (c.flat) return c.textured ? &fill_flat_textured<Real, Perspective> : &fill_flat<Real, Perspective>;
    if (!c.phong) return c.textured ? &fill_lit_textured<Real, Perspective> : &fill_lit<Real, Perspective>;
    if (c.textured) {
        return c.per_sample_vectors ? &fill_phong_general<Real, Perspective, true, true>
                                    : &fill_phong_general<Real, Perspective, false, true>;
    }
    if (!c.specialized) {
        return c.per_sample_vectors ? &fill_phong_general<Real, Perspective, true>
                                    : &fill_phong_general<Real, Perspective, false>;
    }
    const EffectSet& e = c.effects;
    const int key = (e.ambient ? 4 : 0) | (e.diffuse ? 2 : 0) | (e.specular ? 1 : 0);
    switch (key) {
        case 0: return pick_phong_vectors_color<Real, Perspective, false, false, false>(c);
        case 1: return pick_phong_vectors_color<Real, Perspective, false, false, true>(c);
        case 2: return pick_phong_vectors_color<Real, Perspective, false, true, false>(c);
        case 3: return pick_phong_vectors_color<Real, Perspective, false, true, true>(c);
        case 4: return pick_phong_vectors_color<Real, Perspective, true, false, false>(c);
        case 5: return pick_phong_vectors_color<Real, Perspective, true, false, true>(c);
        case 6: return pick_phong_vectors_color<Real, Perspective, true, true, false>(c);
        default: return pick_phong_vectors_color<Real, Perspective, true, true, true>(c);
    }
}

/// The TinyDraw kernel matching pick_kernel(c), where there is one: flat and
/// Gouraud untextured, Phong (specialised) with only the ambient term and varying colours.
template <typename Real>
TinyFillKernel<Real> pick_tiny_kernel(const KernelChoice& c) {
    if (c.textured) return nullptr;
    if (c.flat) return c.perspective ? &fill_tiny_flat<Real, true> : &fill_tiny_flat<Real, false>;
    if (!c.phong) return c.perspective ? &fill_tiny_lit<Real, true> : &fill_tiny_lit<Real, false>;
    const EffectSet& e = c.effects;
    if (c.specialized && e.ambient && !e.diffuse && !e.specular && !c.uniform_color) {
        return c.perspective ? &fill_tiny_ambient<Real, true> : &fill_tiny_ambient<Real, false>;
    }
    return nullptr;
}

/// The single dispatch of a render.
template <typename Real>
FillKernel<Real> pick_kernel(const KernelChoice& c) {
    return c.perspective ? pick_kernel_for_projection<Real, true>(c) : pick_kernel_for_projection<Real, false>(c);
}

}  // namespace PHONGRAST_FILL_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNELS_HPP
