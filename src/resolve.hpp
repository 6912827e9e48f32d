// The resolve (internal header): from the samples of supersampling to
// pixels. An ordered grid renders one image samples_per_axis times larger
// and box-filters it; a rotated grid renders one pass per sample position
// and averages the passes.
#ifndef PHONGRAST_SRC_RESOLVE_HPP
#define PHONGRAST_SRC_RESOLVE_HPP

#include <glm/vec2.hpp>

#include "phongrast/image.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Renders one pass of rows x columns samples, each sample_offset pixels
/// from its pixel's centre, into `image`, adding its counts to `stats`.
class PassRenderer {
public:
    virtual void render_pass(int rows, int columns, glm::dvec2 sample_offset, RenderStats& stats, Image& image) = 0;

protected:
    ~PassRenderer() = default;
};

/// The resolve's intermediate images, kept from frame to frame.
struct ResolveImages {
    Image samples;  ///< ordered grid: the image in samples
    Image pass;     ///< rotated grid: one pass
    Image sum;      ///< rotated grid: the running sum of the passes
};

/// Renders every pass samples_per_axis asks for and resolves them into
/// result.image; result.stats gets the triangle counts of one pass and the
/// work of all of them.
void render_and_resolve(const Scene& scene, const RenderOptions& options, PassRenderer& passes,
                        ResolveImages& images, RenderResult& result);

/// Rotated grid: the offset from the pixel centre of sample (i, j) of s x s, in pixels.
glm::dvec2 rotated_grid_offset(int i, int j, int s);

/// Averages each factor x factor block of `samples` into `pixels` (resized, memory reused).
void box_downsample(const Image& samples, int factor, int rows, int columns, Image& pixels);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_RESOLVE_HPP
