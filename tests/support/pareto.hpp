// The Pareto front of (time, error) points: the configurations no other one
// beats on both at once (header-only, shared with the tests).
#ifndef PHONGRAST_SUPPORT_PARETO_HPP
#define PHONGRAST_SUPPORT_PARETO_HPP

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace phongrast::support {

/// True when a is at least as fast and as accurate as b, and better in one.
inline bool dominates(double time_a, double error_a, double time_b, double error_b) {
    return time_a <= time_b && error_a <= error_b && (time_a < time_b || error_a < error_b);
}

/// Indices of the non-dominated points, fastest first (so errors decrease
/// along the result). Of points equal in both, the first one listed is kept.
inline std::vector<std::size_t> pareto_front(const std::vector<double>& times,
                                             const std::vector<double>& errors) {
    if (times.size() != errors.size()) throw std::invalid_argument("pareto_front: sizes differ");
    std::vector<std::size_t> order(times.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    // Fastest first; among equal times the most accurate first; then listing order.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (times[a] != times[b]) return times[a] < times[b];
        return errors[a] < errors[b];
    });
    std::vector<std::size_t> front;
    for (std::size_t index : order) {
        // Sorted by time, a point is on the front when it beats every faster point's error.
        if (front.empty() || errors[index] < errors[front.back()]) front.push_back(index);
    }
    return front;
}

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_PARETO_HPP
