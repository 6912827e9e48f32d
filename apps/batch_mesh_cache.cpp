#include "batch_mesh_cache.hpp"

#include <set>

#include "phongrast/io/texture_file.hpp"
#include "phongrast/mesh.hpp"

namespace phongrast::cli {
namespace {

template <typename T>
std::size_t vector_bytes(const std::vector<T>& values) {
    return values.capacity() * sizeof(T);
}

/// Every side file still as it was when the mesh was read (a missing one still missing).
bool sides_unchanged(const std::vector<std::pair<std::string, std::string>>& sides) {
    for (const auto& [path, identity] : sides) {
        if (io::file_identity(path) != identity) return false;
    }
    return true;
}

/// The canonical path in an io::file_identity ("path#size#mtime"; the path may hold '#').
std::string identity_path(const std::string& identity) {
    const std::size_t mtime = identity.rfind('#');
    const std::size_t size = mtime == std::string::npos || mtime == 0 ? std::string::npos : identity.rfind('#', mtime - 1);
    return size == std::string::npos ? identity : identity.substr(0, size);
}

}  // namespace

std::size_t mesh_file_bytes(const io::MeshFile& file) {
    const Mesh& mesh = file.mesh;
    std::size_t bytes = sizeof(io::MeshFile) + vector_bytes(mesh.positions) + vector_bytes(mesh.colors) +
                        vector_bytes(mesh.triangles) + vector_bytes(mesh.normals) + vector_bytes(mesh.texcoords) +
                        vector_bytes(mesh.texcoord_triangles) + vector_bytes(mesh.file_normals) +
                        vector_bytes(mesh.file_normal_triangles) + vector_bytes(mesh.materials) +
                        vector_bytes(mesh.face_materials);
    std::set<const TextureImage*> images;
    for (const FaceMaterial& material : mesh.materials) {
        bytes += material.name.capacity();
        if (material.texture && material.texture->image && images.insert(material.texture->image.get()).second) {
            bytes += sizeof(TextureImage) + vector_bytes(material.texture->image->texels);
        }
    }
    for (const std::string& text : file.warnings) bytes += sizeof(std::string) + text.capacity();
    for (const std::string& text : file.side_files) bytes += sizeof(std::string) + text.capacity();
    return bytes;
}

std::shared_ptr<const io::MeshFile> MeshFileCache::read(const std::string& path) {
    // Taken before reading: a file changed while it is read has another identity next time.
    const std::string identity = io::file_identity(path);
    const std::string canonical = identity_path(identity);
    std::unique_lock<std::mutex> lock(mutex_);
    if (!identity.empty()) {
        // Another thread parsing this file: wait for it rather than parse it twice.
        read_finished_.wait(lock, [&] { return reading_.count(canonical) == 0; });
        for (auto entry = entries_.begin(); entry != entries_.end(); ++entry) {
            if (entry->canonical != canonical) continue;
            if (entry->identity == identity && sides_unchanged(entry->side_identities)) {
                entries_.splice(entries_.begin(), entries_, entry);  // now the most recently used
                return entries_.front().file;
            }
            bytes_ -= entry->bytes;  // an older version of the file: never wanted again
            entries_.erase(entry);
            break;
        }
        reading_.insert(canonical);
    }
    // Parsed outside the lock, so that several loaders parse different files at once.
    lock.unlock();
    Entry fresh;
    fresh.identity = identity;
    fresh.canonical = canonical;
    try {
        // read_mesh throws for a bad file, and nothing is kept. The side files are
        // known only after the read: one edited during it is seen at its next edit.
        fresh.file = std::make_shared<const io::MeshFile>(io::read_mesh(path));
        if (!identity.empty()) {
            for (const std::string& side : fresh.file->side_files) {
                fresh.side_identities.emplace_back(side, io::file_identity(side));
            }
            fresh.bytes = mesh_file_bytes(*fresh.file);
        }
    } catch (...) {
        lock.lock();
        reading_.erase(canonical);
        read_finished_.notify_all();
        throw;
    }
    lock.lock();
    ++parses_;
    if (identity.empty()) return fresh.file;  // no identity to find it by (not a regular file?)
    reading_.erase(canonical);
    read_finished_.notify_all();
    bytes_ += fresh.bytes;
    entries_.push_front(std::move(fresh));
    while (bytes_ > budget_ && entries_.size() > 1) {
        bytes_ -= entries_.back().bytes;
        entries_.pop_back();
    }
    return entries_.front().file;
}

std::shared_ptr<const std::vector<glm::vec3>> MeshFileCache::computed_normals(
    const std::shared_ptr<const io::MeshFile>& file) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (Entry& entry : entries_) {
        if (entry.file != file) continue;
        if (!entry.normals) {
            entry.normals = std::make_shared<const std::vector<glm::vec3>>(calculate_normals(file->mesh));
            ++normals_computed_;
            const std::size_t normal_bytes = vector_bytes(*entry.normals);
            entry.bytes += normal_bytes;
            bytes_ += normal_bytes;  // over the budget now: the next read() drops the least recently used
        }
        return entry.normals;
    }
    ++normals_computed_;
    return std::make_shared<const std::vector<glm::vec3>>(calculate_normals(file->mesh));
}

std::size_t MeshFileCache::files() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return entries_.size();
}

std::size_t MeshFileCache::bytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_;
}

std::size_t MeshFileCache::parses() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return parses_;
}

std::size_t MeshFileCache::normals_computed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return normals_computed_;
}

}  // namespace phongrast::cli
