// A shard's log, OUTDIR/.phongrast-batch/shard-I-of-N.jsonl: one JSON object
// per line and per job, appended with a single write() as soon as the job
// ends, so a shard killed at any moment leaves whole lines behind:
//   {"job": 12, "outputs": ["knot-00.png", ...], "status": "done", "render_seconds": 0.41,
//    "seconds": 0.52, "shard": "1/4", "time": 1764000000.25}
// status: done, failed (with "error"), timeout (with "error") or skipped (its
// outputs all existed). "job" is the manifest line, "time" seconds since 1970.
#ifndef PHONGRAST_APPS_BATCH_LOG_HPP
#define PHONGRAST_APPS_BATCH_LOG_HPP

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace phongrast::cli {

/// The folder of the logs inside the output folder.
std::string log_folder(const std::string& output_folder);

class BatchLog {
public:
    /// Opens (creates) the log for appending. Throws io::FileError.
    explicit BatchLog(const std::string& path);
    ~BatchLog();
    BatchLog(const BatchLog&) = delete;
    BatchLog& operator=(const BatchLog&) = delete;

    /// Appends `record` with "time" added, as one line, in one write() call.
    void append(nlohmann::json record);

private:
    std::string path_;
    int descriptor_ = -1;
};

/// Every record of every shard log in `output_folder`, in file order. Lines
/// that are not JSON objects (a log cut by a full disk) are counted in
/// `unreadable`, not returned.
std::vector<nlohmann::json> read_logs(const std::string& output_folder, int* unreadable);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_LOG_HPP
