// Texture images as contract version 2 reads them (docs/scene-format.md,
// "Texture maps"): any format OpenImageIO reads (PNG, JPEG, EXR, ...), texels
// as stored (8-bit k is k/255, 16-bit k/65535, float as is; no transfer
// function), grey giving equal r, g, b, alpha dropped, row 0 the top row.
//
// Each file is read once per process and shared: every material, object and
// batch job that names it gets the same image (the cache is keyed by the
// file's canonical path, size and modification time, and is thread-safe).
#ifndef PHONGRAST_IO_TEXTURE_FILE_HPP
#define PHONGRAST_IO_TEXTURE_FILE_HPP

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "phongrast/texture.hpp"

namespace phongrast::io {

/// The image at `path`, from the cache when it was read before. On failure
/// (missing, unreadable, not an image, empty) returns null and, when `error`
/// is given, sets it to why ("spot.png: no such file"); failures are not
/// cached, so a file that appears later is read then.
std::shared_ptr<const TextureImage> load_texture(const std::string& path, std::string* error = nullptr);

/// An image held in memory (a glTF image from a buffer view or a data: URI).
/// `name` is for messages and its extension (.png, .jpg) picks the decoder;
/// `cache_key`, when not empty, shares the image among loads of the same
/// source (load_gltf uses the file's identity and the image's index).
std::shared_ptr<const TextureImage> load_texture_from_memory(std::string_view bytes, const std::string& name,
                                                             const std::string& cache_key,
                                                             std::string* error = nullptr);

/// Images in the cache now (for tests and long-running processes).
std::size_t texture_cache_size();
/// Forgets every cached image (images in use stay alive with their users).
void clear_texture_cache();

/// "path#size#mtime" of an existing file, by its canonical path: the identity
/// the cache uses; empty when the file cannot be found.
std::string file_identity(const std::string& path);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_TEXTURE_FILE_HPP
