// How the fill kernels write a span of samples (internal header, included by
// fill_kernels.hpp once per instruction set, in its namespace): the guard
// every pixel passes, and, in the AVX2 kernels in float, span writers that
// paint a span in vector code of their own where the generic paths
// (fill_samples()' sample-by-sample loop, the 8-lane batches of
// fill_span_lanes()) cost more than the shading: Gouraud's and Phong's
// ambient-only interpolation (InterpolatedSpans) and flat's one colour
// (FlatSpans). Each writes the bits, counts and replacements the generic
// paths write: lane by lane the scalar code's operations in its order
// (-ffp-contract=off, no FMA), no pixel past a span touched.
#ifndef PHONGRAST_SRC_FILL_SPAN_WRITERS_HPP
#define PHONGRAST_SRC_FILL_SPAN_WRITERS_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "fill_phong_lanes.hpp"
#include "fill_types.hpp"

namespace phongrast::detail {
inline namespace PHONGRAST_FILL_ISA {

/// The last guard before a pixel is written: every input was validated
/// finite, so this should never fire; if it does, the channel becomes 0 and
/// is counted (RenderStats::nonfinite_values_replaced), never written as NaN.
PHONGRAST_FILL_INLINE glm::vec3 finite_or_replaced(glm::vec3 pixel, std::uint64_t& replaced) {
    if (std::isfinite(pixel.x + pixel.y + pixel.z)) return pixel;
    for (int channel = 0; channel < 3; ++channel) {
        if (!std::isfinite(pixel[channel])) {
            pixel[channel] = 0.0f;
            ++replaced;
        }
    }
    return pixel;
}

/// Spans at least this long, painted whole (no owner buffer to skip samples
/// by, no depth test), are shaded kSampleBatch samples at a time in vector
/// loops (fill_span_lanes()); shorter spans, most spans of a mesh of small
/// triangles, go sample by sample, which sets up less. Both write the same
/// bits, so this is a choice of speed only: a padded batch of 8 lanes beat
/// 4 to 7 samples one by one (armadillo, teapot, bunny Gouraud 0.87-0.92x
/// against a threshold of 8), while spans of 2 and 3 gained nothing
/// measurable.
constexpr int kMinLanesSpan = 4;

/// The rank test of the fill in mesh order: writes `colour` to sample k
/// where painter's order draws this draw (rank `key`, then `tie`) after the
/// one whose colour is there. `Ties`: the draws' ties must be compared (a
/// reordered mesh); else the draws come in the order of their ties, so a
/// draw of equal key always comes after the one whose colour is there.
template <bool Ties>
PHONGRAST_FILL_INLINE void write_if_ranked_later(std::uint64_t* keys, std::uint32_t* ties, glm::vec3* pixels, int k,
                                                 std::uint64_t key, std::uint32_t tie, glm::vec3 colour) {
    if constexpr (Ties) {
        if (key > keys[k] || (key == keys[k] && tie > ties[k])) {
            keys[k] = key;
            ties[k] = tie;
            pixels[k] = colour;
        }
    } else if (key >= keys[k]) {
        keys[k] = key;
        pixels[k] = colour;
    }
}

/// Writes samples start + k, k < count, of the fill in mesh order, sample k
/// the colour pixel(k) (evaluated before its test, as painter's fill shades
/// every sample), by write_if_ranked_later(). The test stays scalar: the same
/// test in four lanes, with masked loads and stores of the keys, ties and
/// pixels, was slower (in-process A/B, 1 thread: the 1.3M sphere's Gouraud
/// and Phong ambient-only 0.94 with the scalar test, the 125k 0.98), likely
/// as masked stores cannot forward to the next span's loads.
template <bool Ties, typename Real, typename Pixel>
PHONGRAST_FILL_INLINE void write_ranked(FillTarget<Real>& target, std::size_t start, int count, Pixel&& pixel) {
    std::uint64_t* keys = target.rank_keys + start;
    std::uint32_t* ties = Ties ? target.rank_ties + start : nullptr;
    glm::vec3* pixels = target.image.pixels.data() + start;
    // Locals: the stores to keys could otherwise be taken to change them.
    const std::uint64_t key = target.key;
    const std::uint32_t tie = target.tie;
    for (int k = 0; k < count; ++k) write_if_ranked_later<Ties>(keys, ties, pixels, k, key, tie, pixel(k));
}

#if PHONGRAST_FILL_VECTOR_BYTES == 32
/// Writes eight lanes of three channels, the first n (1 to 8) of them, as n
/// pixels of three floats from `out` on: turned into 24 interleaved floats by
/// shuffles within 128-bit halves, then written as three 32-byte stores, a
/// partial group's masked to its lanes (no pixel past them is touched).
PHONGRAST_FILL_INLINE void store_group_interleaved(float* out, int n, __m256 r, __m256 g, __m256 b) {
    // Per 128-bit half (lanes 0-3, then 4-7): r0 g0 b0 r1 | g1 b1 r2 g2 | b2 r3 g3 b3.
    const __m256 rg_lo = _mm256_unpacklo_ps(r, g), rg_hi = _mm256_unpackhi_ps(r, g);
    const __m256 br_lo = _mm256_unpacklo_ps(b, r), br_hi = _mm256_unpackhi_ps(b, r);
    const __m256 gb_lo = _mm256_unpacklo_ps(g, b), gb_hi = _mm256_unpackhi_ps(g, b);
    const __m256 x0 = _mm256_shuffle_ps(rg_lo, br_lo, _MM_SHUFFLE(3, 0, 1, 0));
    const __m256 x1 = _mm256_shuffle_ps(gb_lo, rg_hi, _MM_SHUFFLE(1, 0, 3, 2));
    const __m256 x2 = _mm256_shuffle_ps(br_hi, gb_hi, _MM_SHUFFLE(3, 2, 3, 0));
    // The lower halves hold pixels 0-3, the upper 4-7: put them in order.
    const __m256 out0 = _mm256_permute2f128_ps(x0, x1, 0x20);
    const __m256 out1 = _mm256_permute2f128_ps(x2, x0, 0x30);
    const __m256 out2 = _mm256_permute2f128_ps(x1, x2, 0x31);
    if (n == 8) {
        _mm256_storeu_ps(out, out0);
        _mm256_storeu_ps(out + 8, out1);
        _mm256_storeu_ps(out + 16, out2);
        return;
    }
    const int floats = 3 * n;
    const __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    _mm256_maskstore_ps(out, _mm256_cmpgt_epi32(_mm256_set1_epi32(floats), index), out0);
    _mm256_maskstore_ps(out + 8, _mm256_cmpgt_epi32(_mm256_set1_epi32(floats - 8), index), out1);
    _mm256_maskstore_ps(out + 16, _mm256_cmpgt_epi32(_mm256_set1_epi32(floats - 16), index), out2);
}

/// Writes lanes [0, n) of a batch's three channels as n pixels, eight at a
/// time (store_group_interleaved()). The loop GCC made of the same copy
/// wrote the last group's pixels one by one, a loop whose varying trip count
/// mispredicted at most span ends.
PHONGRAST_FILL_INLINE void store_pixels_interleaved(glm::vec3* pixels, int n, const float (*channel)[kSampleBatch]) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "pixels are three packed floats");
    for (int start = 0; start < n; start += 8) {
        store_group_interleaved(&pixels[start].x, std::min(8, n - start), _mm256_loadu_ps(channel[0] + start),
                                _mm256_loadu_ps(channel[1] + start), _mm256_loadu_ps(channel[2] + start));
    }
}

