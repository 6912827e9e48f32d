// Mapping a buffer's pages in one call (src/populate_pages.hpp): contents
// never change, and where the kernel supports it the writes that follow
// take (nearly) no page faults.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#endif

#include "populate_pages.hpp"
#include "resize_polling.hpp"

using namespace phongrast::detail;

namespace {

long minor_faults() {
#if defined(__linux__)
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
#else
    return 0;
#endif
}

}  // namespace

TEST_CASE("populate: reserve_populated and assign_populated keep what a plain reserve and assign give") {
    std::vector<std::uint32_t> values(1000);
    std::iota(values.begin(), values.end(), 7u);
    const std::vector<std::uint32_t> before = values;
    reserve_populated(values, std::size_t(1) << 20);  // 4 MiB: mapped, old elements kept
    CHECK(values == before);
    CHECK(values.capacity() >= (std::size_t(1) << 20));
    reserve_populated(values, 10);  // smaller than the capacity: nothing happens
    CHECK(values == before);

    std::vector<float> filled;
    assign_populated(filled, std::size_t(3) << 18, 2.5f);
    REQUIRE(filled.size() == (std::size_t(3) << 18));
    CHECK(std::all_of(filled.begin(), filled.end(), [](float v) { return v == 2.5f; }));
    assign_populated(filled, 5, -1.0f);  // shrinking: a plain assign
    CHECK(filled == std::vector<float>(5, -1.0f));

    std::vector<double> grown(3, 1.0);
    resize_polling(grown, std::size_t(1) << 20, {});  // the new part value-initialised, as resize()
    CHECK(grown[0] == 1.0);
    CHECK(grown[2] == 1.0);
    CHECK(std::all_of(grown.begin() + 3, grown.end(), [](double v) { return v == 0.0; }));
}

TEST_CASE("populate: small or empty ranges are left to page faults") {
    std::vector<char> small(4096);
    CHECK_FALSE(populate_for_writing(small.data(), small.size()));
    CHECK_FALSE(populate_for_writing(nullptr, std::size_t(1) << 20));
}

TEST_CASE("populate: writing a populated buffer takes (nearly) no page faults") {
    constexpr std::size_t kBytes = std::size_t(16) << 20;  // far above malloc's mmap threshold: fresh pages
    std::vector<unsigned char> buffer;
    buffer.reserve(kBytes);
    if (!populate_for_writing(buffer.data(), kBytes)) {
        WARN("skipped: this kernel has no MADV_POPULATE_WRITE (Linux 5.14 and later), so pages are faulted in as before");
        return;
    }
    const long faults_before = minor_faults();
    buffer.resize(kBytes, 1);
    const long faults = minor_faults() - faults_before;

    std::vector<unsigned char> unpopulated;
    unpopulated.reserve(kBytes);
    const long faults_plain_before = minor_faults();
    unpopulated.resize(kBytes, 1);
    const long faults_plain = minor_faults() - faults_plain_before;
    INFO("faults while writing 4,096 populated pages: " << faults << "; 4,096 fresh pages: " << faults_plain);
    CHECK(faults_plain >= 4096);  // the control: this measure sees a fault per fresh page
    // Populated, the buffer's own pages take none; what faults remain are not
    // the buffer's (under AddressSanitizer its shadow memory, an eighth of
    // the buffer: 512 pages, which the unpopulated write pays as well).
    CHECK(faults * 4 < faults_plain);
    CHECK(faults_plain - faults >= 4000);
}
