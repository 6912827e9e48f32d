// libFuzzer target: the OBJ loader (phongrast::io::read_obj), then a small
// render of whatever mesh it accepts (see fuzz_mesh_reader for what a finding is).
#include <cstdint>

#include "fuzz_common.hpp"
#include "phongrast/io/obj_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return phongrast_fuzz::fuzz_mesh_reader(data, size, ".obj", phongrast::io::read_obj);
}
