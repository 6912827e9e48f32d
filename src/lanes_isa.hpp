// The instruction set the lane-by-lane lighting headers (normalize_lanes.hpp,
// shade_lanes.hpp, vertex_lighting_lanes.hpp, seed_corner_lanes.hpp) are
// compiled for, as the name of the inline namespace their templates live in
// (internal header).
//
// Every translation unit compiles them for the baseline (x86-64: SSE2)
// except lighting_avx2.cpp, which defines PHONGRAST_LANES_ISA as avx2
// and includes them inside `#pragma GCC target("avx2")`. Different
// namespaces give the two compilations different symbols, so the linker can
// never substitute an AVX2 copy for code that must run on any x86-64 (as
// fill_kernels.hpp does with PHONGRAST_FILL_ISA).
#ifndef PHONGRAST_SRC_LANES_ISA_HPP
#define PHONGRAST_SRC_LANES_ISA_HPP

#ifndef PHONGRAST_LANES_ISA
#define PHONGRAST_LANES_ISA baseline
#endif

#endif  // PHONGRAST_SRC_LANES_ISA_HPP
