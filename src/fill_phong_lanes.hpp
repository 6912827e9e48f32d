// Batched Phong shading for the fill kernels (internal header, included by
// fill_kernels.hpp once per instruction set, in its namespace).
//
#ifndef PHONGRAST_SRC_FILL_PHONG_LANES_HPP
#define PHONGRAST_SRC_FILL_PHONG_LANES_HPP

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "fill_types.hpp"

/// The helpers below are meant to fold into shade_phong_batch(), so that its
/// single-lane instantiation keeps a constant trip count throughout.
#define PHONGRAST_FILL_INLINE PHONGRAST_ALWAYS_INLINE

namespace phongrast::detail {
inline namespace PHONGRAST_FILL_ISA {

/// Phong shades up to kSampleBatch samples of a span at a time, structure of
/// arrays: every step below is a loop over the n lanes with no call and no
/// branch (selects only), which GCC vectorises (SSE2: 4 floats or 2 doubles per
/// instruction, AVX2 twice as many; the remainder in scalar code with the same operations; check
/// with -fopt-info-vec). A run-time trip count keeps GCC from unrolling the
/// loops instead, and costs no lanes past the end of a span. Lane for lane it performs the scalar formula's
/// operations in the same order (see shading.hpp), so the specialised and the
/// general kernel, which both shade through here, agree bit for bit.
constexpr int kSampleBatch = 32;

template <typename Real>
using Lanes = Real[kSampleBatch];

/// The first lanes of a gathered batch that gather_sample_batches() sets
/// (to zero) before gathering, so that code may read a whole group of them
/// whatever the batch's size.
constexpr int kGatherGroup = 8;

/// The lighting terms a batch evaluates: fixed at compile time for the specialised kernels.
template <bool Ambient, bool Diffuse, bool Specular>
struct FixedTerms {
    static constexpr bool ambient() { return Ambient; }
    static constexpr bool diffuse() { return Diffuse; }
    static constexpr bool specular() { return Specular; }
    static constexpr bool textured() { return false; }
};
/// ... or asked at run time, as the general kernel does.
struct SelectedTerms {
    Lighting lighting;
    bool ambient() const { return lighting.ambient; }
    bool diffuse() const { return lighting.diffuse; }
    bool specular() const { return lighting.specular; }
    static constexpr bool textured() { return false; }
};
/// The general kernel's terms on textured faces: c is multiplied by T(s, t) at the sample.
struct SelectedTexturedTerms : SelectedTerms {
    static constexpr bool textured() { return true; }
};

/// out = a * wa + b * wb + c * wc per lane (glm's order: (w0 a + w1 b) + w2 c).
template <typename Real>
inline void interpolate_lanes(int n, const Lanes<Real>* w, Real a, Real b, Real c, Lanes<Real>& out) {
    for (int l = 0; l < n; ++l) out[l] = (w[0][l] * a + w[1][l] * b) + w[2][l] * c;
}

/// safe_normalize() lane by lane: the same operations, the branch as a select.
template <typename Real>
inline void normalize_lanes(int n, Lanes<Real>& x, Lanes<Real>& y, Lanes<Real>& z) {
    for (int l = 0; l < n; ++l) {
        const Real ax = std::abs(x[l]), ay = std::abs(y[l]), az = std::abs(z[l]);
        const Real m = ay < az ? az : ay;       // std::max(ay, az)
        const Real largest = ax < m ? m : ax;  // std::max(ax, m)
        const bool ok = largest > Real(0) && largest <= std::numeric_limits<Real>::max();
        const Real divisor = ok ? largest : Real(1);
        const Real sx = x[l] / divisor, sy = y[l] / divisor, sz = z[l] / divisor;
        const Real length = std::sqrt((sx * sx + sy * sy) + sz * sz);
        x[l] = ok ? sx / length : Real(0);
        y[l] = ok ? sy / length : Real(0);
        z[l] = ok ? sz / length : Real(0);
    }
}

/// out = x^exponent per lane, for x in [0, 1]. A whole exponent up to 256 (the
/// usual case: 16, 32, ...) is computed by repeated squaring, in vector
/// registers, within a few ulps of std::pow (0^0 = 1 as the contract says);
/// any other exponent calls std::pow lane by lane.
template <typename Real>
inline void power_lanes(int n, const Lanes<Real>& x, Real exponent, Lanes<Real>& out) {
    if (exponent >= Real(0) && exponent <= Real(256) && exponent == std::floor(exponent)) {
        for (int l = 0; l < n; ++l) out[l] = Real(1);
        Lanes<Real> square;
        for (int l = 0; l < n; ++l) square[l] = x[l];
        for (unsigned bits = static_cast<unsigned>(exponent); bits != 0; bits >>= 1) {
            if (bits & 1u) {
                for (int l = 0; l < n; ++l) out[l] *= square[l];
            }
            if (bits > 1) {
                for (int l = 0; l < n; ++l) square[l] *= square[l];
            }
        }
        return;
    }
    for (int l = 0; l < n; ++l) out[l] = std::pow(x[l], exponent);
}

/// A texel index brought into [0, size) as OpenGL's wrap modes do (the
/// reference's wrap_index() in src/texture.cpp).
inline long long wrap_texel(long long index, long long size, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::clamp_to_edge: return index < 0 ? 0 : (index >= size ? size - 1 : index);
        case TextureWrap::mirrored_repeat: {
            long long period = index % (2 * size);
            if (period < 0) period += 2 * size;
            const long long a = period - size;
            return (size - 1) - (a >= 0 ? a : -(1 + a));
        }
        case TextureWrap::repeat:
        default: {
            const long long wrapped = index % size;
            return wrapped < 0 ? wrapped + size : wrapped;
        }
    }
}

/// T(s, t) in Real: the contract's bilinear lookup (as sample_bilinear()
/// computes it in double, in the same order), or the nearest texel.
/// Coordinates too large for Real give T = 1: nothing non-finite reaches a pixel.
/// AlwaysWrap: every index through fmod and wrap_texel(), even inside the
/// image (the fast path's reference, for tests/test_texture_lookup.cpp).
template <typename Real, bool AlwaysWrap = false>
PHONGRAST_FILL_INLINE Vec3<Real> texture_at(const KernelTexture& texture, Real s, Real t) {
    const Real x = s * Real(texture.columns) - Real(0.5);
    const Real y = (Real(1) - t) * Real(texture.rows) - Real(0.5);
    if (!std::isfinite(x) || !std::isfinite(y)) return Vec3<Real>(Real(1));
    const long long columns = texture.columns, rows = texture.rows;
    const auto texel = [&](long long i, long long j) {
        return Vec3<Real>(texture.texels[static_cast<std::size_t>(i) * static_cast<std::size_t>(columns) +
                                         static_cast<std::size_t>(j)]);
    };
    // Reduced modulo twice the size first, so that no index overflows (every wrap has that period).
    const auto reduce = [](Real index, long long size) {
        return static_cast<long long>(std::fmod(index, Real(2) * static_cast<Real>(size)));
    };
    // An index in [0, last] is its own reduction and every wrap mode leaves
    // it as it is, so where all the texels read lie inside the image (most
    // samples) the indices are the floors themselves: no fmod, no wrap.
    // (A limit past 2^24 might round in float: such images take the general path.)
    const auto inside = [](Real index, long long last) {
        return !AlwaysWrap && last < (1ll << 24) && index >= Real(0) && index <= static_cast<Real>(last);
    };
    if (texture.filter == TextureFilter::nearest) {
        // The texel whose area holds (s W, (1 - t) H): floor(x + 1/2).
        const Real j_nearest = std::floor(x + Real(0.5)), i_nearest = std::floor(y + Real(0.5));
        if (inside(j_nearest, columns - 1) && inside(i_nearest, rows - 1)) {
            return texel(static_cast<long long>(i_nearest), static_cast<long long>(j_nearest));
        }
        const long long j = wrap_texel(reduce(j_nearest, columns), columns, texture.wrap_s);
        const long long i = wrap_texel(reduce(i_nearest, rows), rows, texture.wrap_t);
        return texel(i, j);
    }
    const Real j_floor = std::floor(x), i_floor = std::floor(y);
    const Real a = x - j_floor, b = y - i_floor;
    long long j0, j1, i0, i1;
    if (inside(j_floor, columns - 2) && inside(i_floor, rows - 2)) {
        j0 = static_cast<long long>(j_floor);
        i0 = static_cast<long long>(i_floor);
        j1 = j0 + 1;
        i1 = i0 + 1;
    } else {
        j0 = wrap_texel(reduce(j_floor, columns), columns, texture.wrap_s);
        j1 = wrap_texel(reduce(j_floor, columns) + 1, columns, texture.wrap_s);
        i0 = wrap_texel(reduce(i_floor, rows), rows, texture.wrap_t);
        i1 = wrap_texel(reduce(i_floor, rows) + 1, rows, texture.wrap_t);
    }
    const Real one = Real(1);
    return (one - a) * (one - b) * texel(i0, j0) + a * (one - b) * texel(i0, j1) + (one - a) * b * texel(i1, j0) +
           a * b * texel(i1, j1);
}

/// rho^2 of texture_lambda(): the larger squared length, +infinity for NaN.
template <typename Real>
PHONGRAST_FILL_INLINE Real texture_footprint2(const KernelTexture& texture, Real ds_dx, Real dt_dx, Real ds_dy,
                                              Real dt_dy) {
    const Real columns = static_cast<Real>(texture.columns), rows = static_cast<Real>(texture.rows);
    const Real ux = ds_dx * columns, vx = dt_dx * rows, uy = ds_dy * columns, vy = dt_dy * rows;
    const Real along_x = ux * ux + vx * vx, along_y = uy * uy + vy * vy;
    if (std::isnan(along_x) || std::isnan(along_y)) return std::numeric_limits<Real>::infinity();
    return along_x < along_y ? along_y : along_x;
}

/// The trilinear filter's level of detail in Real (mip_lambda() in
/// src/texture.cpp, in double): log2 of the larger of the lengths of
/// (ds/dx W, dt/dx H) and (ds/dy W, dt/dy H), in level-0 texels per step.
/// Zero derivatives give -infinity (magnified: level 0); a NaN or infinite
/// one, or lengths too long for Real, +infinity (the last level).
template <typename Real>
PHONGRAST_FILL_INLINE Real texture_lambda(const KernelTexture& texture, Real ds_dx, Real dt_dx, Real ds_dy,
                                          Real dt_dy) {
    return Real(0.5) * std::log2(texture_footprint2(texture, ds_dx, dt_dx, ds_dy, dt_dy));
}

/// Level `level` (1 ... mip_level_count) of a trilinear texture as a bilinear KernelTexture.
inline KernelTexture texture_level(const KernelTexture& texture, int level) {
    KernelTexture view = texture;
    const MipLevel& reduced = texture.mip_levels[level - 1];
    view.texels = reduced.texels.data();
    view.rows = reduced.rows;
    view.columns = reduced.columns;
    view.filter = TextureFilter::bilinear;
    return view;
}

/// A texture coordinate taken into the wrap mode's period, which every level
/// shares (each spans [0, 1]): s - floor(s) for repeat, s - 2 floor(s / 2)
/// for mirrored repeat (rounded by at most half an ulp of the period), as it
/// is for clamp. The lookups then mostly stay inside the image and skip
/// texture_at()'s wrap arithmetic; non-finite coordinates stay non-finite (T = 1).
template <typename Real>
PHONGRAST_FILL_INLINE Real one_period(Real coordinate, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::repeat: return coordinate - std::floor(coordinate);
        case TextureWrap::mirrored_repeat: return coordinate - Real(2) * std::floor(coordinate * Real(0.5));
        case TextureWrap::clamp_to_edge:
        default: return coordinate;
    }
}

