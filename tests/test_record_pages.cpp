// A large frame's set-up records mapped ahead of the writes
// (src/record_pages.hpp): what a chunk mapped but did not write goes back to
// the kernel when the chunk is done, records keep their values, and a later
// frame in the same storage maps and releases nothing.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "populate_pages.hpp"
#include "record_pages.hpp"

using namespace phongrast::detail;

namespace {

/// As large as a single-precision fill triangle: 546 records to a 64 KiB step.
struct Record {
    std::uint32_t values[30];
};

constexpr std::size_t kChunk = 4096;  // kSetupChunk: the room a chunk reserves
constexpr std::size_t kDrawn = 1000;  // records the chunk's triangles write

#if defined(__linux__)
std::uintptr_t page_size() { return static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE)); }

/// Resident pages among the whole pages inside [begin, end).
std::size_t resident_pages(const void* begin, const void* end) {
    const std::uintptr_t page = page_size();
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(end) / page * page;
    if (last <= first) return 0;
    std::vector<unsigned char> flags((last - first) / page);
    if (mincore(reinterpret_cast<void*>(first), last - first, flags.data()) != 0) return SIZE_MAX;
    std::size_t resident = 0;
    for (unsigned char flag : flags) resident += flag & 1u;
    return resident;
}
#endif

/// One chunk's set-up as set_up_triangles() runs it: kChunk triangles, the
/// first 3 of every 4 write a record until kDrawn are written, the rest none.
/// Returns the resident pages past the last record before release_unwritten().
std::size_t set_up_chunk(ChunkVector<Record>& records, MappedRecords& mapped) {
    records.clear();
    records.reserve(kChunk);
    RecordPages<Record> pages(mapped);
    for (std::size_t t = 0; t < kChunk; ++t) {
        pages.map_ahead(records, kChunk - t);
        if (t % 4 == 3 || records.size() == kDrawn) continue;
        Record record{};
        for (std::uint32_t& value : record.values) value = static_cast<std::uint32_t>(t);
        records.push_back(record);
    }
    std::size_t resident = 0;
#if defined(__linux__)
    resident = resident_pages(records.data() + records.size(), records.data() + kChunk);
#endif
    pages.release_unwritten(records);
    return resident;
}

bool records_intact(const ChunkVector<Record>& records) {
    if (records.size() != kDrawn) return false;
    for (std::size_t i = 0; i < records.size(); ++i) {
        const std::uint32_t t = static_cast<std::uint32_t>(i / 3 * 4 + i % 3);
        for (std::uint32_t value : records[i].values) {
            if (value != t) return false;
        }
    }
    return true;
}

}  // namespace

TEST_CASE("record pages: a chunk's unwritten room is given back, and a later frame maps nothing ahead") {
#if defined(__linux__)
    ChunkVector<Record> records{SlotAllocator<Record>(nullptr)};  // a large frame's chunk: on the heap
    records.reserve(kChunk);
    const Record* room_end = records.data() + kChunk;
    // The control: populated, the room counts as resident; released, it no longer does.
    if (!populate_for_writing(records.data(), kChunk * sizeof(Record))) {
        WARN("skipped: this kernel has no MADV_POPULATE_WRITE (Linux 5.14 and later): nothing is mapped ahead");
        return;
    }
    REQUIRE(resident_pages(records.data(), room_end) >= kChunk * sizeof(Record) / page_size() - 1);
    REQUIRE(release_pages(records.data(), kChunk * sizeof(Record)));
    REQUIRE(resident_pages(records.data(), room_end) == 0);

    MappedRecords mapped;
    const std::size_t mapped_ahead = set_up_chunk(records, mapped);
    CHECK(records_intact(records));
    CHECK(mapped.storage == records.data());
    CHECK(mapped.finished);
    CHECK(mapped.records == kDrawn);
    const std::size_t left = resident_pages(records.data() + records.size(), room_end);
    INFO("resident pages past the last record: " << mapped_ahead << " before the release, " << left << " after");
    CHECK(mapped_ahead > 0);  // mapped ahead of the writes: what the release is for
    CHECK(left == 0);

    SECTION("the next frame in the same storage writes the same records and maps nothing past them") {
        CHECK(set_up_chunk(records, mapped) == 0);
        CHECK(records_intact(records));
        CHECK(mapped.storage == records.data());
        CHECK(resident_pages(records.data() + records.size(), room_end) == 0);
    }
    SECTION("new storage is mapped ahead again") {
        ChunkVector<Record> other{SlotAllocator<Record>(nullptr)};
        other.reserve(kChunk);
        RecordPages<Record> pages(mapped);
        pages.map_ahead(other, kChunk);
        CHECK(mapped.storage == other.data());
        CHECK_FALSE(mapped.finished);
        CHECK(mapped.records == (std::size_t(64) << 10) / sizeof(Record));  // one step
    }
#else
    WARN("skipped: pages are mapped ahead on Linux only");
#endif
}

TEST_CASE("record pages: a step reaches no further than one record per triangle left in the chunk") {
    ChunkVector<Record> records{SlotAllocator<Record>(nullptr)};
    records.reserve(kChunk);
    MappedRecords mapped;
    RecordPages<Record> pages(mapped);
    pages.map_ahead(records, 200);
    CHECK(mapped.records == 200);
    records.resize(198);
    pages.map_ahead(records, 2);  // 198 + 4 > 200, but two triangles write at most two more
    CHECK(mapped.records == 200);
    pages.release_unwritten(records);
    CHECK(mapped.records == 198);
    CHECK(mapped.finished);
    records.resize(300);  // a later frame writing more: past the first frame's pages they are faulted in
    pages.map_ahead(records, 100);
    CHECK(mapped.records == 198);
}

TEST_CASE("record pages: release_pages leaves partial pages and empty ranges alone") {
    CHECK_FALSE(release_pages(nullptr, std::size_t(1) << 20));
    std::vector<char> small(100, 'x');
    CHECK_FALSE(release_pages(small.data() + 1, 50));  // no whole page inside
    CHECK(small[0] == 'x');
    CHECK(small[60] == 'x');
}
