#include "painter_order.hpp"

#include <algorithm>
#include <limits>

#include <tbb/parallel_for.h>

#include "populate_pages.hpp"

namespace phongrast::detail {
namespace {

using painter_sort::Counts;
using painter_sort::kBuckets;
using painter_sort::kDigitBits;

/// Neighbouring buckets sorted by one task, with one scratch area.
constexpr std::size_t kTaskBuckets = 32;
/// Set-up chunks per group: a group (65,536 triangles) counts and scatters its records as one task.
constexpr std::size_t kGroupChunks = 16;

/// Bits needed for `range`: 0 for 0, 64 for the largest.
int bit_width(std::uint64_t range) {
    int bits = 0;
    for (; range != 0; range >>= 1) ++bits;
    return bits;
}

/// A radix digit: the `bits` bits of key - base just below bit `shift`
/// (every key of the records it sorts agrees with base on the bits above).
struct Digit {
    std::uint64_t base;
    int shift;
    int bits;
    Digit(std::uint64_t base_, int shift_) : base(base_), shift(shift_), bits(std::min(shift_, kDigitBits)) {}
    std::size_t operator()(std::uint64_t key) const {
        return static_cast<std::size_t>(((key - base) >> (shift - bits)) & ((std::uint64_t(1) << bits) - 1));
    }
};

/// Sorts n records, in mesh order, whose keys agree with `base` above bit
/// `shift`, stably by key: up to 64 by insertion, more by a radix pass on the
/// next 8 bits (256 counters: cheap for the few hundred records of a typical
/// bucket) through `scratch` (room for n records), then each part the same
/// way. Stability keeps ties in mesh order.
void sort_bucket(PaintRecord* data, PaintRecord* scratch, std::size_t n, std::uint64_t base, int shift) {
    if (shift == 0) return;  // all keys equal: mesh order is the order
    if (n <= 64) {
        for (std::size_t i = 1; i < n; ++i) {
            const PaintRecord record = data[i];
            std::size_t j = i;
            for (; j > 0 && data[j - 1].key > record.key; --j) data[j] = data[j - 1];
            data[j] = record;
        }
        return;
    }
    const int low = std::max(0, shift - 8);
    const auto digit = [base, low](std::uint64_t key) { return static_cast<std::size_t>(((key - base) >> low) & 0xff); };
    std::array<std::uint32_t, 257> start{};
    for (std::size_t i = 0; i < n; ++i) ++start[digit(data[i].key) + 1];
    if (std::any_of(start.begin(), start.end(), [n](std::uint32_t c) { return c == n; })) {
        sort_bucket(data, scratch, n, base, low);  // these 8 bits are all alike
        return;
    }
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    std::array<std::uint32_t, 257> cursor = start;
    for (std::size_t i = 0; i < n; ++i) scratch[cursor[digit(data[i].key)]++] = data[i];
    std::copy(scratch, scratch + n, data);
    for (std::size_t d = 0; d < 256; ++d) {
        const std::size_t size = start[d + 1] - start[d];
        if (size > 1) sort_bucket(data + start[d], scratch + start[d], size, base, low);
    }
}

/// Runs of equal keys in the sorted records data[0, n) put in the order of
/// tie_rank (the caller's triangle order of a reordered mesh; each rank is
/// a different triangle's, so the order is unique).
void order_ties(PaintRecord* data, std::size_t n, const TieRank& tie_rank) {
    for (std::size_t begin = 0; begin < n;) {
        std::size_t end = begin + 1;
        while (end < n && data[end].key == data[begin].key) ++end;
        if (end - begin > 1) {
            std::sort(data + begin, data + end, [&](const PaintRecord& a, const PaintRecord& b) {
                return tie_rank(a.drawn) < tie_rank(b.drawn);
            });
        }
        begin = end;
    }
}

/// Set-up's records, chunk after chunk, in mesh order.
struct SetupRecords {
    const std::vector<ChunkVector<DrawSpan>>& chunk_drawn;
    const std::vector<ChunkVector<std::uint64_t>>& chunk_keys;
    std::size_t chunks;

    std::size_t groups() const { return (chunks + kGroupChunks - 1) / kGroupChunks; }