/// GL_LINEAR_MIPMAP_LINEAR at (s, t) with level of detail lambda (as
/// sample_trilinear() in double): lambda <= 0 is the bilinear lookup on level 0
/// exactly (texture_at()), lambda >= the last level q bilinear on level q,
/// between them the bilinear lookups on levels floor(lambda) and one below,
/// blended by lambda - floor(lambda). NaN counts as +infinity.
template <typename Real>
PHONGRAST_FILL_INLINE Vec3<Real> texture_at_trilinear(const KernelTexture& texture, Real s, Real t, Real lambda) {
    KernelTexture level0 = texture;
    level0.filter = TextureFilter::bilinear;
    if (std::isnan(lambda)) lambda = std::numeric_limits<Real>::infinity();
    if (!(lambda > Real(0)) || texture.mip_level_count == 0) return texture_at<Real>(level0, s, t);
    // Minified: (s, t) into one period first (the magnified lookup above
    // keeps bilinear's operations, so its picture stays bilinear's bit for bit).
    s = one_period(s, texture.wrap_s);
    t = one_period(t, texture.wrap_t);
    const int last = texture.mip_level_count;
    if (lambda >= static_cast<Real>(last)) return texture_at<Real>(texture_level(texture, last), s, t);
    const Real floor_lambda = std::floor(lambda), fraction = lambda - floor_lambda;
    const int d = static_cast<int>(floor_lambda);
    const Vec3<Real> finer = d == 0 ? texture_at<Real>(level0, s, t) : texture_at<Real>(texture_level(texture, d), s, t);
    const Vec3<Real> coarser = texture_at<Real>(texture_level(texture, d + 1), s, t);
    return (Real(1) - fraction) * finer + fraction * coarser;
}

