// Progress of a shard on stderr, only when stderr is a terminal and not
// --quiet: "[37/120 jobs] 14.2 images/s, 1 failed, about 0:42 left".
#ifndef PHONGRAST_APPS_BATCH_PROGRESS_HPP
#define PHONGRAST_APPS_BATCH_PROGRESS_HPP

#include <chrono>
#include <cstddef>
#include <string>

namespace phongrast::cli {

class BatchProgress {
public:
    /// `jobs` to run, `images` they write in all.
    BatchProgress(bool quiet, std::size_t jobs, std::size_t images);
    /// One job ended, after writing `images` images (0 when it failed).
    void job_ended(std::size_t images, bool failed);
    /// A message on stderr (always, even --quiet), on its own line above the progress.
    void error(const std::string& text) const;
    /// Ends the progress line.
    void finish() const;

private:
    void show() const;

    bool shown_;
    std::size_t jobs_;
    std::size_t images_;
    std::size_t jobs_ended_ = 0;
    std::size_t images_written_ = 0;
    std::size_t failed_ = 0;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_PROGRESS_HPP
