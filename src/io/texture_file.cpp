#include "phongrast/io/texture_file.hpp"

#include <filesystem>
#include <map>
#include <mutex>

#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"

namespace phongrast::io {
namespace {

/// The contract's texels from the file's channels: grey (1 or 2 channels)
/// gives r = g = b, RGB and more take the first three; alpha is dropped.
std::shared_ptr<const TextureImage> to_texture(const StoredImage& stored, const std::string& name) {
    auto image = std::make_shared<TextureImage>();
    image->rows = stored.rows;
    image->columns = stored.columns;
    image->name = name;
    const auto channels = static_cast<std::size_t>(stored.channels);
    const std::size_t count = static_cast<std::size_t>(stored.rows) * static_cast<std::size_t>(stored.columns);
    image->texels.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float* pixel = stored.values.data() + i * channels;
        image->texels[i] = channels < 3 ? glm::vec3(pixel[0]) : glm::vec3(pixel[0], pixel[1], pixel[2]);
    }
    return image;
}

/// One cached image: loaded once, under its own lock, so that two threads
/// asking for the same file wait for one read while other files load freely.
struct CacheEntry {
    std::mutex mutex;
    std::shared_ptr<const TextureImage> image;
};

struct TextureCache {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<CacheEntry>> entries;

    std::shared_ptr<CacheEntry> entry(const std::string& key) {
        const std::lock_guard<std::mutex> lock(mutex);
        std::shared_ptr<CacheEntry>& entry = entries[key];
        if (!entry) entry = std::make_shared<CacheEntry>();
        return entry;
    }
};

TextureCache& cache() {
    static TextureCache instance;
    return instance;
}

/// `read()` once per key; a failed read leaves the entry empty for the next try.
template <class Read>
std::shared_ptr<const TextureImage> cached(const std::string& key, const Read& read, std::string* error) {
    const std::shared_ptr<CacheEntry> entry = cache().entry(key);
    const std::lock_guard<std::mutex> lock(entry->mutex);
    if (entry->image) return entry->image;
    try {
        entry->image = read();
    } catch (const FileError& failure) {
        if (error != nullptr) *error = failure.what();
        return nullptr;
    }
    return entry->image;
}

}  // namespace

std::string file_identity(const std::string& path) {
    std::error_code failed;
    const std::filesystem::path canonical = std::filesystem::canonical(path, failed);
    if (failed) return {};
    const auto size = std::filesystem::file_size(canonical, failed);
    if (failed) return {};
    const auto time = std::filesystem::last_write_time(canonical, failed);
    if (failed) return {};
    return canonical.string() + "#" + std::to_string(size) + "#" +
           std::to_string(time.time_since_epoch().count());
}

std::shared_ptr<const TextureImage> load_texture(const std::string& path, std::string* error) {
    std::error_code failed;
    const std::filesystem::file_status status = std::filesystem::status(path, failed);
    if (!std::filesystem::exists(status)) {
        if (error != nullptr) *error = path + ": no such file";
        return nullptr;
    }
    if (std::filesystem::is_directory(status)) {
        if (error != nullptr) *error = path + ": is a folder; expected an image file";
        return nullptr;
    }
    const std::string key = file_identity(path);
    if (key.empty()) {
        if (error != nullptr) *error = path + ": cannot read the file";
        return nullptr;
    }
    return cached(key, [&] { return to_texture(read_stored_image(path), path); }, error);
}

std::shared_ptr<const TextureImage> load_texture_from_memory(std::string_view bytes, const std::string& name,
                                                             const std::string& cache_key, std::string* error) {
    const auto read = [&] { return to_texture(read_stored_image(bytes, name), name); };
    if (cache_key.empty()) {
        try {
            return read();
        } catch (const FileError& failure) {
            if (error != nullptr) *error = failure.what();
            return nullptr;
        }
    }
    return cached("memory:" + cache_key, read, error);
}

std::size_t texture_cache_size() {
    TextureCache& instance = cache();
    const std::lock_guard<std::mutex> lock(instance.mutex);
    std::size_t count = 0;
    for (const auto& entry : instance.entries) {
        const std::lock_guard<std::mutex> entry_lock(entry.second->mutex);
        if (entry.second->image) ++count;
    }
    return count;
}

void clear_texture_cache() {
    TextureCache& instance = cache();
    const std::lock_guard<std::mutex> lock(instance.mutex);
    instance.entries.clear();
}

}  // namespace phongrast::io