    /// Calls visit(key, drawn) for every record of group `group`, in mesh order.
    template <typename Visit>
    void for_each_in_group(std::size_t group, Visit&& visit) const {
        const std::size_t end = std::min(chunks, (group + 1) * kGroupChunks);
        for (std::size_t chunk = group * kGroupChunks; chunk < end; ++chunk) {
            for (std::size_t i = 0; i < chunk_drawn[chunk].size(); ++i) visit(chunk_keys[chunk][i], chunk_drawn[chunk][i]);
        }
    }
};

/// No sort: the records in mesh order.
void keep_mesh_order(const SetupRecords& records, PainterOrderMemory& memory) {
    std::vector<std::size_t>& offsets = memory.chunk_offsets;
    offsets.resize(records.chunks + 1);
    offsets[0] = 0;
    for (std::size_t chunk = 0; chunk < records.chunks; ++chunk) {
        offsets[chunk + 1] = offsets[chunk] + records.chunk_drawn[chunk].size();
    }
    reserve_populated(memory.sorted, offsets[records.chunks]);
    memory.sorted.resize(offsets[records.chunks]);
    tbb::parallel_for(std::size_t(0), records.chunks, [&](std::size_t chunk) {
        PaintRecord* out = memory.sorted.data() + offsets[chunk];
        for (std::size_t i = 0; i < records.chunk_drawn[chunk].size(); ++i) {
            out[i] = {records.chunk_keys[chunk][i], records.chunk_drawn[chunk][i]};
        }
    });
}

/// The top-level digit: the leading kDigitBits bits of the keys' range
/// (relative to the smallest key, so no pass is spent on bits all share).
Digit leading_digit(const SetupRecords& records, PainterOrderMemory& memory, ProgressMonitor& progress) {
    const std::size_t groups = records.groups();
    memory.group_min.assign(groups, std::numeric_limits<std::uint64_t>::max());
    memory.group_max.assign(groups, 0);
    tbb::parallel_for(std::size_t(0), groups, [&](std::size_t group) {
        // In locals, stored once: neighbouring groups' slots share a cache line.
        std::uint64_t low = std::numeric_limits<std::uint64_t>::max(), high = 0;
        records.for_each_in_group(group, [&](std::uint64_t key, const DrawSpan&) {
            low = std::min(low, key);
            high = std::max(high, key);
        });
        memory.group_min[group] = low;
        memory.group_max[group] = high;
        progress.piece_done();
    });
    const std::uint64_t base = groups == 0 ? 0 : *std::min_element(memory.group_min.begin(), memory.group_min.end());
    const std::uint64_t top = groups == 0 ? 0 : *std::max_element(memory.group_max.begin(), memory.group_max.end());
    return Digit(base, top > base ? bit_width(top - base) : 0);
}

/// Scatters the records into memory.sorted by `digit`, stably: counted per
/// group, laid out bucket after bucket and within a bucket group after
/// group. memory.chunk_offsets gets the kBuckets + 1 bucket starts.
void scatter_by_digit(const SetupRecords& records, const Digit& digit, PainterOrderMemory& memory,
                      ProgressMonitor& progress) {
    const std::size_t groups = records.groups();
    memory.group_counts.resize(groups);
    tbb::parallel_for(std::size_t(0), groups, [&](std::size_t group) {
        Counts& counts = memory.group_counts[group];
        counts.fill(0);
        records.for_each_in_group(group, [&](std::uint64_t key, const DrawSpan&) { ++counts[digit(key)]; });
    });
    std::vector<std::size_t>& bucket_start = memory.chunk_offsets;
    bucket_start.assign(kBuckets + 1, 0);
    std::uint32_t total = 0;
    for (std::size_t b = 0; b < kBuckets; ++b) {
        bucket_start[b] = total;
        for (Counts& counts : memory.group_counts) {
            const std::uint32_t size = counts[b];
            counts[b] = total;
            total += size;
        }
    }
    bucket_start[kBuckets] = total;
    reserve_populated(memory.sorted, total);
    memory.sorted.resize(total);
    tbb::parallel_for(std::size_t(0), groups, [&](std::size_t group) {
        Counts& cursor = memory.group_counts[group];
        records.for_each_in_group(group, [&](std::uint64_t key, const DrawSpan& drawn) {
            memory.sorted[cursor[digit(key)]++] = {key, drawn};
        });
        progress.piece_done();
    });
}

/// Sorts each bucket of memory.sorted (starts in memory.chunk_offsets) on the
/// bits below `digit`, in tasks of kTaskBuckets neighbours, each with
/// scratch for its largest bucket: a small fraction of the records.
void sort_buckets(const Digit& digit, PainterOrderMemory& memory, ProgressMonitor& progress,
                  const TieRank& tie_rank) {
    const std::vector<std::size_t>& bucket_start = memory.chunk_offsets;
    constexpr std::size_t kTasks = kBuckets / kTaskBuckets;
    std::size_t room = 0;
    for (std::size_t task = 0; task < kTasks; ++task) {
        memory.task_scratch_start[task] = room;
        std::size_t largest = 0;
        for (std::size_t b = task * kTaskBuckets; b < (task + 1) * kTaskBuckets; ++b) {
            largest = std::max(largest, bucket_start[b + 1] - bucket_start[b]);
        }
        room += largest;
    }
    memory.scratch.resize(std::max(memory.scratch.size(), room));
    tbb::parallel_for(std::size_t(0), kTasks, [&](std::size_t task) {
        if (progress.cancelled()) return;
        PaintRecord* scratch = memory.scratch.data() + memory.task_scratch_start[task];
        for (std::size_t b = task * kTaskBuckets; b < (task + 1) * kTaskBuckets; ++b) {
            sort_bucket(memory.sorted.data() + bucket_start[b], scratch, bucket_start[b + 1] - bucket_start[b],
                        digit.base, digit.shift - digit.bits);
            if (tie_rank) order_ties(memory.sorted.data() + bucket_start[b], bucket_start[b + 1] - bucket_start[b], tie_rank);
        }
        progress.poll();  // no pieces counted here, but a report keeps Ctrl-C prompt (sorting takes a while)
    });
}

}  // namespace

void painter_order(const std::vector<ChunkVector<DrawSpan>>& chunk_drawn,
                   const std::vector<ChunkVector<std::uint64_t>>& chunk_keys, std::size_t chunks, bool sort,
                   PainterOrderMemory& memory, ProgressMonitor& progress, const TieRank& tie_rank) {
    const SetupRecords records{chunk_drawn, chunk_keys, chunks};
    if (!sort) {
        keep_mesh_order(records, memory);
        return;
    }
    progress.begin_stage(0.35, 0.4, 3 * records.groups());
    const Digit digit = leading_digit(records, memory, progress);
    scatter_by_digit(records, digit, memory, progress);
    sort_buckets(digit, memory, progress, tie_rank);
    for (std::size_t group = 0; group < records.groups(); ++group) progress.piece_done();
    progress.throw_if_cancelled();
}

std::vector<std::uint32_t> farthest_first_order(const std::vector<double>& depth) {
    constexpr std::size_t kChunk = 4096;  // as set-up's chunks, so that ties cross chunks and groups
    const std::size_t chunks = (depth.size() + kChunk - 1) / kChunk;
    std::vector<ChunkVector<DrawSpan>> chunk_drawn(chunks);
    std::vector<ChunkVector<std::uint64_t>> chunk_keys(chunks);
    for (std::size_t i = 0; i < depth.size(); ++i) {
        chunk_drawn[i / kChunk].push_back(DrawSpan::one(i / kChunk, i % kChunk, 0, 0));
        chunk_keys[i / kChunk].push_back(farthest_first_key(depth[i]));
    }
    PainterOrderMemory memory;
    const ProgressCallback no_reports;  // the monitor keeps a reference: it must outlive it
    ProgressMonitor progress(no_reports);
    painter_order(chunk_drawn, chunk_keys, chunks, true, memory, progress);
    std::vector<std::uint32_t> order;
    for (const PaintRecord& record : memory.sorted) {
        order.push_back(static_cast<std::uint32_t>(record.drawn.chunk() * kChunk + record.drawn.first()));
    }
    return order;
}

}  // namespace phongrast::detail
