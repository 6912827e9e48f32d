// Texture maps as contract version 2 states them (docs/scene-format.md,
// "Texture maps"): texels as stored (no transfer function), row 0 the top
// row, (s, t) with t = 0 at the bottom row, and the bilinear lookup on
// level 0 with repeat, clamp-to-edge or mirrored-repeat indices; and the
// mip pyramid the trilinear filter (not part of the contract) reads.
#ifndef PHONGRAST_TEXTURE_HPP
#define PHONGRAST_TEXTURE_HPP

#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace phongrast {

/// How a texel index outside [0, size) is brought back in (OpenGL's wrap modes).
enum class TextureWrap {
    repeat,           ///< index mod size (the default)
    clamp_to_edge,    ///< clamped to [0, size - 1]
    mirrored_repeat,  ///< as OpenGL's GL_MIRRORED_REPEAT
};
/// "repeat", "clamp_to_edge" or "mirrored_repeat"; throws std::invalid_argument otherwise.
TextureWrap parse_texture_wrap(std::string_view text);
const char* to_string(TextureWrap wrap);

/// How a texture is sampled (RenderOptions::texture_filter). The contract's
/// picture is `bilinear`; the others are accuracy knobs.
enum class TextureFilter {
    nearest,    ///< the texel whose centre is nearest
    bilinear,   ///< the contract: GL_LINEAR on level 0
    trilinear,  ///< GL_LINEAR_MIPMAP_LINEAR on a box-filtered pyramid built once per texture
};
/// "nearest", "bilinear" or "trilinear"; throws std::invalid_argument otherwise.
TextureFilter parse_texture_filter(std::string_view text);
const char* to_string(TextureFilter filter);

/// One level of a mip pyramid: rows x columns texels, row-major, row 0 the top row.
struct MipLevel {
    int rows = 0;
    int columns = 0;
    std::vector<glm::vec3> texels;

    const glm::vec3& at(int row, int column) const {
        return texels[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                      static_cast<std::size_t>(column)];
    }
};

/// Level k + 1 of a mip pyramid from level k (docs/accuracy.md, "Trilinear"):
/// max(1, floor(size / 2)) texels along each axis, each the average of the
/// part of level k it covers when both levels span the same [0, 1] x [0, 1]
/// (a 2 x 2 box for even sizes; for an odd size n the box is n / floor(n / 2)
/// texels wide, its end texels weighted by the part inside it), in double,
/// rounded to float once.
MipLevel next_mip_level(const MipLevel& level);

/// Built once per image, on first use (TextureImage::mip_levels()).
class MipPyramidCache {
public:
    MipPyramidCache() = default;
    /// A copy of an image builds its own pyramid (from its own texels) when asked.
    MipPyramidCache(const MipPyramidCache&) : state_(std::make_unique<State>()) {}
    MipPyramidCache& operator=(const MipPyramidCache&) {
        state_ = std::make_unique<State>();
        return *this;
    }
    MipPyramidCache(MipPyramidCache&&) noexcept = default;
    MipPyramidCache& operator=(MipPyramidCache&&) noexcept = default;
    ~MipPyramidCache() = default;

private:
    friend struct TextureImage;
    struct State {
        std::once_flag built;
        std::vector<MipLevel> levels;
    };
    std::unique_ptr<State> state_ = std::make_unique<State>();
};

/// An image used as a texture: linear RGB texels exactly as the file stores
/// them (8-bit k is k/255, 16-bit k/65535, float as is; grey gives equal
/// r, g, b; alpha is dropped), row 0 the top row.
struct TextureImage {
    int rows = 0;
    int columns = 0;
    std::vector<glm::vec3> texels;  ///< rows * columns, row-major
    std::string name;               ///< the file it came from, for messages

    const glm::vec3& at(int row, int column) const {
        return texels[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                      static_cast<std::size_t>(column)];
    }

    /// Levels 1, 2, ... of the image's mip pyramid, down to 1 x 1 (empty for a
    /// 1 x 1 or empty image; level 0 is the image itself). Built on the first
    /// call, once, whichever thread calls first (the others wait for it), and
    /// kept with the image: every material, object and frame using it shares
    /// the one pyramid. The texels must not change after that first call.
    const std::vector<MipLevel>& mip_levels() const;

private:
    mutable MipPyramidCache mip_cache_;
};

/// A texture as a material uses it: the image (shared by every material and
/// object that uses the same file) and how s and t wrap.
struct TextureMap {
    std::shared_ptr<const TextureImage> image;  ///< null: unreadable, drawn with T = 1
    TextureWrap wrap_s = TextureWrap::repeat;
    TextureWrap wrap_t = TextureWrap::repeat;
};

/// The contract's bilinear lookup T(s, t) in double precision (the reference
/// the renderer's kernels are tested against). A map without an image gives 1.
glm::dvec3 sample_bilinear(const TextureMap& map, double s, double t);

/// The trilinear filter's level of detail (OpenGL's lambda) in double: log2 of
/// the larger of the lengths of (ds/dx W, dt/dx H) and (ds/dy W, dt/dy H), the
/// texels one step along x and along y covers on level 0 (W x H texels).
/// Zero derivatives give -infinity (magnified); an infinite or NaN one gives
/// +infinity (the last level).
double mip_lambda(double ds_dx, double dt_dx, double ds_dy, double dt_dy, int columns, int rows);

/// GL_LINEAR_MIPMAP_LINEAR in double, the reference of the kernels' trilinear
/// lookup: lambda <= 0 (or NaN's opposite, -infinity) is sample_bilinear() on
/// level 0; lambda >= the last level q is bilinear on level q; between, the
/// bilinear lookups on levels floor(lambda) and floor(lambda) + 1 blended by
/// lambda - floor(lambda). Every level wraps as the map says. A NaN lambda
/// counts as +infinity.
glm::dvec3 sample_trilinear(const TextureMap& map, double s, double t, double lambda);

}  // namespace phongrast

#endif  // PHONGRAST_TEXTURE_HPP
