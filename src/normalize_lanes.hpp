// Many vectors normalised at once (internal header).
#ifndef PHONGRAST_SRC_NORMALIZE_LANES_HPP
#define PHONGRAST_SRC_NORMALIZE_LANES_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "lanes_isa.hpp"

namespace phongrast::detail {
inline namespace PHONGRAST_LANES_ISA {

/// safe_normalize() of n vectors at once, written so that the compiler
/// vectorises it: the same operations in the same order, lane by lane, so
/// the same results bit for bit; a vector safe_normalize() would make zero
/// computes a (discarded) quotient by 1 instead of branching. In place:
/// (x[i], y[i], z[i]) is vector i.
template <typename Real>
void safe_normalize_lanes(std::size_t n, Real* x, Real* y, Real* z) {
    for (std::size_t i = 0; i < n; ++i) {
        const Real largest = std::max(std::abs(x[i]), std::max(std::abs(y[i]), std::abs(z[i])));
        const bool usable = largest > Real(0) && largest <= std::numeric_limits<Real>::max();  // > 0 and finite
        const Real divisor = usable ? largest : Real(1);
        const Real sx = x[i] / divisor, sy = y[i] / divisor, sz = z[i] / divisor;
        const Real length = std::sqrt(sx * sx + sy * sy + sz * sz);
        x[i] = usable ? sx / length : Real(0);
        y[i] = usable ? sy / length : Real(0);
        z[i] = usable ? sz / length : Real(0);
    }
}

}  // namespace PHONGRAST_LANES_ISA
}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_NORMALIZE_LANES_HPP
