#include "process_exit.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define PHONGRAST_LEAK_CHECKED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PHONGRAST_LEAK_CHECKED 1
#endif

namespace phongrast::cli {

int end_one_off_process(int status) {
#if defined(PHONGRAST_LEAK_CHECKED)
    return status;
#else
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);  // as exit() would (whose status does not tell of a failed flush either)
    std::_Exit(status);
#endif
}

}  // namespace phongrast::cli
