// The OBJ path phongrast used before its own reader, kept callable for the
// loading benchmark only: a line-by-line check (split into word strings,
// strtod/strtoll), then tinyobjloader (double build) parsing the text again.
#ifndef PHONGRAST_BENCH_LEGACY_OBJ_READER_HPP
#define PHONGRAST_BENCH_LEGACY_OBJ_READER_HPP

#include <string>

#include "phongrast/mesh.hpp"

namespace phongrast_bench {

/// Throws std::runtime_error on a bad file (the benchmark only reads good ones).
phongrast::Mesh legacy_read_obj(const std::string& path);

}  // namespace phongrast_bench

#endif  // PHONGRAST_BENCH_LEGACY_OBJ_READER_HPP
