#include "gltf_materials.hpp"

#include <cstring>
#include <filesystem>

#include "phongrast/io/error.hpp"
#include "phongrast/io/texture_file.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast::io {
namespace {

using nlohmann::json;

TextureWrap wrap_mode(const json& sampler, const char* key, const std::string& where, const std::string& path) {
    switch (gltf_integer(sampler, key, where, path, 10497)) {
        case 10497: return TextureWrap::repeat;
        case 33071: return TextureWrap::clamp_to_edge;
        case 33648: return TextureWrap::mirrored_repeat;
        default:
            gltf_fail(path, where + "/" + key,
                      "expected 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 (MIRRORED_REPEAT), got " +
                          sampler[key].dump());
    }
}

/// A URI's %XX escapes decoded (glTF URIs are URI-encoded: "my%20texture.png").
std::string decode_percent(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

/// ".png" or ".jpg" for a MIME type, so the decoder is chosen by name.
std::string extension_for(const std::string& mime) {
    if (mime == "image/jpeg") return ".jpg";
    if (mime == "image/png") return ".png";
    if (mime == "image/x-exr") return ".exr";
    return ".png";
}

std::string decode_base64(std::string_view text, const std::string& path, const std::string& where) {
    std::string out;
    out.reserve(text.size() / 4 * 3);
    std::uint32_t bits = 0;
    int count = 0;
    for (const char c : text) {
        if (c == '=') break;
        const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const char* at = c != '\0' ? std::strchr(alphabet, c) : nullptr;
        if (at == nullptr) gltf_fail(path, where, "invalid base64 character in the data URI");
        bits = (bits << 6) | static_cast<std::uint32_t>(at - alphabet);
        if (++count == 4) {
            out.push_back(static_cast<char>(bits >> 16));
            out.push_back(static_cast<char>(bits >> 8));
            out.push_back(static_cast<char>(bits));
            bits = 0;
            count = 0;
        }
    }
    if (count >= 2) out.push_back(static_cast<char>(bits >> (count == 2 ? 4 : 10)));
    if (count == 3) out.push_back(static_cast<char>(bits >> 2));
    return out;
}

}  // namespace

std::string decode_data_uri(const std::string& uri, const std::string& path, const std::string& where) {
    const std::size_t comma = uri.find(";base64,");
    if (uri.rfind("data:", 0) != 0 || comma == std::string::npos) gltf_fail(path, where, "expected a base64 data URI");
    return decode_base64(std::string_view(uri).substr(comma + 8), path, where);
}

GltfMaterials::Use GltfMaterials::use(const json& primitive, const std::string& where,
                                      std::vector<FaceMaterial>& materials) {
    const std::int64_t index = gltf_integer(primitive, "material", where, path_);
    if (index < 0) return Use{kNoIndex, 0};
    const auto known = read_.find(index);
    if (known != read_.end()) return known->second;
    if (static_cast<std::size_t>(index) >= gltf_array(document_, "materials").size()) {
        gltf_fail(path_, where + "/material", "no such material");
    }
    Use use;
    FaceMaterial material = read(index, use.texcoord_set);
    use.slot = static_cast<std::uint32_t>(materials.size());
    materials.push_back(std::move(material));
    read_.emplace(index, use);
    return use;
}

FaceMaterial GltfMaterials::read(std::int64_t index, std::int64_t& texcoord_set) {
    const json& object = gltf_array(document_, "materials")[static_cast<std::size_t>(index)];
    const std::string where = "/materials/" + std::to_string(index);
    if (!object.is_object()) gltf_fail(path_, where, "expected an object");
    FaceMaterial material;
    const auto name = object.find("name");
    material.name = name != object.end() && name->is_string() ? name->get<std::string>() : where;
    const json& pbr = gltf_object(object, "pbrMetallicRoughness");
    if (pbr.contains("baseColorFactor")) {
        const std::string at = where + "/pbrMetallicRoughness/baseColorFactor";
        const json& factor = pbr["baseColorFactor"];
        if (!factor.is_array() || factor.size() != 4) gltf_fail(path_, at, "expected 4 numbers");
        for (int k = 0; k < 3; ++k) {
            const json& v = factor[static_cast<std::size_t>(k)];
            if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1.0)) {
                gltf_fail(path_, at, "expected numbers from 0 to 1, got " + v.dump());
            }
            material.color_factor[k] = static_cast<float>(v.get<double>());
        }
    }
    if (pbr.contains("baseColorTexture")) {
        material.texture = texture(pbr["baseColorTexture"], where + "/pbrMetallicRoughness/baseColorTexture",
                                   material.name, texcoord_set);
    }
    return material;
}

