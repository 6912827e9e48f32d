// Texture maps as contract version 2 states them (docs/scene-format.md,
// "Texture maps"): texels as stored (no transfer function), row 0 the top
// row, (s, t) with t = 0 at the bottom row, and the bilinear lookup on
// level 0 with repeat, clamp-to-edge or mirrored-repeat indices.
#ifndef PHONGRAST_TEXTURE_HPP
#define PHONGRAST_TEXTURE_HPP

#include <memory>
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

}  // namespace phongrast

#endif  // PHONGRAST_TEXTURE_HPP
