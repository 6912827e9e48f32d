// The per-frame buffers' pool of huge-page mappings (src/huge_page_pool.hpp):
// blocks aligned and side by side, freed blocks reused, mappings returned
// when empty, every failure of the system calls a fallback to the heap, and
// FrameVector a vector like any other whatever its memory.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <vector>

#include "huge_page_pool.hpp"
#include "populate_pages.hpp"
#include "resize_polling.hpp"

using namespace phongrast::detail;

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;

bool aligned_to(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

/// System calls that record what the pool asked for, and fail on demand.
struct FakeSystem {
    static inline bool available = true, map_fails = false, advice_fails = false;
    static inline int maps = 0, unmaps = 0, advices = 0;
    static inline std::size_t mapped_bytes = 0;  // mapped and not yet unmapped

    static void reset() {
        available = true;
        map_fails = advice_fails = false;
        maps = unmaps = advices = 0;
        mapped_bytes = 0;
    }
    static HugePagePool::System calls() {
        return {[] { return available; },
                [](std::size_t bytes) -> void* {
                    ++maps;
                    if (map_fails) return nullptr;
                    mapped_bytes += bytes;
                    return HugePagePool::system_calls().map(bytes);
                },
                [](void* begin, std::size_t bytes) {
                    ++unmaps;
                    mapped_bytes -= bytes;
                    HugePagePool::system_calls().unmap(begin, bytes);
                },
                [](void* begin, std::size_t bytes) {
                    ++advices;
                    if (advice_fails) return false;
                    return HugePagePool::system_calls().advise_huge_pages(begin, bytes);
                }};
    }
};

bool system_has_huge_pages() {
    const HugePagePool::System real = HugePagePool::system_calls();
    return real.huge_pages_available();
}

}  // namespace

TEST_CASE("huge page pool: blocks side by side in one 2 MiB-aligned mapping, reused when freed") {
    if (!system_has_huge_pages()) {
        WARN("skipped: no transparent huge pages here (not Linux, or `never`); the pool gives the heap");
        return;
    }
    FakeSystem::reset();
    HugePagePool pool(FakeSystem::calls());
    void* first = pool.allocate(3 * kMiB);
    REQUIRE(first != nullptr);
    CHECK(aligned_to(first, HugePagePool::kHugePage));  // a fresh mapping's first block: its start
    CHECK(pool.mappings() == 1);
    CHECK(FakeSystem::advices == 1);
    // The next block follows at once, rounded up to a cache line: the two share a 2 MiB page.
    void* second = pool.allocate(100 * 1000);
    REQUIRE(second != nullptr);
    CHECK(static_cast<char*>(second) == static_cast<char*>(first) + 3 * kMiB);
    void* third = pool.allocate(20000);
    REQUIRE(third != nullptr);
    CHECK(aligned_to(third, HugePagePool::kBlockAlignment));
    CHECK(static_cast<char*>(third) == static_cast<char*>(second) + 100032);  // 100,000 rounded up to 64
    CHECK(pool.owns(first));
    CHECK(pool.owns(static_cast<char*>(third) + 19999));
    int on_stack = 0;
    CHECK_FALSE(pool.owns(&on_stack));

    // New memory reads as zero; the blocks do not overlap.
    const auto* bytes = static_cast<const unsigned char*>(second);
    CHECK(std::all_of(bytes, bytes + 100000, [](unsigned char b) { return b == 0; }));
    std::memset(first, 1, 3 * kMiB);
    std::memset(second, 2, 100000);
    std::memset(third, 3, 20000);
    CHECK(static_cast<unsigned char*>(first)[3 * kMiB - 1] == 1);
    CHECK(static_cast<unsigned char*>(second)[0] == 2);
    CHECK(static_cast<unsigned char*>(second)[99999] == 2);

    SECTION("a freed block's place is reused by a block that fits, the rest stays a hole") {
        REQUIRE(pool.deallocate(second, 100 * 1000));
        CHECK(pool.allocate(50000) == second);
        void* rest = pool.allocate(40000);
        CHECK(rest == static_cast<char*>(second) + 50048);
        CHECK(pool.mappings() == 1);
    }
    SECTION("neighbouring holes merge: two freed blocks make room for one of both sizes") {
        REQUIRE(pool.deallocate(first, 3 * kMiB));
        REQUIRE(pool.deallocate(second, 100 * 1000));
        CHECK(pool.allocate(3 * kMiB + 100000) == first);
    }
    SECTION("the last block freed unmaps the mapping") {
        REQUIRE(pool.deallocate(second, 100 * 1000));
        REQUIRE(pool.deallocate(third, 20000));
        CHECK(pool.mappings() == 1);
        REQUIRE(pool.deallocate(first, 3 * kMiB));
        CHECK(pool.mappings() == 0);
        CHECK(FakeSystem::mapped_bytes == 0);
        CHECK_FALSE(pool.owns(first));
        // And a new block maps again.
        void* again = pool.allocate(kMiB);
        REQUIRE(again != nullptr);
        CHECK(pool.mappings() == 1);
        CHECK(pool.deallocate(again, kMiB));
    }
    SECTION("a block that no mapping has room for gets a mapping of its own") {
        void* big = pool.allocate(HugePagePool::kMaxBlock);
        void* bigger = pool.allocate(HugePagePool::kMaxBlock);
        REQUIRE(big != nullptr);
        REQUIRE(bigger != nullptr);
        CHECK(pool.mappings() == 2);
        CHECK(aligned_to(bigger, HugePagePool::kHugePage));
        CHECK(pool.deallocate(big, HugePagePool::kMaxBlock));
        CHECK(pool.deallocate(bigger, HugePagePool::kMaxBlock));
    }
    SECTION("memory that is not the pool's is left to the caller") {
        int* heap = new int[5000];
        CHECK_FALSE(pool.deallocate(heap, 5000 * sizeof(int)));
        delete[] heap;
    }
}

