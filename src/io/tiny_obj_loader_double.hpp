// tinyobjloader with real_t = double; see tiny_obj_loader_double.cpp for why.
// Private to phongrast_io: never included from a public header.
#ifndef PHONGRAST_IO_TINY_OBJ_LOADER_DOUBLE_HPP
#define PHONGRAST_IO_TINY_OBJ_LOADER_DOUBLE_HPP

#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

static_assert(sizeof(tinyobj::real_t) == sizeof(double), "tinyobjloader must be compiled with double");

#endif  // PHONGRAST_IO_TINY_OBJ_LOADER_DOUBLE_HPP
