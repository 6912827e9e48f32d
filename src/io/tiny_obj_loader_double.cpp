// The one translation unit that compiles tinyobjloader, with double precision.
//
// Debian's libtinyobjloader is built with `float`: a coordinate such as
// 10000000.25 loses its low digits while being parsed, before phongrast sees
// it (the core keeps positions in double precisely so that meshes far from
// the origin keep their detail). So the header-only implementation is compiled
// here with TINYOBJLOADER_USE_DOUBLE and the packaged library is not linked
// (linking both would give two definitions of the same symbols).
#define TINYOBJLOADER_IMPLEMENTATION
#include "tiny_obj_loader_double.hpp"