/// T of n lanes with the trilinear filter into texel[3]: (s, t) and their
/// screen-space derivatives at each sample. Vertex i's weight is E_i / (2 area)
/// (the edge function opposite it), divided by its depth z_i and renormalised
/// when perspective-correct: w_i = q_i / sum_j q_j with q_i linear on the
/// screen. By the quotient rule ds/dx = Z sum_i dq_i/dx (s_i - s), where
/// Z = 1 / sum_j q_j = sum_i w_i z_i (the sample's depth); with screen-linear
/// weights (z_i taken as 1) that is the constant sum_i dw_i/dx s_i. x and y
/// step one sample, scaled by texture.footprint_scale.
template <typename Real>
inline void texture_lanes_trilinear(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w, const Lanes<Real>& s,
                                    const Lanes<Real>& t, const KernelTexture& texture, Lanes<Real>* texel) {
    const SnappedTriangle& coverage = draw.coverage;
    const Real scale = static_cast<Real>(texture.footprint_scale) / static_cast<Real>(coverage.area2());
    Real gx[3], gy[3];
    for (int i = 0; i < 3; ++i) {
        const CompactPoint& a = coverage.v[(i + 1) % 3];
        const CompactPoint& b = coverage.v[(i + 2) % 3];
        const Real weight_scale = texture.perspective ? scale / draw.depth[i] : scale;
        gx[i] = static_cast<Real>(-(std::int64_t(b.y) - a.y) * kSubpixelScale) * weight_scale;
        gy[i] = static_cast<Real>((std::int64_t(b.x) - a.x) * kSubpixelScale) * weight_scale;
    }
    const auto sum = [&](const Real* g, int channel) {
        return (g[0] * draw.v[0]->lit[channel] + g[1] * draw.v[1]->lit[channel]) + g[2] * draw.v[2]->lit[channel];
    };
    const Real s_x = sum(gx, 0), t_x = sum(gx, 1), s_y = sum(gy, 0), t_y = sum(gy, 1);
    const Real g_x = (gx[0] + gx[1]) + gx[2], g_y = (gy[0] + gy[1]) + gy[2];
    KernelTexture level0 = texture;
    level0.filter = TextureFilter::bilinear;
    for (int l = 0; l < n; ++l) {
        const Real depth = texture.perspective
                               ? (w[0][l] * draw.depth[0] + w[1][l] * draw.depth[1]) + w[2][l] * draw.depth[2]
                               : Real(1);
        const Real rho2 = texture_footprint2(texture, depth * (s_x - s[l] * g_x), depth * (t_x - t[l] * g_x),
                                             depth * (s_y - s[l] * g_y), depth * (t_y - t[l] * g_y));
        // rho^2 <= 1 is lambda <= 0 (magnified: level 0), without the logarithm.
        const Vec3<Real> value = rho2 <= Real(1)
                                     ? texture_at<Real>(level0, s[l], t[l])
                                     : texture_at_trilinear<Real>(texture, s[l], t[l], Real(0.5) * std::log2(rho2));
        for (int c = 0; c < 3; ++c) texel[c][l] = value[c];
    }
}

