// 8-bit PNG channel values (internal header): what every PNG phongrast writes stores.
#ifndef PHONGRAST_SRC_IO_PNG_BYTES_HPP
#define PHONGRAST_SRC_IO_PNG_BYTES_HPP

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace phongrast::io::detail {

/// [0,1] clamp then round to 8 bits, no gamma curve; NaN (never expected) becomes 0.
/// The rounding is std::lround(clamped * 255.0f)'s (half away from zero)
/// without the library call: the float product is below 256, so adding 0.5
/// in double is exact and truncating the sum rounds it. (A loop of this
/// over an image still did not vectorize: the array form below does.)
inline std::uint8_t to_8_bit(float value) {
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(clamped * 255.0f) + 0.5));
}

/// to[i] = to_8_bit(from[i]) for i < count. GCC leaves to_8_bit's clamp as
/// branches in a loop (it may not evaluate both sides of a float comparison
/// that could trap), 14 instructions a value; this does four values per SSE2
/// step with the same operations: maxps(v, 0) is `v > 0 ? v : 0` (NaN and
/// -0 give +0), minps(c, 1) is `c < 1 ? c : 1`, the product rounded to
/// float, widened to double, 0.5 added (exact) and truncated.
inline void to_8_bit(const float* from, std::uint8_t* to, std::size_t count) {
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 scale = _mm_set1_ps(255.0f);
    const __m128d half = _mm_set1_pd(0.5);
    for (; i + 4 <= count; i += 4) {
        const __m128 clamped = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(from + i), zero), one);
        const __m128 product = _mm_mul_ps(clamped, scale);
        const __m128i low = _mm_cvttpd_epi32(_mm_add_pd(_mm_cvtps_pd(product), half));
        const __m128i high = _mm_cvttpd_epi32(_mm_add_pd(_mm_cvtps_pd(_mm_movehl_ps(product, product)), half));
        const __m128i words = _mm_packs_epi32(_mm_unpacklo_epi64(low, high), _mm_setzero_si128());
        const int four = _mm_cvtsi128_si32(_mm_packus_epi16(words, words));
        std::memcpy(to + i, &four, 4);
    }
#endif
    for (; i < count; ++i) to[i] = to_8_bit(from[i]);
}

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_PNG_BYTES_HPP
