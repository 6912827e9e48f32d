// Runs one shard and keeps its log true whatever happens to the rendering.
//
// The supervisor does no rendering itself: it forks a worker process
// (batch_worker.hpp) and watches, over a pipe, which job the worker is on.
// When a job runs longer than --job-timeout, or the worker dies (a crash in a
// library, the out-of-memory killer), the supervisor kills the worker, records
// that job as timed out or failed, removes the job's temporary files and forks
// a fresh worker from the next job. The renderer needs no way to be
// cancelled, and one bad job cannot take the rest of the shard with it. Only
// the supervisor writes the log, one whole line per job. If the supervisor
// itself is killed, the kernel kills the worker too (PR_SET_PDEATHSIG); the
// next run of the shard removes the temporary files left behind and skips
// the jobs whose images all exist.
#ifndef PHONGRAST_APPS_BATCH_SUPERVISOR_HPP
#define PHONGRAST_APPS_BATCH_SUPERVISOR_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "batch_manifest.hpp"
#include "batch_shard.hpp"
#include "phongrast/io/image_file.hpp"

namespace phongrast::cli {

struct ShardRun {
    std::string output_folder;
    Shard shard;
    double job_timeout = 0.0;  ///< seconds; 0: no limit
    bool force = false;        ///< render even the jobs whose images exist
    bool quiet = false;
    int threads = 0;
    io::ImageWriteOptions image_options;  ///< --png-compression
};

/// Renders `jobs` (this shard's, in manifest order). Returns the exit status:
/// 0 when every job succeeded or was already done, 1 when some failed or timed out.
int run_shard(const std::vector<const BatchJob*>& jobs, const ShardRun& run);

/// Removes temporary files that an interrupted write of one of `jobs`'
/// outputs left (".NAME.tmp-XXXXXX.EXT" next to the output). Only these jobs'
/// names are touched, so shards running at the same time do not disturb each other.
void remove_temporary_files(const std::vector<const BatchJob*>& jobs, const std::string& output_folder);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_SUPERVISOR_HPP
