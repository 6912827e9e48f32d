// The process that renders a shard's jobs, started (forked) and watched by the
// supervisor (batch_supervisor.hpp). Three threads in a pipeline:
//   loader:   reads the next jobs' scenes and meshes (at most 2 jobs ahead),
//   renderer: one phongrast::Renderer for every view of every job (its own
//             worker threads use all cores),
//   writer:   encodes and writes the images (at most 4 waiting), each to a
//             temporary file renamed into place.
// It tells the supervisor, one line of JSON each on `report_fd`,
//   {"start": K}                     when job K starts (its loading included), and
//   {"finished": K, "status": "done" | "failed", "error": "...", "render_seconds": S}
//                                    when every image of job K is written or the job failed,
// K being the job's position in the list the worker was given.
#ifndef PHONGRAST_APPS_BATCH_WORKER_HPP
#define PHONGRAST_APPS_BATCH_WORKER_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "batch_manifest.hpp"
#include "phongrast/io/image_file.hpp"

namespace phongrast::cli {

/// Renders jobs[first..] into `output_folder`, reporting on `report_fd`.
void run_worker(const std::vector<const BatchJob*>& jobs, std::size_t first, const std::string& output_folder,
                int threads, const io::ImageWriteOptions& image_options, int report_fd);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_WORKER_HPP
