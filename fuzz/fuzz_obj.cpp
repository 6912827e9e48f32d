// libFuzzer target: the OBJ loader (phongrast::io::read_obj), then a small
// render of whatever mesh it accepts.
//
// A clear error (phongrast::io::FileError, or std::invalid_argument from
// validation) is the expected answer to bad input; anything else -- a crash, a
// sanitizer report, another exception type, a non-finite pixel -- is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "fuzz_common.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/obj_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // read_obj takes a path: one scratch file per fuzzing process.
    static const std::string path = "/tmp/phongrast_fuzz_obj_" + std::to_string(getpid()) + ".obj";
    if (!phongrast_fuzz::write_file(path, data, size)) return 0;
    try {
        const phongrast::io::ObjFile obj = phongrast::io::read_obj(path);
        phongrast_fuzz::render_small(obj.mesh);
    } catch (const phongrast::io::FileError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