/// The bilinear T of n lanes into texel[3], texture_at()'s bits lane for
/// lane. Lanes whose four texels lie inside the image (texture_at()'s fast
/// path: most samples) are looked up in vector loops: x and y, their floors
/// (a conversion: they are non-negative), the weights and the blend in the
/// same operations and order as texture_at(), the texels read by offset; the
/// others then go through texture_at() one by one.
template <typename Real>
PHONGRAST_FILL_INLINE void bilinear_lanes(const KernelTexture& texture, int n, const Lanes<Real>& s,
                                          const Lanes<Real>& t, Lanes<Real>* texel) {
    const long long columns = texture.columns, rows = texture.rows;
    // texture_at()'s limit (2^24 texels a side), offsets in 32 bits, and the four texels of
    // an inside lane within the array (at least 2 x 2).
    const bool vectors = columns >= 2 && rows >= 2 && columns - 2 < (1ll << 24) && rows - 2 < (1ll << 24) &&
                         columns * rows <= 0x7fffffffll;
    if (!vectors) {
        for (int l = 0; l < n; ++l) {
            const Vec3<Real> value = texture_at<Real>(texture, s[l], t[l]);
            for (int c = 0; c < 3; ++c) texel[c][l] = value[c];
        }
        return;
    }
    const Real width = Real(texture.columns), height = Real(texture.rows);
    const Real column_limit = static_cast<Real>(columns - 1), row_limit = static_cast<Real>(rows - 1);
    const std::int32_t stride = texture.columns;
    Lanes<Real> a, b;
    std::int32_t offset[kSampleBatch], inside[kSampleBatch];
    int outside = 0;
    for (int l = 0; l < n; ++l) {
        const Real x = s[l] * width - Real(0.5);
        const Real y = (Real(1) - t[l]) * height - Real(0.5);
        // floor(x) in [0, columns - 2] exactly when 0 <= x < columns - 1 (a NaN is neither).
        // (& rather than &&: no branch, so that the loop vectorises.)
        const bool in = (x >= Real(0)) & (x < column_limit) & (y >= Real(0)) & (y < row_limit);
        const std::int32_t j = static_cast<std::int32_t>(in ? x : Real(0));  // floor(x)
        const std::int32_t i = static_cast<std::int32_t>(in ? y : Real(0));
        a[l] = x - static_cast<Real>(j);
        b[l] = y - static_cast<Real>(i);
        offset[l] = i * stride + j;
        inside[l] = in;
        outside += 1 - inside[l];  // (written so, the loop vectorises: GCC 12)
    }
    Lanes<Real> t00[3], t01[3], t10[3], t11[3];
    for (int l = 0; l < n; ++l) {
        const glm::vec3* p = texture.texels + offset[l];  // offset 0 for a lane outside: read, then replaced
        for (int c = 0; c < 3; ++c) {
            t00[c][l] = static_cast<Real>(p[0][c]);
            t01[c][l] = static_cast<Real>(p[1][c]);
            t10[c][l] = static_cast<Real>(p[stride][c]);
            t11[c][l] = static_cast<Real>(p[stride + 1][c]);
        }
    }
    const Real one = Real(1);
    for (int l = 0; l < n; ++l) {
        const Real w00 = (one - a[l]) * (one - b[l]), w01 = a[l] * (one - b[l]);
        const Real w10 = (one - a[l]) * b[l], w11 = a[l] * b[l];
        for (int c = 0; c < 3; ++c) {
            texel[c][l] = ((w00 * t00[c][l] + w01 * t01[c][l]) + w10 * t10[c][l]) + w11 * t11[c][l];
        }
    }
    if (outside == 0) return;
    for (int l = 0; l < n; ++l) {
        if (inside[l]) continue;
        const Vec3<Real> value = texture_at<Real>(texture, s[l], t[l]);
        for (int c = 0; c < 3; ++c) texel[c][l] = value[c];
    }
}