/// What an interpolating span writer interpolates at a triangle's corners:
/// Gouraud's lit colours as they are (`Scaled` false: (w0 a + w1 b) + w2 c per
/// channel, interpolate_lit()), or Phong's ambient term of the vertex colours
/// (`Scaled`: 0 + factor * that, fill_phong_unlit()'s operations; the 0 + turns
/// a -0 into +0 as the scalar code does).
template <bool Scaled>
struct CornerColours {
    const glm::vec3* corner[3];
    glm::vec3 factor{};  ///< `Scaled` only: the ambient factor per channel
};

// The vector operations colours_at() is written with, for SSE and AVX alike.
PHONGRAST_FILL_INLINE __m128 lanes_add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
PHONGRAST_FILL_INLINE __m256 lanes_add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
PHONGRAST_FILL_INLINE __m128 lanes_mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
PHONGRAST_FILL_INLINE __m256 lanes_mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
PHONGRAST_FILL_INLINE void lanes_set1(float x, __m128& out) { out = _mm_set1_ps(x); }
PHONGRAST_FILL_INLINE void lanes_set1(float x, __m256& out) { out = _mm256_set1_ps(x); }

/// The colours at weights w (one vector of lanes per corner), per channel,
/// for 4 (SSE) or 8 (AVX) lanes.
template <bool Scaled, typename Vector>
PHONGRAST_FILL_INLINE void colours_at(const CornerColours<Scaled>& corners, const Vector* w, Vector* colour) {
    for (int c = 0; c < 3; ++c) {
        Vector a, b, d;
        lanes_set1((*corners.corner[0])[c], a);
        lanes_set1((*corners.corner[1])[c], b);
        lanes_set1((*corners.corner[2])[c], d);
        colour[c] = lanes_add(lanes_add(lanes_mul(w[0], a), lanes_mul(w[1], b)), lanes_mul(w[2], d));
        if constexpr (Scaled) {
            Vector zero, factor;
            lanes_set1(0.0f, zero);
            lanes_set1(corners.factor[c], factor);
            colour[c] = lanes_add(zero, lanes_mul(factor, colour[c]));
        }
    }
}