TEST_CASE("huge page pool: blocks too small or too large are the heap's") {
    FakeSystem::reset();
    HugePagePool pool(FakeSystem::calls());
    CHECK(pool.allocate(HugePagePool::kMinBlock - 1) == nullptr);
    CHECK(pool.allocate(HugePagePool::kMaxBlock + 1) == nullptr);
    CHECK(pool.allocate(0) == nullptr);
    CHECK(FakeSystem::maps == 0);
    CHECK(pool.mappings() == 0);
}

TEST_CASE("huge page pool: when the system cannot give huge pages, every block is the heap's") {
    FakeSystem::reset();
    SECTION("transparent huge pages off: nothing is mapped") {
        FakeSystem::available = false;
        HugePagePool pool(FakeSystem::calls());
        CHECK(pool.allocate(kMiB) == nullptr);
        CHECK(pool.disabled());
        CHECK(FakeSystem::maps == 0);
    }
    SECTION("mmap fails: this block from the heap, the next one tries again") {
        FakeSystem::map_fails = true;
        HugePagePool pool(FakeSystem::calls());
        CHECK(pool.allocate(kMiB) == nullptr);
        CHECK_FALSE(pool.disabled());
        CHECK(pool.mappings() == 0);
        FakeSystem::map_fails = false;
        void* block = pool.allocate(kMiB);
        if (system_has_huge_pages()) {
            REQUIRE(block != nullptr);
            CHECK(pool.deallocate(block, kMiB));
        }
    }
    SECTION("madvise fails: the mapping is returned and the pool gives up") {
        FakeSystem::advice_fails = true;
        HugePagePool pool(FakeSystem::calls());
        CHECK(pool.allocate(kMiB) == nullptr);
        CHECK(pool.disabled());
        CHECK(FakeSystem::advices == 1);
        CHECK(FakeSystem::mapped_bytes == 0);  // the mapping and its trimmed ends all unmapped
        CHECK(pool.allocate(kMiB) == nullptr);
        CHECK(FakeSystem::maps == 1);  // not asked again
    }
}

TEST_CASE("FrameVector: a vector whatever its memory, values kept as it grows across the pool's limits") {
    FrameVector<std::uint64_t> values;
    // From the heap (under kMinBlock), into the pool, then past kMaxBlock back to the heap.
    const std::size_t largest = HugePagePool::kMaxBlock / sizeof(std::uint64_t) + 1000;
    bool seen_pool = false;
    for (std::uint64_t i = 0; i < largest; ++i) {
        values.push_back(i * 7 + 1);
        if (values.size() == HugePagePool::kMinBlock / sizeof(std::uint64_t) * 4) {
            seen_pool = HugePageAllocator<std::uint64_t>::on_huge_pages(values.data());
        }
    }
    CHECK(seen_pool == system_has_huge_pages());
    CHECK_FALSE(HugePageAllocator<std::uint64_t>::on_huge_pages(values.data()));  // past kMaxBlock: the heap's
    bool all_kept = true;
    for (std::uint64_t i = 0; i < largest; ++i) all_kept = all_kept && values[i] == i * 7 + 1;
    CHECK(all_kept);

    SECTION("copies, moves and swaps keep the values") {
        FrameVector<std::uint64_t> small(5000);
        std::iota(small.begin(), small.end(), std::uint64_t(0));
        FrameVector<std::uint64_t> copy = small;
        FrameVector<std::uint64_t> moved = std::move(small);
        copy.swap(values);
        CHECK(values.size() == 5000);
        CHECK(values[4999] == 4999);
        CHECK(moved[4999] == 4999);
        CHECK(copy.size() == largest);
        CHECK(copy.back() == (largest - 1) * 7 + 1);
    }
    SECTION("resize_polling grows a pooled vector without populating it, values kept") {
        FrameVector<double> grown(3000, 2.5);
        resize_polling(grown, 600000, nullptr);
        REQUIRE(grown.size() == 600000);
        CHECK(grown[2999] == 2.5);
        CHECK(grown[3000] == 0.0);
        CHECK(grown.back() == 0.0);
        // Pool memory is left to huge page faults (heap memory is populated as before).
        const bool pooled = HugePageAllocator<double>::on_huge_pages(grown.data());
        CHECK(pooled == system_has_huge_pages());
        if (pooled) CHECK_FALSE(populate_for_writing_in<HugePageAllocator<double>>(grown.data(), 4 * kMiB));
    }
}

TEST_CASE("reserve_on_huge_pages: a std::vector grown with room for its end's whole 2 MiB page, values kept") {
    std::vector<float> values(1000);
    std::iota(values.begin(), values.end(), 0.0f);
    const std::size_t size = 3 * kMiB / sizeof(float);  // a 512x512 float RGB image's bytes
    CHECK(reserve_on_huge_pages(values, size));
    REQUIRE(values.size() == 1000);
    CHECK(values[999] == 999.0f);
    // The slack: the page holding the new part's end lies inside the buffer (or, without huge pages, exactly size).
    CHECK(values.capacity() >= size);
    if (system_has_huge_pages()) CHECK(values.capacity() >= size + HugePagePool::kHugePage / sizeof(float));
    values.resize(size, 7.0f);
    CHECK(values[1000] == 7.0f);
    CHECK(values.back() == 7.0f);
    CHECK_FALSE(reserve_on_huge_pages(values, size));  // room already: nothing done
    // Outside [2 MiB, kMaxBlock]: an exact reserve, mapped ahead as before.
    std::vector<float> small;
    CHECK(reserve_on_huge_pages(small, 1000));
    CHECK(small.capacity() == 1000);
}