/// T of n lanes at their (s, t) into texel[3]: bilinear_lanes(), or texture_at() lane by lane.
template <typename Real>
PHONGRAST_FILL_INLINE void texel_lanes(const KernelTexture& texture, int n, const Lanes<Real>& s, const Lanes<Real>& t,
                                       Lanes<Real>* texel) {
    if (texture.filter == TextureFilter::bilinear) {
        bilinear_lanes(texture, n, s, t, texel);
        return;
    }
    for (int l = 0; l < n; ++l) {
        const Vec3<Real> value = texture_at<Real>(texture, s[l], t[l]);
        for (int c = 0; c < 3; ++c) texel[c][l] = value[c];
    }
}

/// T of n lanes of `draw` at their (s, t) into texel[3], by the texture's
/// filter (trilinear reads the triangle for the derivatives of (s, t)).
template <typename Real>
PHONGRAST_FILL_INLINE void filtered_texel_lanes(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w,
                                                const Lanes<Real>& s, const Lanes<Real>& t,
                                                const KernelTexture& texture, Lanes<Real>* texel) {
    if (texture.filter == TextureFilter::trilinear) {
        texture_lanes_trilinear(draw, n, w, s, t, texture, texel);
    } else {
        texel_lanes(texture, n, s, t, texel);
    }
}

/// Multiplies each lane's colour by T at its (s, t), which Phong's textured
/// faces carry in their vertices' `lit` (interpolated like every attribute).
template <typename Real>
inline void texture_lanes(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w, const KernelTexture& texture,
                          Lanes<Real>* color) {
    if (texture.texels == nullptr) return;  // no texture, or an unreadable one: T = 1
    Lanes<Real> s, t, texel[3];
    interpolate_lanes(n, w, draw.v[0]->lit[0], draw.v[1]->lit[0], draw.v[2]->lit[0], s);
    interpolate_lanes(n, w, draw.v[0]->lit[1], draw.v[1]->lit[1], draw.v[2]->lit[1], t);
    filtered_texel_lanes(draw, n, w, s, t, texture, texel);
    for (int c = 0; c < 3; ++c) {
        for (int l = 0; l < n; ++l) color[c][l] *= texel[c][l];
    }
}

/// out = 0 + factor * color per lane (shade_terms' `result(0)` and `+=`: a
/// zero sum keeps its sign as the scalar code does), or 0 without ambient.
/// One loop, not zeroing then adding: GCC zeroed the array with `rep stosq`,
/// whose start-up cost was 8% of exact Phong's batch shading.
template <typename Real>
PHONGRAST_FILL_INLINE void ambient_lanes(int n, bool ambient, Real factor, const Lanes<Real>& color, Lanes<Real>& out) {
    if (ambient) {
        for (int l = 0; l < n; ++l) out[l] = Real(0) + factor * color[l];
    } else {
        for (int l = 0; l < n; ++l) out[l] = Real(0);
    }
}

/// The surface colour of each lane into `color` (times T on textured faces), and out = its ambient term.
template <typename Real, bool UniformColor, typename Terms>
PHONGRAST_FILL_INLINE void shade_ambient_lanes(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w,
                                               const Terms& terms, const FillConstants<Real>& constants,
                                               Lanes<Real>* color, Lanes<Real>* out) {
    const auto interpolate_color = [&](int c) {
        if (UniformColor) {
            // Each broadcast from a local: read through a reference, GCC reloaded it
            // for every lane in a scalar loop (it could not rule out that the stores alias it).
            const Real uniform = constants.color[c];
            for (int l = 0; l < n; ++l) color[c][l] = uniform;
        } else {
            interpolate_lanes(n, w, draw.v[0]->color[c], draw.v[1]->color[c], draw.v[2]->color[c], color[c]);
        }
    };
    const auto ambient = [&](int c) {
        ambient_lanes(n, terms.ambient(), constants.rig_of(draw).ambient_factor[c], color[c], out[c]);
    };
    if constexpr (Terms::textured()) {
        for (int c = 0; c < 3; ++c) interpolate_color(c);
        texture_lanes(draw, n, w, constants.textures[draw.surface], color);
        for (int c = 0; c < 3; ++c) ambient(c);
    } else {
        for (int c = 0; c < 3; ++c) {
            interpolate_color(c);
            ambient(c);
        }
    }
}

