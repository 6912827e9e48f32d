// 8-bit PNG channel values (internal header): what every PNG phongrast writes stores.
#ifndef PHONGRAST_SRC_IO_PNG_BYTES_HPP
#define PHONGRAST_SRC_IO_PNG_BYTES_HPP

#include <cmath>
#include <cstdint>

namespace phongrast::io::detail {

/// [0,1] clamp then round to 8 bits, no gamma curve; NaN (never expected) becomes 0.
inline std::uint8_t to_8_bit(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::lround(value * 255.0f));
}

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_PNG_BYTES_HPP
