// Message pieces for the image-size limit (internal header; the limit itself
// is public: include/phongrast/image.hpp).
#ifndef PHONGRAST_SRC_IMAGE_SIZE_HPP
#define PHONGRAST_SRC_IMAGE_SIZE_HPP

#include <cstdio>
#include <string>

namespace phongrast::detail {

/// "111.8 GiB", "3.0 MiB".
std::string memory_text(double bytes);
/// "at most 268435456 <unit> (3.0 GiB as float RGB)".
std::string image_limit_text(const char* unit);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_IMAGE_SIZE_HPP