/// The colours of a span's first four samples, one SSE vector per channel:
/// the weights q + dq k, renormalised when perspective-correct
/// (sample_weights()), then colours_at(). For spans of 1 to 3 samples (under
/// kMinLanesSpan): computed once in lanes instead of sample by sample (a
/// division and an interpolation per sample, and the scalar loop's
/// latency); the lanes past the span are never written.
template <bool Perspective, bool Scaled>
PHONGRAST_FILL_INLINE void short_span_colours(const CornerColours<Scaled>& corners, const float* q, const float* dq,
                                              __m128* colour) {
    static_assert(kMinLanesSpan <= 5, "a short span fits four lanes");
    const __m128 k = _mm_setr_ps(0.0f, 1.0f, 2.0f, 3.0f);
    __m128 w[3];
    for (int i = 0; i < 3; ++i) w[i] = _mm_add_ps(_mm_set1_ps(q[i]), _mm_mul_ps(_mm_set1_ps(dq[i]), k));
    if constexpr (Perspective) {
        const __m128 depth = _mm_div_ps(_mm_set1_ps(1.0f), _mm_add_ps(_mm_add_ps(w[0], w[1]), w[2]));
        for (int i = 0; i < 3; ++i) w[i] = _mm_mul_ps(w[i], depth);
    }
    colours_at(corners, w, colour);
}

/// finite_or_replaced()'s test, isfinite((r + g) + b), failed in any of the first `count` lanes.
PHONGRAST_FILL_INLINE bool any_nonfinite_short(const __m128* colour, int count) {
    const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_add_ps(_mm_add_ps(colour[0], colour[1]), colour[2]));
    const int nonfinite = _mm_movemask_ps(_mm_cmp_ps(magnitude, _mm_set1_ps(std::numeric_limits<float>::max()),
                                                     _CMP_NLE_UQ));
    return (nonfinite & ((1 << count) - 1)) != 0;
}

/// Writes the four lanes' pixels where `lanes` (one 32-bit mask per lane) is set:
/// r0 g0 b0 r1 | g1 b1 r2 g2 | b2 r3 g3 b3, as store_group_interleaved() forms each half.
PHONGRAST_FILL_INLINE void store_short_span(glm::vec3* pixels, const __m128* colour, __m128i lanes) {
    const __m128 r = colour[0], g = colour[1], b = colour[2];
    const __m128 x0 = _mm_shuffle_ps(_mm_unpacklo_ps(r, g), _mm_unpacklo_ps(b, r), _MM_SHUFFLE(3, 0, 1, 0));
    const __m128 x1 = _mm_shuffle_ps(_mm_unpacklo_ps(g, b), _mm_unpackhi_ps(r, g), _MM_SHUFFLE(1, 0, 3, 2));
    const __m128 x2 = _mm_shuffle_ps(_mm_unpackhi_ps(b, r), _mm_unpackhi_ps(g, b), _MM_SHUFFLE(3, 2, 3, 0));
    float* first = &pixels[0].x;
    // Float j of the twelve belongs to pixel j / 3.
    _mm_maskstore_ps(first, _mm_shuffle_epi32(lanes, _MM_SHUFFLE(1, 0, 0, 0)), x0);
    _mm_maskstore_ps(first + 4, _mm_shuffle_epi32(lanes, _MM_SHUFFLE(2, 2, 1, 1)), x1);
    _mm_maskstore_ps(first + 8, _mm_shuffle_epi32(lanes, _MM_SHUFFLE(3, 3, 3, 2)), x2);
}

