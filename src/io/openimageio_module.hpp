// The OpenImageIO module's interface (internal header), shared by the module
// (openimageio_module.cpp, built as phongrast_openimageio.so) and the code
// that loads it on first use (openimageio_loader.cpp).
//
// Debian's libOpenImageIO pulls in some 250 shared libraries (OpenCV, FFmpeg,
// DCMTK...) whose loading and initialisers take about 175 ms; linked into the
// command or the Python module, every process paid it at start-up. Only the
// uses that need OpenImageIO itself go through here: reading image formats
// phongrast does not read with its own libraries (the sheet's labels use
// FreeType: text_drawing.hpp).
#ifndef PHONGRAST_SRC_IO_OPENIMAGEIO_MODULE_HPP
#define PHONGRAST_SRC_IO_OPENIMAGEIO_MODULE_HPP

#include <cstddef>
#include <string>

extern "C" {

/// Plain C types only: the module and the library may come from different builds.
struct PhongrastOpenImageIoModule {
    int version;  ///< kPhongrastOpenImageIoModuleVersion
    /// Any image OpenImageIO reads, to float RGB (grey repeated, the first
    /// three channels otherwise). 0 on success, with *rgb from malloc
    /// (release with free_pixels); otherwise the message in `error`.
    int (*read_rgb)(const char* path, int* rows, int* columns, float** rgb, char* error, std::size_t error_size);
    void (*free_pixels)(float* rgb);
};

/// The one symbol the module exports.
const PhongrastOpenImageIoModule* phongrast_openimageio_module(void);
}

namespace phongrast::io::detail {

constexpr int kPhongrastOpenImageIoModuleVersion = 2;  // 2: draw_text moved to FreeType
constexpr const char* kOpenImageIoModuleFile = "phongrast_openimageio.so";

/// The module, loaded on the first call (thread-safe). Searched for, in order:
/// the file named by $PHONGRAST_OPENIMAGEIO_MODULE; next to the program or
/// shared library holding this code, and in ../lib/phongrast and
/// ../<libdir>/phongrast from there; the installed <libdir>/phongrast; the
/// build tree. Throws std::runtime_error listing where it looked when it
/// cannot be loaded (`purpose` says what needed it).
const PhongrastOpenImageIoModule& openimageio_module(const std::string& purpose);

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_OPENIMAGEIO_MODULE_HPP
