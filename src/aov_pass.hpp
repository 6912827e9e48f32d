// The extra outputs' pass (internal header): after the colour fill, walk the
// binned triangles of each band again and write, for each sample, the depth,
// shading normal and triangle id of the surface that painted it. A separate
// pass so that a render asking for no extra output runs exactly the colour
// fill; then the resolve of the samples into pixels.
#ifndef PHONGRAST_SRC_AOV_PASS_HPP
#define PHONGRAST_SRC_AOV_PASS_HPP

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "binning.hpp"
#include "huge_page_pool.hpp"
#include "fill_types.hpp"
#include "phongrast/aov.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"
#include "progress_monitor.hpp"

namespace phongrast::detail {

struct VisibleLayer;

/// The extra outputs of one render pass at its own resolution (the
/// supersampled image, or one rotated-grid pass): one entry per sample.
struct AovSamples {
    int rows = 0, columns = 0;
    std::vector<float> depth;          ///< z_c; +infinity where nothing painted
    std::vector<glm::vec3> normal;     ///< world space, unit (or zero)
    std::vector<std::int32_t> id;      ///< source triangle, -1 where nothing painted
    std::vector<std::uint8_t> covered; ///< 1 where some triangle covers the sample
    std::vector<glm::vec2> uv;         ///< (s, t); zero where nothing painted
    std::vector<float> distance;       ///< distance from the eye; +infinity where nothing painted

    /// Sized for rows x columns with the planes `planes` asks for, all background; memory reused.
    void reset(int rows, int columns, const AovRequest& planes);
};

/// What the pass reads of the frame the colour fill just drew.
template <typename Real>
struct AovPassInput {
    const Bins<Real>* bins = nullptr;  ///< the colour fill's bins: painter's order within each band
    Shader shader = Shader::phong;
    bool perspective = true;              ///< the shading's weights are perspective-correct
    const Real* depth_buffer = nullptr;   ///< the colour fill's final depths with Visibility::depth_buffer, else null
    const std::vector<Triangle>* triangles = nullptr;
    const FrameVector<Varyings<Real>>* vertices = nullptr;  ///< camera-space varyings, by mesh vertex
    const CameraFrame* frame = nullptr;
    /// The pass's sample offset (View::sample_offset): sample (row, column) lies at the frame's
    /// pixel coordinates (column + 0.5 + offset.x, row + 0.5 + offset.y), where the distance's ray goes.
    glm::dvec2 sample_offset{0.0};
    /// The vertices' (s, t) is in their `lit` (Phong and flat of a scene with
    /// texture coordinates): the uv plane interpolates it; else it stays zero.
    bool uv_in_lit = false;
    /// The caller's index of each triangle of a reordered mesh (mesh_order.hpp), which the id output
    /// gives; null when the mesh is rendered in the caller's order.
    const std::uint32_t* original_triangle = nullptr;
    /// The colour fill's owner buffers, one per band (fill_driver.hpp), when it
    /// shaded only the visible samples: each sample's last triangle is there
    /// already, so coverage and ids alone are read from them, not found again.
    const VisibleLayer* band_layers = nullptr;
};

/// Fills `out` (already reset) for every band, in parallel over bands.
template <typename Real>
void run_aov_pass(const AovPassInput<Real>& input, const AovRequest& planes, AovSamples& out,
                  ProgressMonitor& progress);

/// Adds the pixels of `samples` (factor x factor samples per pixel) into
/// `out`, by the rule of AovPlanes: the nearest covered sample gives depth,
/// distance, normal, id and uv, unless `out` already holds a nearer one from an earlier
/// rotated-grid pass; alpha counts covered samples until finish_aovs.
/// `planes` are the planes `out` was reset with (sample_planes_for).
void resolve_aovs(const AovSamples& samples, int factor, const AovRequest& planes, AovPlanes& out);

/// After the last resolve: alpha becomes the covered fraction, and planes
/// used only inside (depth to pick the nearest sample) are emptied.
void finish_aovs(const AovRequest& requested, int samples_per_pixel, AovPlanes& out);

/// `out` sized for rows x columns with the requested planes, background everywhere.
void reset_aov_planes(int rows, int columns, const AovRequest& requested, AovPlanes& out);

/// The planes the sample pass must fill to resolve `requested` with `factor` samples per axis:
/// depth too whenever a pixel has several samples to choose the nearest from, and
/// whenever distance is asked for (it is computed from the depth).
AovRequest sample_planes_for(const AovRequest& requested, int factor);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_AOV_PASS_HPP
