// Mapping a new buffer's pages in one system call (internal header).
//
// The first write to fresh memory costs the kernel a page fault per 4 KiB
// page. On the virtual machines this project is measured on a fault costs
// 7 us idle and over 30 us under load (8 MiB written page by page took
// 66-85 ms; mapped first with MADV_POPULATE_WRITE, 15-24 ms), and a
// process's first render writes megabytes of fresh buffers: in a one-off
// `phongrast render` of a 10k-triangle mesh at 256x256 about 1,700 faults
// were a third of the process's time. Later frames of a Renderer reuse
// their buffers and fault nothing, so this matters for first frames only.
#ifndef PHONGRAST_SRC_POPULATE_PAGES_HPP
#define PHONGRAST_SRC_POPULATE_PAGES_HPP

#include <cstddef>
#include <type_traits>
#include <vector>

namespace phongrast::detail {

/// Asks the kernel to map the whole pages inside [begin, begin + bytes)
/// for writing now, in one call (madvise MADV_POPULATE_WRITE, Linux 5.14 and
/// later). Ranges under 16 KiB (four pages) are left to faults; elsewhere, or
/// on an older kernel, nothing happens. The memory's contents are not
/// changed: pages already mapped stay as they are, new ones read as zero, as
/// they would after a fault. Returns whether the kernel mapped the pages
/// (for tests; callers need not care).
bool populate_for_writing(const void* begin, std::size_t bytes);

/// Gives the whole pages inside [begin, begin + bytes) back to the kernel
/// (madvise MADV_DONTNEED): they no longer count as resident, and read as
/// zero when touched again. Only for memory that holds nothing, such as a
/// vector's capacity past its size. Returns whether pages were released
/// (for tests; callers need not care); elsewhere than Linux nothing happens.
bool release_pages(const void* begin, std::size_t bytes);

template <typename Allocator, typename = void>
struct KnowsHugePages : std::false_type {};
template <typename Allocator>
struct KnowsHugePages<Allocator, std::void_t<decltype(Allocator::on_huge_pages(nullptr))>> : std::true_type {};

/// populate_for_writing() for memory of a vector with `Allocator`, except
/// memory on huge pages (huge_page_pool.hpp), which is faulted in a 2 MiB
/// page at a time: populating huge pages ahead took longer here.
template <typename Allocator>
bool populate_for_writing_in(const void* begin, std::size_t bytes) {
    if constexpr (KnowsHugePages<Allocator>::value) {
        if (bytes >= (std::size_t(16) << 10) && Allocator::on_huge_pages(begin)) return false;
    }
    return populate_for_writing(begin, bytes);
}

/// values.reserve(size), the new capacity mapped at once (populate_for_writing).
template <typename T, typename A>
void reserve_populated(std::vector<T, A>& values, std::size_t size) {
    if (size <= values.capacity()) return;
    values.reserve(size);
    populate_for_writing_in<A>(values.data() + values.size(), (values.capacity() - values.size()) * sizeof(T));
}

/// values.assign(size, value) into memory mapped at once when it must grow.
template <typename T, typename A>
void assign_populated(std::vector<T, A>& values, std::size_t size, const T& value) {
    if (size > values.capacity()) {
        values.clear();
        reserve_populated(values, size);
    }
    values.assign(size, value);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_POPULATE_PAGES_HPP
