// Set-up's chunk vectors in one huge-page mapping (src/chunk_arena.hpp):
// vectors behave as vectors whether they sit in a slot or on the heap, a
// slot is lent to one vector at a time, and large frames get no mapping.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "chunk_arena.hpp"

using namespace phongrast::detail;

namespace {

bool inside(const void* p, const ArenaSlot& slot) {
    const char* c = static_cast<const char*>(p);
    const char* base = static_cast<const char*>(slot.base);
    return base != nullptr && c >= base && c < base + slot.bytes;
}

}  // namespace

TEST_CASE("chunk arena: a small frame's vectors sit in their slots, 2 MiB-aligned and zeroed") {
    ChunkArena arena;
    arena.reset(3, {4096 * 8, 4096 * 4, 100});
    REQUIRE(arena.chunks() == 3);
    if (!arena.mapped()) {
        WARN("skipped: no mapping on this system (not Linux); the vectors use the heap");
        return;
    }
    CHECK(reinterpret_cast<std::uintptr_t>(arena.slot(0, 0)->base) % (std::uintptr_t(2) << 20) == 0);
    std::vector<ChunkVector<std::uint64_t>> chunks;
    for (std::size_t c = 0; c < 3; ++c) chunks.emplace_back(SlotAllocator<std::uint64_t>(arena.slot(c, 0)));
    for (std::size_t c = 0; c < 3; ++c) {
        chunks[c].reserve(4096);
        CHECK(inside(chunks[c].data(), *arena.slot(c, 0)));
        CHECK(arena.slot(c, 0)->lent);
        // Slots do not overlap: fill each with its own values.
        for (std::uint64_t i = 0; i < 4096; ++i) chunks[c].push_back(c * 10000 + i);
    }
    for (std::size_t c = 0; c < 3; ++c) {
        REQUIRE(chunks[c].size() == 4096);
        CHECK(chunks[c].front() == c * 10000);
        CHECK(chunks[c].back() == c * 10000 + 4095);
    }
    // A slot's memory reads as zero before anything is written (fresh pages).
    const auto* unwritten = static_cast<const unsigned char*>(arena.slot(1, 1)->base);
    CHECK(std::all_of(unwritten, unwritten + 4096 * 4, [](unsigned char b) { return b == 0; }));

    SECTION("a vector that outgrows its slot moves to the heap, keeps its values and gives the slot back") {
        chunks[1].push_back(42);
        CHECK_FALSE(inside(chunks[1].data(), *arena.slot(1, 0)));
        CHECK_FALSE(arena.slot(1, 0)->lent);
        REQUIRE(chunks[1].size() == 4097);
        CHECK(chunks[1][4095] == 14095);
        CHECK(chunks[1].back() == 42);
    }
    SECTION("clear() keeps the slot; a second vector on a lent slot gets the heap") {
        chunks[2].clear();
        chunks[2].reserve(10);
        CHECK(inside(chunks[2].data(), *arena.slot(2, 0)));
        ChunkVector<std::uint64_t> other{SlotAllocator<std::uint64_t>(arena.slot(2, 0))};
        other.assign(5, 7);
        CHECK_FALSE(inside(other.data(), *arena.slot(2, 0)));
        CHECK(other == ChunkVector<std::uint64_t>(5, 7));
    }
    SECTION("reset refuses while a slot is lent, and works once the vectors are gone") {
        CHECK_THROWS_AS(arena.reset(1, {64, 64, 64}), std::logic_error);
        chunks.clear();
        arena.reset(1, {64, 64, 64});
        CHECK(arena.chunks() == 1);
    }
}

TEST_CASE("chunk arena: a frame over the size limit gets no mapping, its vectors use the heap") {
    ChunkArena arena;
    const std::size_t per_kind = kHugePageArenaBytes / 2;
    arena.reset(2, {per_kind, 8, 8});  // twice the limit
    CHECK_FALSE(arena.mapped());
    REQUIRE(arena.chunks() == 2);
    CHECK(arena.slot(1, 0)->base == nullptr);
    ChunkVector<int> values{SlotAllocator<int>(arena.slot(1, 0))};
    values.resize(1000);
    std::iota(values.begin(), values.end(), 0);
    CHECK(values[999] == 999);
    CHECK_FALSE(arena.slot(1, 0)->lent);
}

TEST_CASE("chunk arena: vectors without a slot are plain vectors") {
    ChunkVector<int> values;
    values.assign(100, 3);
    values.push_back(4);
    CHECK(values.size() == 101);
    CHECK(values.back() == 4);
    CHECK(SlotAllocator<int>() == SlotAllocator<double>());
}
