// The process that renders a shard's jobs, started (forked) and watched by the
// supervisor (batch_supervisor.hpp). Threads in a pipeline:
//   loaders:  read the next jobs' scenes and meshes (a few jobs ahead; two
//             when there are several lanes, so that new meshes parse two at once),
//   lanes:    render the jobs, one whole job at a time each. With --threads 0
//             (the default) there is one lane per core (up to 4), and a small
//             job (up to 8 views of at most 512x512 samples and 262,144
//             triangles) renders on one thread beside the other lanes' small
//             jobs, each lane with its own phongrast::Renderer; any other job
//             renders alone, after the jobs before it, with every thread and
//             one Renderer the lanes share, as with a single lane. --threads N
//             gives one lane whose renders use N threads.
//   writer:   encodes and writes the images (at most 4 waiting), each to a
//             temporary file renamed into place, job by job in order.
// It tells the supervisor, one line of JSON each on `report_fd`,
//   {"start": K}                     when job K starts (its loading included), and
//   {"finished": K, "status": "done" | "failed", "error": "...", "render_seconds": S}
//                                    when every image of job K is written or the job failed,
// K being the job's position in the list the worker was given; jobs start and
// finish in that order (several may have started and not finished).
#ifndef PHONGRAST_APPS_BATCH_WORKER_HPP
#define PHONGRAST_APPS_BATCH_WORKER_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "batch_manifest.hpp"
#include "phongrast/io/image_file.hpp"

namespace phongrast::cli {

/// Renders jobs[first..] into `output_folder`, reporting on `report_fd`.
/// `one_lane`: one render lane whatever `threads` says (after a crash, so
/// that the job that crashed is the only one rendering when it crashes again).
void run_worker(const std::vector<const BatchJob*>& jobs, std::size_t first, const std::string& output_folder,
                int threads, const io::ImageWriteOptions& image_options, int report_fd, bool one_lane = false);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_WORKER_HPP
