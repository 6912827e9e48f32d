#include "populate_pages.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace phongrast::detail {

bool populate_for_writing(const void* begin, std::size_t bytes) {
#if defined(__linux__)
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14 (include/uapi/asm-generic/mman-common.h)
#endif
    constexpr std::size_t kSmallest = std::size_t(16) << 10;
    if (begin == nullptr || bytes < kSmallest) return false;
    static const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) / page * page;
    if (last <= first) return false;
    // Only a hint: EINVAL on kernels before 5.14, ENOMEM and friends leave the
    // pages to be faulted in one by one as before. Nothing to report.
    return madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE) == 0;
#else
    (void)begin;
    (void)bytes;
    return false;
#endif
}

bool release_pages(const void* begin, std::size_t bytes) {
#if defined(__linux__)
    if (begin == nullptr) return false;
    static const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) / page * page;
    if (last <= first) return false;
    return madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED) == 0;
#else
    (void)begin;
    (void)bytes;
    return false;
#endif
}

}  // namespace phongrast::detail
