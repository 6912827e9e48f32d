// glTF materials as contract version 2 reads them ("Materials", "Texture
// maps"): a primitive's material gives the colour factor (baseColorFactor,
// rgb) and the texture (baseColorTexture: its image, its sampler's wrapS and
// wrapT, its texCoord set), never the coefficients. Images come from a buffer
// view (embedded in a GLB), a data: URI, or a file relative to the glTF file.
#ifndef PHONGRAST_IO_GLTF_MATERIALS_HPP
#define PHONGRAST_IO_GLTF_MATERIALS_HPP

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf_accessors.hpp"
#include "phongrast/material.hpp"

namespace phongrast::io {

class GltfMaterials {
public:
    GltfMaterials(const nlohmann::json& document, const GltfAccessors& accessors, const std::string& path,
                  std::vector<std::string>& warnings)
        : document_(document), accessors_(accessors), path_(path), warnings_(warnings) {}

    struct Use {
        std::uint32_t slot = 0xffffffffu;  ///< index into `materials`, or kNoIndex (no material)
        std::int64_t texcoord_set = 0;     ///< the TEXCOORD_n the texture reads
    };

    /// The primitive's material (`/meshes/m/primitives/p` at `where`), read
    /// once per material index and appended to `materials`.
    Use use(const nlohmann::json& primitive, const std::string& where, std::vector<FaceMaterial>& materials);

    /// The image files read so far (MeshFile::side_files).
    std::vector<std::string> image_files;

private:
    FaceMaterial read(std::int64_t index, std::int64_t& texcoord_set);
    std::optional<TextureMap> texture(const nlohmann::json& info, const std::string& where, const std::string& material,
                                      std::int64_t& texcoord_set);
    std::shared_ptr<const TextureImage> image(std::int64_t index, const std::string& material, std::string& why);

    const nlohmann::json& document_;
    const GltfAccessors& accessors_;
    const std::string& path_;
    std::vector<std::string>& warnings_;
    std::map<std::int64_t, Use> read_;
};

/// The bytes of a base64 data: URI's payload; throws FileError naming `where`.
std::string decode_data_uri(const std::string& uri, const std::string& path, const std::string& where);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_GLTF_MATERIALS_HPP
