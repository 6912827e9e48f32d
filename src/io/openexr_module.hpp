// The OpenEXR module's interface (internal header), shared by the module
// (openexr_module.cpp, built as phongrast_openexr.so) and exr_file.cpp,
// which loads it on the first EXR read or write (module_loader.hpp).
//
// OpenEXR and the libraries it pulls in (Imath, Iex, IlmThread) are C++
// libraries whose loading and relocation cost every process that links
// them: a program linking them printed "hi" in 24.7 ms against 16.0 ms
// without them (fastest of 60 alternating runs at a load of 7;
// docs/startup.md). Most processes write PNG; only EXR reads and writes
// load them now.
#ifndef PHONGRAST_SRC_IO_OPENEXR_MODULE_HPP
#define PHONGRAST_SRC_IO_OPENEXR_MODULE_HPP

#include <cstddef>

extern "C" {

/// One channel's place in memory: pixel (x, y) of the file's data window at
/// base + x * stride + y * stride * columns. Plain C types only: the module
/// and the library may come from different builds.
struct PhongrastExrChannel {
    const char* name;
    int unsigned_int;  ///< 0: 32-bit float
    char* base;
    std::size_t stride;
};

struct PhongrastOpenExrModule {
    int version;  ///< kPhongrastOpenExrModuleVersion
    /// Writes a ZIP-compressed (16 rows per block) scan-line file. 0 on
    /// success; otherwise OpenEXR's message in `error`.
    int (*write)(const char* file, int columns, int rows, const PhongrastExrChannel* channels, std::size_t count,
                 char* error, std::size_t error_size);
    /// Opens a file for reading: its handle, or null with the message in `error`.
    void* (*open)(const char* file, int* columns, int* rows, char* error, std::size_t error_size);
    std::size_t (*channel_count)(void* handle);
    const char* (*channel_name)(void* handle, std::size_t index);  ///< alphabetical, as OpenEXR keeps them
    /// Reads the whole data window into `channels` (converted as they ask). 0 on success.
    int (*read)(void* handle, const PhongrastExrChannel* channels, std::size_t count, char* error,
                std::size_t error_size);
    void (*close)(void* handle);
};

/// The one symbol the module exports.
const PhongrastOpenExrModule* phongrast_openexr_module(void);
}

namespace phongrast::io::detail {

constexpr int kPhongrastOpenExrModuleVersion = 1;
constexpr const char* kOpenExrModuleFile = "phongrast_openexr.so";

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_OPENEXR_MODULE_HPP
