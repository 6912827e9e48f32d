// Growing a large buffer without going silent (internal header).
#ifndef PHONGRAST_SRC_RESIZE_POLLING_HPP
#define PHONGRAST_SRC_RESIZE_POLLING_HPP

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "populate_pages.hpp"

namespace phongrast::detail {

/// values.resize(size), but growing in steps of about 4 MiB with `poll()`
/// between them (ProgressMonitor::poll_function(), which reports and throws
/// RenderCancelled once cancelled; empty: no polls). A resize value-initialises its new part on one thread: in
/// a fresh Renderer, a 2048² supersampled image is 50 MB of new zeroed
/// pages, which took 0.3-0.5 s under load with no progress report in
/// between (so Ctrl-C in Python waited that long). The contents end up the
/// same as one resize's; shrinking is one resize. Each step's new pages are
/// mapped in one call first (populate_pages.hpp).
/// `populate` false: the caller has mapped or advised the new part already (reserve_on_huge_pages).
template <typename T, typename A>
void resize_polling(std::vector<T, A>& values, std::size_t size, const std::function<void()>& poll,
                    bool populate = true) {
    if (size <= values.size()) {
        values.resize(size);
        return;
    }
    values.reserve(size);
    constexpr std::size_t kStepBytes = std::size_t(4) << 20;
    const std::size_t step = std::max<std::size_t>(1, kStepBytes / sizeof(T));
    while (values.size() < size) {
        const std::size_t next = std::min(size, values.size() + step);
        if (populate) populate_for_writing_in<A>(values.data() + values.size(), (next - values.size()) * sizeof(T));
        values.resize(next);
        if (poll) poll();
    }
}

/// values.assign(size, value), the same way: when the vector must grow
/// beyond its capacity (new pages), it is filled in steps with `poll()`
/// between them; otherwise one assign (memory already touched is fast).
template <typename T, typename A>
void assign_polling(std::vector<T, A>& values, std::size_t size, const T& value, const std::function<void()>& poll) {
    if (size <= values.capacity()) {
        values.assign(size, value);
        return;
    }
    values.clear();
    values.reserve(size);
    constexpr std::size_t kStepBytes = std::size_t(4) << 20;
    const std::size_t step = std::max<std::size_t>(1, kStepBytes / sizeof(T));
    while (values.size() < size) {
        const std::size_t next = std::min(size, values.size() + step);
        populate_for_writing_in<A>(values.data() + values.size(), (next - values.size()) * sizeof(T));
        values.resize(next, value);
        if (poll) poll();
    }
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_RESIZE_POLLING_HPP
