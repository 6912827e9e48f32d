// Mapping a large frame's set-up records a step ahead of the writes
// (internal header; populate_pages.hpp says why), and giving back what a
// chunk mapped but did not write.
//
// Set-up reserves room for every triangle of a chunk, but about a fifth of
// the 8M-triangle mesh's triangles write no record (they cover no sample),
// so a chunk's last step of 64 KiB mapped ahead is mostly left unwritten:
// 35 MiB over that mesh's 1,957 chunks, past the memory goal's budget
// (docs/performance.md, Memory). So a step never reaches past one record
// per triangle left in the chunk, and once the chunk is done the whole
// pages past its last record go back to the kernel. Later frames in the
// same storage map nothing ahead: their records lie on the pages the first
// frame wrote, and what a larger frame adds is faulted in as written, so a
// frame neither maps nor releases anything again.
#ifndef PHONGRAST_SRC_RECORD_PAGES_HPP
#define PHONGRAST_SRC_RECORD_PAGES_HPP

#include <algorithm>
#include <cstddef>

#include "chunk_arena.hpp"
#include "populate_pages.hpp"

namespace phongrast::detail {

/// How far a chunk's set-up records are mapped, and in which storage: kept
/// from frame to frame, so that a Renderer maps each page once rather than
/// asking the kernel again every frame (23 madvise calls a frame for a
/// 10k-triangle mesh, on pages mapped long before).
struct MappedRecords {
    const void* storage = nullptr;
    std::size_t records = 0;  ///< records [0, records) lie on pages mapped ahead
    bool finished = false;    ///< a frame has ended in this storage: nothing more is mapped ahead
};

/// Maps a growing vector's reserved pages in steps of 64 KiB a little
/// ahead of its end: one call per step instead of a page fault per 4 KiB,
/// never more than a step, nor one record per triangle left, beyond what is
/// written; release_unwritten() gives back what the chunk did not write.
template <typename T>
class RecordPages {
public:
    explicit RecordPages(MappedRecords& mapped) : mapped_(mapped) {}

    /// Before a triangle's set-up: `triangles_left` triangles of the chunk
    /// (this one included) may still write a record each (more when
    /// clipped: those are faulted in as written).
    void map_ahead(ChunkVector<T>& records, std::size_t triangles_left) {
        if (records.data() != mapped_.storage) {  // new storage (first call, or grown past its reservation)
            mapped_ = {records.data(), records.size(), false};
        }
        if (mapped_.finished) return;
        if (records.size() + kAhead <= mapped_.records || mapped_.records >= records.capacity()) return;
        const std::size_t next = std::min({records.capacity(), std::max(mapped_.records, records.size()) + kStep,
                                           records.size() + triangles_left});
        if (next <= mapped_.records) return;
        populate_for_writing(records.data() + mapped_.records, (next - mapped_.records) * sizeof(T));
        mapped_.records = next;
    }

    /// After the chunk's last triangle: the whole pages mapped ahead past
    /// its last record go back to the kernel, and later frames in this
    /// storage map nothing ahead.
    void release_unwritten(ChunkVector<T>& records) {
        if (records.data() != mapped_.storage || mapped_.finished) return;
        if (mapped_.records > records.size()) {
            release_pages(records.data() + records.size(), (mapped_.records - records.size()) * sizeof(T));
            mapped_.records = records.size();
        }
        mapped_.finished = true;
    }

private:
    static constexpr std::size_t kStep = std::max<std::size_t>(1, (std::size_t(64) << 10) / sizeof(T));
    static constexpr std::size_t kAhead = 4;
    MappedRecords& mapped_;
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_RECORD_PAGES_HPP
