// The command's malloc set-up for one-off processes (apps/process_heap.cpp):
// a buffer of a few MiB comes from the heap, on memory advised as huge
// pages, and a buffer over 32 MiB is still a mapping of its own. Its own
// test program: the set-up changes malloc for the whole process.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "process_heap.hpp"

// Under AddressSanitizer malloc is the sanitizer's, not glibc's: mallopt and
// the heap's break do not apply, and the set-up leaves it as it is.
#if defined(__SANITIZE_ADDRESS__)
#define PHONGRAST_SANITIZER_MALLOC 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PHONGRAST_SANITIZER_MALLOC 1
#endif
#endif

namespace {

/// The /proc/self/smaps entry holding `address`: its name ("[heap]", a file, or
/// empty) and its VmFlags ("rd wr mr ... hg"); found false when none holds it.
struct Mapping {
    bool found = false;
    std::string name;
    std::string flags;
};

[[maybe_unused]] Mapping mapping_of(const void* address) {  // unused under ASan
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    Mapping mapping;
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream words(line);
        if (words >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
            if (inside) return mapping;  // the holding entry ended without VmFlags
            inside = begin <= at && at < end;
            if (inside) {
                std::string perms, offset, device, inode;
                words >> perms >> offset >> device >> inode;
                std::getline(words >> std::ws, mapping.name);
                mapping.found = true;
            }
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            mapping.flags = line.substr(8) + " ";
            return mapping;
        }
    }
    return mapping;
}

}  // namespace

TEST_CASE("prepare_one_off_heap: MiB buffers on the heap's huge pages, large ones mapped apart") {
#if !defined(__GLIBC__) || !defined(__linux__)
    SUCCEED("skipped: the set-up is glibc's malloc on Linux only");
#elif defined(PHONGRAST_SANITIZER_MALLOC)
    WARN("skipped: malloc is AddressSanitizer's here, which the set-up leaves alone");
    phongrast::cli::prepare_one_off_heap();  // still callable: it must change nothing and not crash
    void* buffer = std::malloc(3 << 20);
    REQUIRE(buffer != nullptr);
    std::memset(buffer, 1, 3 << 20);
    std::free(buffer);
#else
    if (!std::ifstream("/proc/self/smaps")) {
        SUCCEED("skipped: no /proc/self/smaps to check the mappings with");
        return;
    }
    constexpr std::size_t kMiB = std::size_t(1) << 20;
    phongrast::cli::prepare_one_off_heap();
    // Without the set-up, glibc maps every block over 128 KiB apart.
    void* buffer = std::malloc(3 * kMiB);
    REQUIRE(buffer != nullptr);
    std::memset(buffer, 1, 3 * kMiB);
    const Mapping heap = mapping_of(buffer);
    REQUIRE(heap.found);
    CHECK(heap.name == "[heap]");
    INFO("VmFlags: " << heap.flags);
    CHECK(heap.flags.find(" hg ") != std::string::npos);  // MADV_HUGEPAGE

    void* large = std::malloc(40 * kMiB);  // over the 32 MiB threshold
    REQUIRE(large != nullptr);
    const Mapping apart = mapping_of(large);
    REQUIRE(apart.found);
    CHECK(apart.name.empty());  // an anonymous mapping of its own, returned on free
    std::free(large);
    std::free(buffer);
#endif
}

namespace {

// A stand-in for malloc and free: hands out the addresses queued in `placements`, in turn, and records the sizes
// asked for and the blocks given back.
std::vector<std::uintptr_t> placements;
std::vector<std::size_t> sizes_asked;
std::vector<void*> released;
void* fake_allocate(std::size_t bytes) {
    sizes_asked.push_back(bytes);
    if (sizes_asked.size() > placements.size()) return nullptr;
    return reinterpret_cast<void*>(placements[sizes_asked.size() - 1]);
}
void fake_release(void* block) { released.push_back(block); }

}  // namespace

TEST_CASE("the one-off heap's hold comes from the heap's top, up to the next 2 MiB boundary if placed elsewhere") {
    constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
    constexpr std::uintptr_t kHeader = 2 * sizeof(std::size_t);
    constexpr std::uintptr_t first = 64 * kHugePage, last = first + 14 * kHugePage, top = first - 4256;
    constexpr std::uintptr_t elsewhere = 3 * kHugePage + 4096;
    placements.clear();
    sizes_asked.clear();
    released.clear();
    SECTION("placed at the top: held up to the first boundary") {
        placements = {top};
        CHECK(phongrast::cli::hold_up_to_huge_page(top, first, last, fake_allocate, fake_release) ==
              reinterpret_cast<void*>(top));
        CHECK(sizes_asked == std::vector<std::size_t>{first - top - kHeader});
        CHECK(released.empty());
    }
    SECTION("placed elsewhere (a free chunk it fits): given back, then held up to the next boundary") {
        placements = {elsewhere, top};
        CHECK(phongrast::cli::hold_up_to_huge_page(top, first, last, fake_allocate, fake_release) ==
              reinterpret_cast<void*>(top));
        CHECK(sizes_asked == std::vector<std::size_t>{first - top - kHeader, first + kHugePage - top - kHeader});
        CHECK(released == std::vector<void*>{reinterpret_cast<void*>(elsewhere)});
    }
    SECTION("the first boundary within a header of the top: held up to the next one") {
        placements = {first - kHeader};
        CHECK(phongrast::cli::hold_up_to_huge_page(first - kHeader, first, last, fake_allocate, fake_release) ==
              reinterpret_cast<void*>(first - kHeader));
        CHECK(sizes_asked == std::vector<std::size_t>{kHugePage});
    }
    SECTION("never placed at the top, or no memory: nothing held, every misplaced hold given back") {
        placements = {elsewhere, elsewhere + kHugePage};  // then null
        CHECK(phongrast::cli::hold_up_to_huge_page(top, first, last, fake_allocate, fake_release) == nullptr);
        CHECK(sizes_asked.size() == 3);
        CHECK(released.size() == 2);
    }
}