/// Lanes 0 to count - 1 set.
PHONGRAST_FILL_INLINE __m128i first_lanes(int count) {
    return _mm_cmpgt_epi32(_mm_set1_epi32(count), _mm_setr_epi32(0, 1, 2, 3));
}

/// A span of 1 to 3 samples painted whole (short_span_colours()).
template <bool Perspective, bool Scaled>
PHONGRAST_FILL_INLINE void fill_short_span(const CornerColours<Scaled>& corners, const float* q, const float* dq,
                                           int count, glm::vec3* pixels, std::uint64_t& replaced) {
    __m128 colour[3];
    short_span_colours<Perspective>(corners, q, dq, colour);
    if (any_nonfinite_short(colour, count)) {
        alignas(16) float channel[3][4];
        for (int c = 0; c < 3; ++c) _mm_store_ps(channel[c], colour[c]);
        for (int l = 0; l < count; ++l) {
            pixels[l] = finite_or_replaced(glm::vec3(channel[0][l], channel[1][l], channel[2][l]), replaced);
        }
        return;
    }
    store_short_span(pixels, colour, first_lanes(count));
}

/// A span of 1 to 3 samples in the fill in mesh order: its colours as
/// fill_short_span() computes them, written by write_ranked(). False,
/// with nothing written, if a colour is not finite: the caller then takes the
/// sample-by-sample path, which counts the replaced channels.
template <bool Ties, bool Perspective, bool Scaled>
PHONGRAST_FILL_INLINE bool fill_ranked_short_span(const CornerColours<Scaled>& corners, FillTarget<float>& target,
                                                  std::size_t start, int count, const float* q, const float* dq) {
    __m128 colour[3];
    short_span_colours<Perspective>(corners, q, dq, colour);
    if (any_nonfinite_short(colour, count)) return false;
    alignas(16) float channel[3][4];
    for (int c = 0; c < 3; ++c) _mm_store_ps(channel[c], colour[c]);
    write_ranked<Ties>(target, start, count, [&](int k) PHONGRAST_INLINE_LAMBDA {
        return glm::vec3(channel[0][k], channel[1][k], channel[2][k]);
    });
    target.samples += static_cast<std::uint64_t>(count);
    return true;
}

