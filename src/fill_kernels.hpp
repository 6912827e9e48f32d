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
#include <vector>

#include "fill_types.hpp"

// This header is compiled once per instruction set: the library's sources see
// the baseline kernels; fill_kernels_avx2.cpp defines these two macros and
// compiles it again for AVX2. Each compilation lives in its own namespace, so
// no kernel of one instruction set can stand in for another's at link time.
#ifndef PHONGRAST_FILL_ISA
#define PHONGRAST_FILL_ISA baseline
#endif
#ifndef PHONGRAST_FILL_VECTOR_BYTES
#define PHONGRAST_FILL_VECTOR_BYTES 16  // SSE2
#endif

namespace phongrast::detail {
inline namespace PHONGRAST_FILL_ISA {

/// 1 / depth of each corner, for perspective-correct weights.
template <typename Real>
void inverse_depths(const DrawTriangle<Real>& draw, Real* inverse) {
    for (int i = 0; i < 3; ++i) inverse[i] = Real(1) / draw.depth[i];
}

/// The interpolation weights q at a span's first sample and their step dq per
/// column, from the exact edge values e and steps: screen-space weights,
/// divided by each vertex's depth when perspective-correct.
template <typename Real, bool Perspective>
inline void span_weights(const std::int64_t* e, const std::int64_t* step, Real inverse_area,
                         const Real* inverse_depth, Real* q, Real* dq) {
    for (int i = 0; i < 3; ++i) {
        q[i] = static_cast<Real>(e[i]) * inverse_area;
        dq[i] = static_cast<Real>(step[i]) * inverse_area;
        if constexpr (Perspective) {
            q[i] *= inverse_depth[i];
            dq[i] *= inverse_depth[i];
        }
    }
}

/// The last guard before a pixel is written: every input was validated
/// finite, so this should never fire; if it does, the channel becomes 0 and
/// is counted (RenderStats::nonfinite_values_replaced), never written as NaN.
inline glm::vec3 finite_or_replaced(glm::vec3 pixel, std::uint64_t& replaced) {
    if (std::isfinite(pixel.x + pixel.y + pixel.z)) return pixel;
    for (int channel = 0; channel < 3; ++channel) {
        if (!std::isfinite(pixel[channel])) {
            pixel[channel] = 0.0f;
            ++replaced;
        }
    }
    return pixel;
}

/// Visits the triangle's covered samples in the target's rows with
/// interpolation weights w (summing to 1 up to rounding) and writes shade(w)
/// there. Each span starts from weights derived from exact edge values and
/// steps them by a constant per column.
template <typename Real, bool Perspective, typename Shade>
void fill_samples(const DrawTriangle<Real>& draw, FillTarget<Real>& target, Shade&& shade) {
    const Real inverse_area = Real(1) / static_cast<Real>(draw.coverage.area2);
    Real inverse_depth[3] = {Real(1), Real(1), Real(1)};
    if constexpr (Perspective) inverse_depths(draw, inverse_depth);
    Image& image = target.image;
    for_each_covered_span(draw.coverage, target.row_begin, target.row_end,
                          [&](int row, int first_column, int count, const std::int64_t* e, const std::int64_t* step) {
        Real q[3], dq[3];
        span_weights<Real, Perspective>(e, step, inverse_area, inverse_depth, q, dq);
        const std::size_t row_start = static_cast<std::size_t>(row) * static_cast<std::size_t>(image.columns);
        const std::uint32_t* owners = owner_row(target, row);
        target.covered += static_cast<std::uint64_t>(count);
        std::uint64_t written = 0;
        for (int k = 0; k < count; ++k) {
            // Painted over later: skipped. The weights below depend on k only, not on what was skipped.
            if (owners != nullptr && owners[first_column + k] != target.self) continue;
            Real w[3] = {q[0] + dq[0] * static_cast<Real>(k), q[1] + dq[1] * static_cast<Real>(k),
                         q[2] + dq[2] * static_cast<Real>(k)};
            Real depth;
            if constexpr (Perspective) {
                // Weights linear in the triangle's plane: renormalise the depth-divided ones.
                depth = Real(1) / (w[0] + w[1] + w[2]);
                for (int i = 0; i < 3; ++i) w[i] *= depth;
            } else {
                depth = w[0] * draw.depth[0] + w[1] * draw.depth[1] + w[2] * draw.depth[2];
            }
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
Vec3<Real> interpolate_lit(const DrawTriangle<Real>& d, const Real* w) {
    return w[0] * d.lit[0] + w[1] * d.lit[1] + w[2] * d.lit[2];
}

/// Gouraud: the colour was lit per vertex; interpolate it.
template <typename Real, bool Perspective>
void fill_lit(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
              const FillSetup<Real>&) {
    fill_samples<Real, Perspective>(draw, target, [&](const Real* w) { return interpolate_lit(draw, w); });
}

/// Flat: the triangle's one colour, written as is. (Interpolating it like
/// Gouraud would give weights summing to 1 only up to rounding, so the colour
/// would wander by an ulp across the triangle.)
template <typename Real, bool Perspective>
void fill_flat(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
               const FillSetup<Real>&) {
    fill_samples<Real, Perspective>(draw, target, [&](const Real*) { return draw.lit[0]; });
}

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

/// The lighting terms a batch evaluates: fixed at compile time for the specialised kernels.
template <bool Ambient, bool Diffuse, bool Specular>
struct FixedTerms {
    static constexpr bool ambient() { return Ambient; }
    static constexpr bool diffuse() { return Diffuse; }
    static constexpr bool specular() { return Specular; }
};
/// ... or asked at run time, as the general kernel does.
struct SelectedTerms {
    Lighting lighting;
    bool ambient() const { return lighting.ambient; }
    bool diffuse() const { return lighting.diffuse; }
    bool specular() const { return lighting.specular; }
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

/// Shades the n samples whose weights are w into out (three channels).
template <typename Real, bool PerSampleVectors, bool UniformColor, int FixedCount, typename Terms>
void shade_phong_batch(const DrawTriangle<Real>& draw, int n, const Lanes<Real>* w, const Terms& terms,
                       const std::vector<CameraLight<Real>>& lights, const LightVectorsAt<Real>& vectors,
                       const FillSetup<Real>& setup, Lanes<Real>* out) {
    if constexpr (FixedCount > 0) n = FixedCount;  // a constant trip count: straight scalar code
    const LightRig<Real>& rig = *setup.rig;
    const bool normals = terms.diffuse() || terms.specular();
    Lanes<Real> color[3];
    for (int c = 0; c < 3; ++c) {
        if (UniformColor) {
            for (int l = 0; l < n; ++l) color[c][l] = setup.color[c];
        } else {
            interpolate_lanes(n, w, draw.v[0]->color[c], draw.v[1]->color[c], draw.v[2]->color[c], color[c]);
        }
        for (int l = 0; l < n; ++l) out[c][l] = Real(0);
        if (terms.ambient()) {
            const Real factor = rig.ambient_factor[c];
            for (int l = 0; l < n; ++l) out[c][l] += factor * color[c][l];
        }
    }
    if (!normals || lights.empty()) return;

    Lanes<Real> normal[3], point[3], eye[3] = {};
    for (int c = 0; c < 3; ++c) {
        interpolate_lanes(n, w, draw.v[0]->normal[c], draw.v[1]->normal[c], draw.v[2]->normal[c], normal[c]);
    }
    normalize_lanes(n, normal[0], normal[1], normal[2]);
    if (PerSampleVectors) {
        for (int c = 0; c < 3; ++c) {
            interpolate_lanes(n, w, draw.v[0]->position[c], draw.v[1]->position[c], draw.v[2]->position[c], point[c]);
        }
        if (terms.specular()) {
            for (int c = 0; c < 3; ++c) {
                for (int l = 0; l < n; ++l) eye[c][l] = -point[c][l];
            }
            normalize_lanes(n, eye[0], eye[1], eye[2]);  // the eye is the camera-space origin
        }
    } else if (terms.specular()) {
        for (int c = 0; c < 3; ++c) {
            for (int l = 0; l < n; ++l) eye[c][l] = vectors.to_eye[c];
        }
    }

    const Real threshold = grazing_threshold<Real>();
    const Vec3<Real> kd(rig.material.kd), ks(rig.material.ks);
    const Real exponent = static_cast<Real>(rig.material.n);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        Lanes<Real> to_light[3], n_dot_l;
        for (int c = 0; c < 3; ++c) {
            if (PerSampleVectors) {
                const Real light = lights[k].position[c];
                for (int l = 0; l < n; ++l) to_light[c][l] = light - point[c][l];
            } else {
                for (int l = 0; l < n; ++l) to_light[c][l] = vectors.to_light[k][c];
            }
        }
        if (PerSampleVectors) normalize_lanes(n, to_light[0], to_light[1], to_light[2]);
        for (int l = 0; l < n; ++l) {
            n_dot_l[l] = (normal[0][l] * to_light[0][l] + normal[1][l] * to_light[1][l]) +
                         normal[2][l] * to_light[2][l];
        }
        const Vec3<Real> intensity = lights[k].intensity;
        if (terms.diffuse()) {
            // diffuse_from_direction(): ((Ip * kd) * c) * N.L, or zero at or below the grazing threshold.
            const Vec3<Real> intensity_kd = intensity * kd;
            for (int l = 0; l < n; ++l) {
                const bool lit = n_dot_l[l] > threshold;
                for (int c = 0; c < 3; ++c) {
                    out[c][l] += lit ? (intensity_kd[c] * color[c][l]) * n_dot_l[l] : Real(0);
                }
            }
        }
        if (terms.specular()) {
            // specular_from_direction(): (Ip * ks) * min(1, max(0, R.V))^n with R = (2 N) (N.L) - L.
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
            const Vec3<Real> intensity_ks = intensity * ks;
            for (int l = 0; l < n; ++l) {
                const Real eye_length2 = (eye[0][l] * eye[0][l] + eye[1][l] * eye[1][l]) + eye[2][l] * eye[2][l];
                const bool lit = n_dot_l[l] > threshold && eye_length2 != Real(0);
                for (int c = 0; c < 3; ++c) out[c][l] += lit ? intensity_ks[c] * highlight[l] : Real(0);
            }
        }
    }
}

/// shade_phong_batch() for n samples. Below one vector's worth (tiny triangles
/// of large meshes) the samples go one at a time through the single-lane
/// instantiation, whose loops compile to plain scalar code: the vector loops'
/// set-up would cost more than the work. Same operations either way.
template <typename Real, bool PerSampleVectors, bool UniformColor, typename Terms>
void shade_phong_samples(const DrawTriangle<Real>& draw, int n, const Lanes<Real>* w, const Terms& terms,
                         const std::vector<CameraLight<Real>>& lights, const LightVectorsAt<Real>& vectors,
                         const FillSetup<Real>& setup, Lanes<Real>* out) {
    constexpr int kVectorWidth = PHONGRAST_FILL_VECTOR_BYTES / sizeof(Real);
    if (n >= kVectorWidth) {
        shade_phong_batch<Real, PerSampleVectors, UniformColor, 0>(draw, n, w, terms, lights, vectors, setup, out);
        return;
    }
    for (int l = 0; l < n; ++l) {
        Lanes<Real> one_w[3], one_out[3];
        for (int i = 0; i < 3; ++i) one_w[i][0] = w[i][l];
        shade_phong_batch<Real, PerSampleVectors, UniformColor, 1>(draw, 1, one_w, terms, lights, vectors, setup,
                                                                   one_out);
        for (int c = 0; c < 3; ++c) out[c][l] = one_out[c][0];
    }
}

/// Visits the triangle's covered samples in the target's rows, gathering up
/// to kSampleBatch of them (across rows) with their weights as fill_samples
/// computes them, then calls shade_batch(n, w, out) and writes the batch.
/// Gathering across a triangle's rows keeps batches full for small triangles,
/// whose spans are only a few samples long.
template <typename Real, bool Perspective, typename ShadeBatch>
void fill_sample_batches(const DrawTriangle<Real>& draw, FillTarget<Real>& target, ShadeBatch&& shade_batch) {
    const Real inverse_area = Real(1) / static_cast<Real>(draw.coverage.area2);
    Real inverse_depth[3] = {Real(1), Real(1), Real(1)};
    if constexpr (Perspective) inverse_depths(draw, inverse_depth);
    Image& image = target.image;
    Lanes<Real> w[3], depth, out[3];
    std::size_t index[kSampleBatch];
    int n = 0;
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
        shade_batch(n, static_cast<const Lanes<Real>*>(w), out);
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
        n = 0;
    };
    for_each_covered_span(draw.coverage, target.row_begin, target.row_end,
                          [&](int row, int first_column, int count, const std::int64_t* e, const std::int64_t* step) {
        Real q[3], dq[3];
        span_weights<Real, Perspective>(e, step, inverse_area, inverse_depth, q, dq);
        const std::size_t row_start = static_cast<std::size_t>(row) * static_cast<std::size_t>(image.columns) +
                                      static_cast<std::size_t>(first_column);
        const std::uint32_t* owners = owner_row(target, row);
        if (owners != nullptr) owners += first_column;
        target.covered += static_cast<std::uint64_t>(count);
        for (int k = 0; k < count; ++k) {
            // Painted over later: skipped. A sample's weights depend on k only, not on the batch it joins.
            if (owners != nullptr && owners[k] != target.self) continue;
            const Real step_count = static_cast<Real>(k);
            w[0][n] = q[0] + dq[0] * step_count;
            w[1][n] = q[1] + dq[1] * step_count;
            w[2][n] = q[2] + dq[2] * step_count;
            index[n] = row_start + static_cast<std::size_t>(k);
            if (++n == kSampleBatch) flush();
        }
    });
    if (n > 0) flush();
}

/// Phong compiled for one effect set. Without diffuse or specular it interpolates no normal.
template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular, bool PerSampleVectors,
          bool UniformColor>
void fill_phong(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                const FillSetup<Real>& setup) {
    constexpr bool kNormals = Diffuse || Specular;
    const LightRig<Real>& rig = *setup.rig;
    if constexpr (kNormals && !PerSampleVectors) vectors.compute(rig.active_lights, draw.centroid, Specular);
    const FixedTerms<Ambient, Diffuse, Specular> terms;
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        shade_phong_samples<Real, PerSampleVectors, UniformColor>(draw, n, w, terms, rig.active_lights, vectors, setup,
                                                                out);
    });
}

/// Phong with neither diffuse nor specular needs no normal and no light: per
/// sample it is the ambient term of the interpolated colour, which costs what
/// Gouraud's interpolation costs. It goes sample by sample through
/// fill_samples, skipping the batches' gathering, with shade_phong_batch's
/// operations in the same order (0 + factor * colour, colour interpolated as
/// (w0 a + w1 b) + w2 c), so the image is the general kernel's bit for bit.
template <typename Real, bool Perspective, bool Ambient, bool UniformColor>
void fill_phong_unlit(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>&,
                      const FillSetup<Real>& setup) {
    const Vec3<Real> factor = setup.rig->ambient_factor;
    fill_samples<Real, Perspective>(draw, target, [&](const Real* w) {
        Vec3<Real> out(Real(0));
        if constexpr (Ambient) {
            for (int c = 0; c < 3; ++c) {
                const Real color = UniformColor ? setup.color[c]
                                                : (w[0] * draw.v[0]->color[c] + w[1] * draw.v[1]->color[c]) +
                                                      w[2] * draw.v[2]->color[c];
                out[c] += factor[c] * color;
            }
        }
        return out;
    });
}

/// Phong as a straightforward implementation writes it: every term checked per batch, every light.
template <typename Real, bool Perspective, bool PerSampleVectors>
void fill_phong_general(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                        const FillSetup<Real>& setup) {
    const LightRig<Real>& rig = *setup.rig;
    if (!PerSampleVectors) vectors.compute(rig.lights, draw.centroid, true);
    const SelectedTerms terms{rig.lighting};
    fill_sample_batches<Real, Perspective>(draw, target, [&](int n, const Lanes<Real>* w, Lanes<Real>* out) {
        if (setup.uniform_color) {
            shade_phong_samples<Real, PerSampleVectors, true>(draw, n, w, terms, rig.lights, vectors, setup, out);
        } else {
            shade_phong_samples<Real, PerSampleVectors, false>(draw, n, w, terms, rig.lights, vectors, setup, out);
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
        return c.uniform_color ? &fill_phong<Real, Perspective, Ambient, Diffuse, Specular, true, true>
                               : &fill_phong<Real, Perspective, Ambient, Diffuse, Specular, true, false>;
    }
    return c.uniform_color ? &fill_phong<Real, Perspective, Ambient, Diffuse, Specular, false, true>
                           : &fill_phong<Real, Perspective, Ambient, Diffuse, Specular, false, false>;
}

template <typename Real, bool Perspective>
FillKernel<Real> pick_kernel_for_projection(const KernelChoice& c) {
    if (c.flat) return &fill_flat<Real, Perspective>;
    if (!c.phong) return &fill_lit<Real, Perspective>;
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

/// The single dispatch of a render.
template <typename Real>
FillKernel<Real> pick_kernel(const KernelChoice& c) {
    return c.perspective ? pick_kernel_for_projection<Real, true>(c) : pick_kernel_for_projection<Real, false>(c);
}

}  // namespace PHONGRAST_FILL_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNELS_HPP
