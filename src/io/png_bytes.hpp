// 8-bit PNG channel values (internal header): what every PNG phongrast writes stores.
#ifndef PHONGRAST_SRC_IO_PNG_BYTES_HPP
#define PHONGRAST_SRC_IO_PNG_BYTES_HPP

#include <cmath>
#include <cstdint>

namespace phongrast::io::detail {

/// [0,1] clamp then round to 8 bits, no gamma curve; NaN (never expected) becomes 0.
/// The rounding is std::lround(clamped * 255.0f)'s (half away from zero)
/// without the library call, so that a loop over an image vectorizes: the
/// float product is below 256, so adding 0.5 in double is exact and
/// truncating the sum rounds it.
inline std::uint8_t to_8_bit(float value) {
    const float clamped = value > 0.0f ? (value < 1.0f ? value : 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(clamped * 255.0f) + 0.5));
}

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_PNG_BYTES_HPP