/// A span of any length painted whole: eight samples at a time in AVX
/// vectors, the weights of sample k as shade_span_lanes() forms them (q + dq
/// k, k converted from its integer), renormalised and interpolated lane by
/// lane as short_span_colours() does, then written from the registers by
/// store_group_interleaved(). Inline, so a span of a few groups costs no
/// call and no lane arrays.
template <bool Perspective, bool Scaled>
PHONGRAST_FILL_INLINE void fill_span_interpolated(const CornerColours<Scaled>& corners, const float* q,
                                                  const float* dq, int count, glm::vec3* pixels,
                                                  std::uint64_t& replaced) {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int start = 0; start < count; start += 8) {
        const __m256 k = _mm256_cvtepi32_ps(_mm256_add_epi32(_mm256_set1_epi32(start), lane));
        __m256 w[3];
        for (int i = 0; i < 3; ++i) w[i] = _mm256_add_ps(_mm256_set1_ps(q[i]), _mm256_mul_ps(_mm256_set1_ps(dq[i]), k));
        if constexpr (Perspective) {
            const __m256 depth = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_add_ps(_mm256_add_ps(w[0], w[1]), w[2]));
            for (int i = 0; i < 3; ++i) w[i] = _mm256_mul_ps(w[i], depth);
        }
        __m256 colour[3];
        colours_at(corners, w, colour);
        const int n = std::min(8, count - start);
        // finite_or_replaced()'s test, isfinite((r + g) + b), for the group's lanes.
        const __m256 magnitude =
            _mm256_andnot_ps(_mm256_set1_ps(-0.0f), _mm256_add_ps(_mm256_add_ps(colour[0], colour[1]), colour[2]));
        const int nonfinite = _mm256_movemask_ps(_mm256_cmp_ps(
                                  magnitude, _mm256_set1_ps(std::numeric_limits<float>::max()), _CMP_NLE_UQ)) &
                              ((1 << n) - 1);
        if (nonfinite != 0) {
            alignas(32) float channel[3][8];
            for (int c = 0; c < 3; ++c) _mm256_store_ps(channel[c], colour[c]);
            for (int l = 0; l < n; ++l) {
                pixels[start + l] =
                    finite_or_replaced(glm::vec3(channel[0][l], channel[1][l], channel[2][l]), replaced);
            }
            continue;
        }
        store_group_interleaved(&pixels[start].x, n, colour[0], colour[1], colour[2]);
    }
}

/// fill_samples()' span writers for the kernels that interpolate a colour
/// (fill_lit(), fill_phong_unlit() with varying colours, their TinyDraw
/// kernels): whole() paints a span of any length; ranked() takes the fill in
/// mesh order's spans under kMinLanesSpan and declines longer ones (and
/// non-finite colours), which the caller then writes its own way.
template <bool Perspective, bool Scaled>
struct InterpolatedSpans {
    CornerColours<Scaled> corners;

    PHONGRAST_FILL_INLINE void whole(const float* q, const float* dq, int count, glm::vec3* pixels,
                                     std::uint64_t& replaced) const {
        if (count < kMinLanesSpan) {
            fill_short_span<Perspective>(corners, q, dq, count, pixels, replaced);
        } else {
            fill_span_interpolated<Perspective>(corners, q, dq, count, pixels, replaced);
        }
    }
    template <bool Ties>
    PHONGRAST_FILL_INLINE bool ranked(FillTarget<float>& target, std::size_t start, int count, const float* q,
                                      const float* dq) const {
        if (count >= kMinLanesSpan) return false;
        return fill_ranked_short_span<Ties, Perspective>(corners, target, start, count, q, dq);
    }
};

/// fill_samples()' span writers for one colour per triangle (fill_flat(),
/// fill_tiny_flat(), fill_phong_unlit() with one colour or no ambient term):
/// that colour, as it is, in every sample of a span of any
/// length, eight pixels per group of stores, and in the fill in mesh order
/// with no weights computed. A colour that is not finite goes sample by sample
/// (whole()) or is declined (ranked()), so the replacements are counted as
/// finite_or_replaced() counts them.
struct FlatSpans {
    glm::vec3 colour;

    PHONGRAST_FILL_INLINE bool finite() const { return std::isfinite(colour.x + colour.y + colour.z); }
    PHONGRAST_FILL_INLINE void whole(const float*, const float*, int count, glm::vec3* pixels,
                                     std::uint64_t& replaced) const {
        if (!finite()) {
            for (int k = 0; k < count; ++k) pixels[k] = finite_or_replaced(colour, replaced);
            return;
        }
        const __m256 r = _mm256_set1_ps(colour.x), g = _mm256_set1_ps(colour.y), b = _mm256_set1_ps(colour.z);
        for (int start = 0; start < count; start += 8) {
            store_group_interleaved(&pixels[start].x, std::min(8, count - start), r, g, b);
        }
    }
    template <bool Ties>
    PHONGRAST_FILL_INLINE bool ranked(FillTarget<float>& target, std::size_t start, int count, const float*,
                                      const float*) const {
        if (!finite()) return false;
        write_ranked<Ties>(target, start, count, [&](int) PHONGRAST_INLINE_LAMBDA { return colour; });
        target.samples += static_cast<std::uint64_t>(count);
        return true;
    }
};
#endif

}  // namespace PHONGRAST_FILL_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_SPAN_WRITERS_HPP