/// The unit vector from each lane's camera-space point to the eye (the
/// origin), or the orthographic camera's one direction.
template <typename Real>
PHONGRAST_FILL_INLINE void eye_lanes(int n, bool eye_at_infinity, const Lanes<Real>* point, Lanes<Real>* eye) {
    if (eye_at_infinity) {
        for (int c = 0; c < 3; ++c) {
            const Real axis = kEyeAtInfinity<Real>[c];
            for (int l = 0; l < n; ++l) eye[c][l] = axis;  // orthographic: V = -f
        }
        return;
    }
    for (int c = 0; c < 3; ++c) {
        for (int l = 0; l < n; ++l) eye[c][l] = -point[c][l];
    }
    normalize_lanes(n, eye[0], eye[1], eye[2]);
}

/// The unit normal of each lane, its camera-space point (per-sample vectors)
/// and, for specular, the unit vector to the eye.
template <typename Real, bool PerSampleVectors, typename Terms>
PHONGRAST_FILL_INLINE void surface_lanes(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w,
                                         const Terms& terms, const LightVectorsAt<Real>& vectors,
                                         bool eye_at_infinity, Lanes<Real>* normal, Lanes<Real>* point,
                                         Lanes<Real>* eye) {
    for (int c = 0; c < 3; ++c) {
        interpolate_lanes(n, w, draw.v[0]->normal[c], draw.v[1]->normal[c], draw.v[2]->normal[c], normal[c]);
    }
    normalize_lanes(n, normal[0], normal[1], normal[2]);
    if (PerSampleVectors) {
        for (int c = 0; c < 3; ++c) {
            interpolate_lanes(n, w, draw.v[0]->position[c], draw.v[1]->position[c], draw.v[2]->position[c], point[c]);
        }
        if (terms.specular()) eye_lanes(n, eye_at_infinity, point, eye);
    } else if (terms.specular()) {
        for (int c = 0; c < 3; ++c) {
            const Real to_eye = vectors.to_eye[c];
            for (int l = 0; l < n; ++l) eye[c][l] = to_eye;
        }
    }
}

/// specular_from_direction(): (Ip * ks) * min(1, max(0, R.V))^n with R = (2 N) (N.L) - L, added to out.
template <typename Real>
PHONGRAST_FILL_INLINE void add_specular_lanes(int n, const Vec3<Real>& intensity_ks, Real exponent,
                                              const Lanes<Real>* normal, const Lanes<Real>* to_light,
                                              const Lanes<Real>& n_dot_l, const Lanes<Real>* eye, Lanes<Real>* out) {
    Lanes<Real> r_dot_v, highlight;
    for (int l = 0; l < n; ++l) {
        const Real rx = (Real(2) * normal[0][l]) * n_dot_l[l] - to_light[0][l];
        const Real ry = (Real(2) * normal[1][l]) * n_dot_l[l] - to_light[1][l];
        const Real rz = (Real(2) * normal[2][l]) * n_dot_l[l] - to_light[2][l];
        const Real d = (rx * eye[0][l] + ry * eye[1][l]) + rz * eye[2][l];
        const Real clamped_low = Real(0) < d ? d : Real(0);
        r_dot_v[l] = clamped_low < Real(1) ? clamped_low : Real(1);
    }
    power_lanes(n, r_dot_v, exponent, highlight);
    const Real threshold = grazing_threshold<Real>();
    for (int l = 0; l < n; ++l) {
        const Real eye_length2 = (eye[0][l] * eye[0][l] + eye[1][l] * eye[1][l]) + eye[2][l] * eye[2][l];
        const bool lit = n_dot_l[l] > threshold && eye_length2 != Real(0);
        for (int c = 0; c < 3; ++c) out[c][l] += lit ? intensity_ks[c] * highlight[l] : Real(0);
    }
}

