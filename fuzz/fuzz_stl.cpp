// libFuzzer target: the STL reader (ASCII and binary, welding), then a small render of whatever mesh it
// accepts (see fuzz_mesh_reader for what a finding is).
#include <cstdint>

#include "fuzz_common.hpp"
#include "phongrast/io/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return phongrast_fuzz::fuzz_mesh_reader(data, size, ".stl", phongrast::io::read_stl);
}
