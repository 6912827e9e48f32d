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

#include <cmath>
#include <cstdint>
#include <vector>

#include "clipping.hpp"
#include "phongrast/image.hpp"
#include "raster.hpp"
#include "shading.hpp"

namespace phongrast::detail {

template <typename Real>
struct DrawTriangle {
    CoverageTriangle coverage;
    Varyings<Real> v[3];  ///< in coverage order
    Real depth[3];
    Real inverse_depth[3];
    Vec3<Real> centroid;  ///< camera space, of the source triangle (seed light vectors)
};

/// The rows of the image one task fills, and what it counts.
template <typename Real>
struct FillTarget {
    Image& image;
    std::vector<Real>& depth_buffer;
    int row_begin, row_end;
    bool depth_test;
    std::uint64_t samples;
    std::uint64_t replaced;
};

/// Per-render constants the kernels read.
template <typename Real>
struct FillSetup {
    const LightRig<Real>* rig = nullptr;
    bool uniform_color = true;
    Vec3<Real> color{Real(1)};  ///< the colour of every vertex when uniform_color
};

template <typename Real>
using FillKernel = void (*)(const DrawTriangle<Real>&, FillTarget<Real>&, LightVectorsAt<Real>&,
                            const FillSetup<Real>&);

/// Visits the triangle's covered samples in the target's rows with
/// interpolation weights w (summing to 1 up to rounding) and writes shade(w)
/// there. Each span starts from weights derived from exact edge values and
/// steps them by a constant per column.
template <typename Real, bool Perspective, typename Shade>
void fill_samples(const DrawTriangle<Real>& draw, FillTarget<Real>& target, Shade&& shade) {
    const Real inverse_area = Real(1) / static_cast<Real>(draw.coverage.area2);
    Image& image = target.image;
    for_each_covered_span(draw.coverage, target.row_begin, target.row_end,
                          [&](int row, int first_column, int count, const std::int64_t* e, const std::int64_t* step) {
        // q: screen-space weights, divided by depth when perspective-correct.
        Real q[3], dq[3];
        for (int i = 0; i < 3; ++i) {
            q[i] = static_cast<Real>(e[i]) * inverse_area;
            dq[i] = static_cast<Real>(step[i]) * inverse_area;
            if constexpr (Perspective) {
                q[i] *= draw.inverse_depth[i];
                dq[i] *= draw.inverse_depth[i];
            }
        }
        const std::size_t row_start = static_cast<std::size_t>(row) * static_cast<std::size_t>(image.columns);
        std::uint64_t written = 0;
        for (int k = 0; k < count; ++k) {
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
            glm::vec3 out(shade(w));
            if (!std::isfinite(out.x + out.y + out.z)) {
                // Last guard: every input was validated finite, so this should never fire.
                for (int channel = 0; channel < 3; ++channel) {
                    if (!std::isfinite(out[channel])) {
                        out[channel] = 0.0f;
                        ++target.replaced;
                    }
                }
            }
            image.pixels[index] = out;
            ++written;
        }
        target.samples += written;
    });
}

template <typename Real>
Vec3<Real> interpolate_lit(const DrawTriangle<Real>& d, const Real* w) {
    return w[0] * d.v[0].lit + w[1] * d.v[1].lit + w[2] * d.v[2].lit;
}

template <typename Real>
Vec3<Real> surface_color(const DrawTriangle<Real>& d, const Real* w, const FillSetup<Real>& setup,
                         bool uniform) {
    return uniform ? setup.color : w[0] * d.v[0].color + w[1] * d.v[1].color + w[2] * d.v[2].color;
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
    fill_samples<Real, Perspective>(draw, target, [&](const Real*) { return draw.v[0].lit; });
}

/// Phong compiled for one effect set. Without diffuse or specular it interpolates no normal.
template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular, bool PerSampleVectors,
          bool UniformColor>
void fill_phong(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                const FillSetup<Real>& setup) {
    constexpr bool kNormals = Diffuse || Specular;
    const LightRig<Real>& rig = *setup.rig;
    if constexpr (kNormals && !PerSampleVectors) vectors.compute(rig.active_lights, draw.centroid, Specular);
    fill_samples<Real, Perspective>(draw, target, [&](const Real* w) {
        const Vec3<Real> color = surface_color(draw, w, setup, UniformColor);
        Vec3<Real> normal(Real(0));
        if constexpr (kNormals) {
            normal = safe_normalize<Real>(w[0] * draw.v[0].normal + w[1] * draw.v[1].normal +
                                          w[2] * draw.v[2].normal);
            if constexpr (PerSampleVectors) {
                vectors.compute(rig.active_lights,
                                w[0] * draw.v[0].position + w[1] * draw.v[1].position + w[2] * draw.v[2].position,
                                Specular);
            }
        }
        return shade_terms<Real, Ambient, Diffuse, Specular>(rig, vectors, normal, color);
    });
}

/// Phong as a straightforward implementation writes it: every term checked per sample.
template <typename Real, bool Perspective, bool PerSampleVectors>
void fill_phong_general(const DrawTriangle<Real>& draw, FillTarget<Real>& target, LightVectorsAt<Real>& vectors,
                        const FillSetup<Real>& setup) {
    const LightRig<Real>& rig = *setup.rig;
    if (!PerSampleVectors) vectors.compute(rig.lights, draw.centroid, true);
    fill_samples<Real, Perspective>(draw, target, [&](const Real* w) {
        const Vec3<Real> color = surface_color(draw, w, setup, setup.uniform_color);
        const Vec3<Real> normal =
            safe_normalize<Real>(w[0] * draw.v[0].normal + w[1] * draw.v[1].normal + w[2] * draw.v[2].normal);
        if (PerSampleVectors) {
            vectors.compute(rig.lights,
                            w[0] * draw.v[0].position + w[1] * draw.v[1].position + w[2] * draw.v[2].position, true);
        }
        return shade_general(rig, vectors, normal, color);
    });
}

/// What decides the kernel.
struct KernelChoice {
    bool phong = false;
    bool flat = false;
    bool perspective = true;
    bool specialized = true;
    bool per_sample_vectors = true;
    bool uniform_color = true;
    EffectSet effects;
};

template <typename Real, bool Perspective, bool Ambient, bool Diffuse, bool Specular>
FillKernel<Real> pick_phong_vectors_color(const KernelChoice& c) {
    if (!Diffuse && !Specular) {
        // No normals and no light vectors: only the colour varies.
        return c.uniform_color ? &fill_phong<Real, Perspective, Ambient, false, false, false, true>
                               : &fill_phong<Real, Perspective, Ambient, false, false, false, false>;
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

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FILL_KERNELS_HPP