/// Adds light k's diffuse and specular terms of each lane to out.
template <typename Real, bool PerSampleVectors, typename Terms>
PHONGRAST_FILL_INLINE void add_light_lanes(int n, std::size_t k, const Terms& terms,
                                           const std::vector<CameraLight<Real>>& lights,
                                           const LightVectorsAt<Real>& vectors, const LightRig<Real>& rig,
                                           const Lanes<Real>* normal, const Lanes<Real>* point,
                                           const Lanes<Real>* eye, const Lanes<Real>* color, Lanes<Real>* out) {
    Lanes<Real> to_light[3], n_dot_l;
    for (int c = 0; c < 3; ++c) {
        if (PerSampleVectors) {
            const Real light = lights[k].position[c];
            for (int l = 0; l < n; ++l) to_light[c][l] = light - point[c][l];
        } else {
            const Real light = vectors.to_light[k][c];
            for (int l = 0; l < n; ++l) to_light[c][l] = light;
        }
    }
    if (PerSampleVectors) normalize_lanes(n, to_light[0], to_light[1], to_light[2]);
    for (int l = 0; l < n; ++l) {
        n_dot_l[l] = (normal[0][l] * to_light[0][l] + normal[1][l] * to_light[1][l]) + normal[2][l] * to_light[2][l];
    }
    const Vec3<Real> intensity = lights[k].intensity;
    if (terms.diffuse()) {
        // diffuse_from_direction(): ((Ip * kd) * c) * N.L, or zero at or below the grazing threshold.
        const Real threshold = grazing_threshold<Real>();
        const Vec3<Real> intensity_kd = intensity * Vec3<Real>(rig.material.kd);
        for (int l = 0; l < n; ++l) {
            const bool lit = n_dot_l[l] > threshold;
            for (int c = 0; c < 3; ++c) out[c][l] += lit ? (intensity_kd[c] * color[c][l]) * n_dot_l[l] : Real(0);
        }
    }
    if (terms.specular()) {
        add_specular_lanes(n, intensity * Vec3<Real>(rig.material.ks), static_cast<Real>(rig.material.n), normal,
                           to_light, n_dot_l, eye, out);
    }
}

/// Shades the n samples whose weights are w into out (three channels).
template <typename Real, bool PerSampleVectors, bool UniformColor, int FixedCount, typename Terms>
void shade_phong_batch(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w, const Terms& terms,
                       const std::vector<CameraLight<Real>>& lights, const LightVectorsAt<Real>& vectors,
                       const FillConstants<Real>& constants, Lanes<Real>* out) {
    if constexpr (FixedCount > 0) n = FixedCount;  // a constant trip count: straight scalar code
    Lanes<Real> color[3];
    shade_ambient_lanes<Real, UniformColor>(draw, n, w, terms, constants, color, out);
    if (!(terms.diffuse() || terms.specular()) || lights.empty()) return;
    Lanes<Real> normal[3], point[3], eye[3] = {};
    surface_lanes<Real, PerSampleVectors>(draw, n, w, terms, vectors, constants.rig_of(draw).eye_at_infinity, normal,
                                          point, eye);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        add_light_lanes<Real, PerSampleVectors>(n, k, terms, lights, vectors, constants.rig_of(draw), normal, point, eye, color,
                                                out);
    }
}

/// shade_phong_batch() for n samples. Below one vector's worth (tiny triangles
/// of large meshes: a 12k-triangle mesh at 256x256 shades most of its samples
/// two to seven at a time) the samples are padded to one vector's worth with
/// copies of the first one's weights and shaded by the one-vector
/// instantiation, whose loops compile to a single vector instruction each
/// (no loop, no remainder); the padding lanes' results are never read (out
/// has kSampleBatch lanes; the caller reads n). One sample goes through the
/// single-lane instantiation, plain scalar code. Lane for lane the same
/// operations either way, so the bits do not depend on the batch's size.
template <typename Real, bool PerSampleVectors, bool UniformColor, typename Terms>
void shade_phong_samples(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w, const Terms& terms,
                         const std::vector<CameraLight<Real>>& lights, const LightVectorsAt<Real>& vectors,
                         const FillConstants<Real>& constants, Lanes<Real>* out) {
    constexpr int kVectorWidth = PHONGRAST_FILL_VECTOR_BYTES / sizeof(Real);
    if (n >= kVectorWidth) {
        shade_phong_batch<Real, PerSampleVectors, UniformColor, 0>(draw, n, w, terms, lights, vectors, constants, out);
        return;
    }
    if (n > 1) {
        Lanes<Real> padded[3];
        for (int i = 0; i < 3; ++i) {
            for (int l = 0; l < kVectorWidth; ++l) padded[i][l] = w[i][l < n ? l : 0];
        }
        shade_phong_batch<Real, PerSampleVectors, UniformColor, kVectorWidth>(draw, kVectorWidth, padded, terms, lights,
                                                                               vectors, constants, out);
        return;
    }
    for (int l = 0; l < n; ++l) {
        Lanes<Real> one_w[3], one_out[3];
        for (int i = 0; i < 3; ++i) one_w[i][0] = w[i][l];
        shade_phong_batch<Real, PerSampleVectors, UniformColor, 1>(draw, 1, one_w, terms, lights, vectors, constants,
                                                                   one_out);
        for (int c = 0; c < 3; ++c) out[c][l] = one_out[c][0];
    }
}

