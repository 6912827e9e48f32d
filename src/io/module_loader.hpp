// Finding and loading one of phongrast's own modules (internal header): small
// shared objects that hold a heavy library's code and are dlopen'ed on first
// use, so that a process not needing that library never loads it
// (openimageio_module.hpp, openexr_module.hpp; docs/startup.md says why).
#ifndef PHONGRAST_SRC_IO_MODULE_LOADER_HPP
#define PHONGRAST_SRC_IO_MODULE_LOADER_HPP

#include <string>

namespace phongrast::io::detail {

/// What to load. Every module exports one C function, `entry`, returning a
/// pointer to its table of plain C functions, whose first member is an int
/// version: a module from another build has another version and is refused.
struct ModuleSearch {
    const char* file;             ///< e.g. "phongrast_openexr.so"
    const char* environment;      ///< the variable naming the file instead, e.g. "PHONGRAST_OPENEXR_MODULE"
    const char* build_tree_file;  ///< where this build put it
    const char* entry;            ///< the exported function's name
    int version;                  ///< the table's version this code expects
    const char* library;          ///< what the module holds, for messages ("OpenEXR")
};

struct LoadedModule {
    const void* table = nullptr;  ///< the entry's table; null when nothing loaded
    std::string failure;          ///< why not, and every place looked at
};

/// Looks, in order: the file named by $environment (nothing else then); next
/// to the program or shared library holding this code, and in
/// ../lib/phongrast and ../<libdir>/phongrast from there; the installed
/// <libdir>/phongrast; the build tree. The first that loads and has the
/// right version wins; it is never unloaded (its library's threads and
/// caches may outlive any call).
LoadedModule load_module(const ModuleSearch& search);

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_MODULE_LOADER_HPP
