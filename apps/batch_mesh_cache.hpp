// The batch's parsed meshes, kept across jobs: a manifest naming each of 100
// meshes 10 times (in any order) parses each once. Bounded by memory: the
// least recently used files are dropped once the kept meshes pass the budget.
#ifndef PHONGRAST_APPS_BATCH_MESH_CACHE_HPP
#define PHONGRAST_APPS_BATCH_MESH_CACHE_HPP

#include <condition_variable>
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "phongrast/io/mesh_file.hpp"

namespace phongrast::cli {

/// Parsed mesh files (with their materials and loaded textures) by identity:
/// a file is known by its canonical path, size and modification time
/// (io::file_identity), and so is every side file its reader read or looked
/// for (MeshFile::side_files: MTL, textures, glTF buffers), so an edited mesh,
/// MTL or texture is read again. Failed reads are not kept. Thread-safe:
/// files are parsed outside the lock, several at once, each by one thread
/// (another asking for the same file waits for that parse).
class MeshFileCache {
public:
    /// 256 MiB: a 12k-triangle coloured OBJ takes about 0.36 MB, a 1M-triangle one about 30-60 MB.
    static constexpr std::size_t kDefaultBudgetBytes = std::size_t{256} << 20;

    explicit MeshFileCache(std::size_t budget_bytes = kDefaultBudgetBytes) : budget_(budget_bytes) {}

    /// The file at `path`, parsed now or earlier. Throws what io::read_mesh throws.
    /// The mesh just read is kept even when it alone is over the budget (until the next).
    std::shared_ptr<const io::MeshFile> read(const std::string& path);

    /// calculate_normals() of `file`'s mesh (what the renderer computes for
    /// a mesh given without normals), computed on the first request and kept
    /// with the file while the file is kept; a file the cache does not hold
    /// gets them computed and not kept. A batch names each mesh many times,
    /// and each of its jobs' renders would otherwise compute them again.
    std::shared_ptr<const std::vector<glm::vec3>> computed_normals(const std::shared_ptr<const io::MeshFile>& file);

    std::size_t files() const;  ///< meshes kept now
    std::size_t bytes() const;  ///< their estimated memory (with their normals)
    std::size_t parses() const;  ///< files parsed so far (not found in the cache)
    std::size_t normals_computed() const;  ///< computed_normals() calls that computed them

private:
    struct Entry {
        std::string identity;  ///< the mesh file's
        std::string canonical;  ///< the canonical path in `identity` (compared with each read's)
        std::vector<std::pair<std::string, std::string>> side_identities;  ///< (path, identity at reading)
        std::shared_ptr<const io::MeshFile> file;
        std::shared_ptr<const std::vector<glm::vec3>> normals;  ///< computed_normals(), once asked for
        std::size_t bytes = 0;
    };

    mutable std::mutex mutex_;
    std::condition_variable read_finished_;
    std::set<std::string> reading_;  ///< canonical paths being parsed now (outside the lock)
    std::list<Entry> entries_;  ///< most recently used first
    std::size_t budget_;
    std::size_t bytes_ = 0;
    std::size_t parses_ = 0;
    std::size_t normals_computed_ = 0;
};

/// The memory a parsed mesh holds: its arrays, material names and texture
/// images (a texture shared by several meshes counts in each).
std::size_t mesh_file_bytes(const io::MeshFile& file);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_MESH_CACHE_HPP