/// Adds n samples of `draw` (weights w, depths, image indices) to `pending`
/// after those waiting: their colour (unless one colour for all), normal and
/// camera-space point, each interpolated as interpolate_lanes() does; with
/// CentroidVectors (the seed's light vectors) the point is the triangle's
/// centroid instead, where shade_pending_phong() then computes each sample's
/// vectors as LightVectorsAt::compute() does once per triangle (the same
/// operations: normalize_lanes() is safe_normalize() lane by lane).
/// Out of line: called once or twice per triangle, and inlined it would be
/// copied into each of the kernels' many instantiations.
template <typename Real, bool UniformColor, bool CentroidVectors = false>
PHONGRAST_NOINLINE void add_pending_samples(const FillTriangle<Real>& draw, int n, const Lanes<Real>* w,
                                            const Real* depth, const std::size_t* index,
                                            PendingPhongSamples<Real>& pending) {
    const int at = pending.count;
    // The weights are the caller's, never the pending arrays: restrict lets
    // GCC vectorise without checking at run time whether they overlap.
    const Real* __restrict w0 = w[0];
    const Real* __restrict w1 = w[1];
    const Real* __restrict w2 = w[2];
    const auto add = [&](int lanes) PHONGRAST_INLINE_LAMBDA {
        const auto interpolate = [&](Real a, Real b, Real c, Real* __restrict out) PHONGRAST_INLINE_LAMBDA {
            for (int l = 0; l < lanes; ++l) out[at + l] = (w0[l] * a + w1[l] * b) + w2[l] * c;
        };
        for (int c = 0; c < 3; ++c) {
            if (!UniformColor) interpolate(draw.v[0]->color[c], draw.v[1]->color[c], draw.v[2]->color[c], pending.color[c]);
            interpolate(draw.v[0]->normal[c], draw.v[1]->normal[c], draw.v[2]->normal[c], pending.normal[c]);
            if (CentroidVectors) {
                const Real centroid = draw.centroid()[c];
                for (int l = 0; l < lanes; ++l) pending.point[c][at + l] = centroid;
            } else {
                interpolate(draw.v[0]->position[c], draw.v[1]->position[c], draw.v[2]->position[c], pending.point[c]);
            }
        }
        for (int l = 0; l < lanes; ++l) {
            pending.depth[at + l] = depth[l];
            pending.index[at + l] = index[l];
        }
    };
    if (n <= kGatherGroup && at + kGatherGroup <= kPendingSamples) {
        // The usual case (two or three samples): a whole group of lanes, so
        // each loop is a vector instruction or two instead of scalar
        // remainder code. The lanes past n (zero weights, see
        // gather_sample_batches()) land where the next samples or the
        // batch's padding will be written.
        add(kGatherGroup);
    } else {
        add(n);
    }
    pending.count = at + n;
}

/// shade_phong_batch() with per-sample light vectors on the samples waiting
/// in `pending` (of any triangles of one material), into out: lane for lane
/// the same operations, on kSampleBatch lanes (a constant trip count: whole
/// vectors, no remainder); the lanes past pending.count shade copies of the
/// first sample and are never read. Overwrites the pending normals.
template <typename Real, bool UniformColor, typename Terms>
PHONGRAST_FILL_INLINE void shade_pending_phong(PendingPhongSamples<Real>& pending, Lanes<Real>* out) {
    static_assert(kPendingSamples == kSampleBatch, "a pending batch is one batch of lanes");
    constexpr int n = kSampleBatch;
    const Terms terms;
    const FillConstants<Real>& constants = *pending.constants;
    const LightRig<Real>& rig = constants.rig[pending.surface];
    for (int c = 0; c < 3; ++c) {
        // The first sample's values from locals: read from the arrays being
        // written, they were reloaded lane by lane in scalar loops.
        const Real color = pending.color[c][0], normal = pending.normal[c][0], point = pending.point[c][0];
        for (int l = pending.count; l < n; ++l) {
            pending.color[c][l] = color;
            pending.normal[c][l] = normal;
            pending.point[c][l] = point;
        }
    }
    Lanes<Real> color[3];
    for (int c = 0; c < 3; ++c) {
        const Real uniform = constants.color[c];  // a local: see shade_ambient_lanes()
        for (int l = 0; l < n; ++l) color[c][l] = UniformColor ? uniform : pending.color[c][l];
        ambient_lanes(n, terms.ambient(), rig.ambient_factor[c], color[c], out[c]);
    }
    const std::vector<CameraLight<Real>>& lights = rig.active_lights;
    if (!(terms.diffuse() || terms.specular()) || lights.empty()) return;
    Lanes<Real>* normal = pending.normal;
    const Lanes<Real>* point = pending.point;
    normalize_lanes(n, normal[0], normal[1], normal[2]);
    Lanes<Real> eye[3];
    if (terms.specular()) eye_lanes(n, rig.eye_at_infinity, point, eye);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        add_light_lanes<Real, true>(n, k, terms, lights, *pending.vectors, rig, normal, point, eye, color, out);
    }
}

}  // namespace PHONGRAST_FILL_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_PHONG_LANES_HPP
