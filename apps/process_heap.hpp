// The command's own malloc settings for a process that renders once.
#ifndef PHONGRAST_APPS_PROCESS_HEAP_HPP
#define PHONGRAST_APPS_PROCESS_HEAP_HPP

#include <cstddef>
#include <cstdint>

namespace phongrast::cli {

/// Sets glibc's malloc up for a short process that reads a mesh, renders
/// and writes an image (render, thumbnail, sheet, generate): buffers up to
/// 32 MiB come from the heap (not fresh mappings per buffer, unmapped again
/// on free), and the heap's first 32 MiB is advised as transparent huge
/// pages, so that the first writes to the reader's, renderer's and encoder's
/// buffers (on the main thread) fault once per 2 MiB instead of once per
/// 4 KiB page (about 5 us each on a virtual machine).
/// Called first thing in main: a command's setting, never the library's
/// (a library must not change its host's malloc). Does nothing where
/// glibc's mallopt or MADV_HUGEPAGE is missing; the pictures do not change.
void prepare_one_off_heap();

/// prepare_one_off_heap()'s hold: a block from allocate() starting at `top`
/// (the heap's free top, 2 MiB boundaries `first` to `last` above it) and
/// ending just below the first boundary more than a header above `top`, or
/// below the next one whenever allocate() places a hold elsewhere (a free
/// chunk it fits), which is then given to release(). Null if none could be
/// placed at `top`. Apart for its test: allocate and release stand for
/// malloc and free.
void* hold_up_to_huge_page(std::uintptr_t top, std::uintptr_t first, std::uintptr_t last,
                           void* (*allocate)(std::size_t), void (*release)(void*));

}  // namespace phongrast::cli

#endif