std::optional<TextureMap> GltfMaterials::texture(const json& info, const std::string& where,
                                                 const std::string& material, std::int64_t& texcoord_set) {
    const std::int64_t index = gltf_integer(info, "index", where, path_);
    const json& textures = gltf_array(document_, "textures");
    if (index < 0 || static_cast<std::size_t>(index) >= textures.size()) gltf_fail(path_, where + "/index", "no such texture");
    texcoord_set = gltf_integer(info, "texCoord", where, path_, 0);
    const std::string texture_where = "/textures/" + std::to_string(index);
    const json& texture = textures[static_cast<std::size_t>(index)];
    TextureMap map;
    const std::int64_t sampler = gltf_integer(texture, "sampler", texture_where, path_);
    if (sampler >= 0) {
        const json& samplers = gltf_array(document_, "samplers");
        const std::string sampler_where = "/samplers/" + std::to_string(sampler);
        if (static_cast<std::size_t>(sampler) >= samplers.size()) gltf_fail(path_, texture_where + "/sampler", "no such sampler");
        const json& object = samplers[static_cast<std::size_t>(sampler)];
        map.wrap_s = wrap_mode(object, "wrapS", sampler_where, path_);
        map.wrap_t = wrap_mode(object, "wrapT", sampler_where, path_);
    }
    const std::int64_t source = gltf_integer(texture, "source", texture_where, path_);
    std::string why = "the texture has no source image";
    if (source >= 0) map.image = image(source, material, why);
    if (!map.image) {
        warnings_.push_back(path_ + ": material " + material + ": texture " + texture_where + " cannot be read (" + why +
                            "); its faces draw with T = 1");
    }
    return map;
}

std::shared_ptr<const TextureImage> GltfMaterials::image(std::int64_t index, const std::string& material,
                                                         std::string& why) {
    (void)material;
    const json& images = gltf_array(document_, "images");
    const std::string where = "/images/" + std::to_string(index);
    if (static_cast<std::size_t>(index) >= images.size()) gltf_fail(path_, where, "no such image");
    const json& image = images[static_cast<std::size_t>(index)];
    if (!image.is_object()) gltf_fail(path_, where, "expected an object");
    const std::string mime = image.value("mimeType", std::string());
    const std::int64_t view = gltf_integer(image, "bufferView", where, path_);
    // Images inside the file are shared by every load of the same file (its identity and the image's index).
    const std::string identity = file_identity(path_);
    const std::string key = identity.empty() ? std::string() : identity + where;
    if (view >= 0) {
        const std::string name = path_ + where + extension_for(mime);
        return load_texture_from_memory(accessors_.buffer_view(view), name, key, &why);
    }
    const auto uri_value = image.find("uri");
    if (uri_value == image.end() || !uri_value->is_string()) gltf_fail(path_, where, "expected a uri or a bufferView");
    const std::string uri = uri_value->get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
        const std::string bytes = decode_data_uri(uri, path_, where + "/uri");
        const std::size_t semicolon = uri.find(';');
        const std::string data_mime = uri.substr(5, semicolon == std::string::npos ? 0 : semicolon - 5);
        return load_texture_from_memory(bytes, path_ + where + extension_for(mime.empty() ? data_mime : mime), key, &why);
    }
    const std::filesystem::path folder = std::filesystem::path(path_).parent_path();
    image_files.push_back((folder / decode_percent(uri)).string());
    return load_texture(image_files.back(), &why);
}

}  // namespace phongrast::io
