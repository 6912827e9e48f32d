#include "batch_progress.hpp"

#include <cstdio>

#include <unistd.h>

namespace phongrast::cli {

BatchProgress::BatchProgress(bool quiet, std::size_t jobs, std::size_t images)
    : shown_(!quiet && isatty(STDERR_FILENO) != 0), jobs_(jobs), images_(images),
      start_(std::chrono::steady_clock::now()) {
    show();
}

void BatchProgress::job_ended(std::size_t images, bool failed) {
    ++jobs_ended_;
    images_written_ += images;
    failed_ += failed ? 1 : 0;
    show();
}

void BatchProgress::show() const {
    if (!shown_) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = seconds > 0.0 ? static_cast<double>(images_written_) / seconds : 0.0;
    char failed[32] = "";
    if (failed_ > 0) std::snprintf(failed, sizeof failed, ", %zu failed", failed_);
    char left[48] = "";
    if (rate > 0.0 && images_ > images_written_) {
        const long remaining = static_cast<long>(static_cast<double>(images_ - images_written_) / rate + 0.5);
        std::snprintf(left, sizeof left, ", about %ld:%02ld left", remaining / 60, remaining % 60);
    }
    std::fprintf(stderr, "\r\033[K[%zu/%zu jobs] %.1f images/s%s%s", jobs_ended_, jobs_, rate, failed, left);
    std::fflush(stderr);
}

void BatchProgress::error(const std::string& text) const {
    std::fprintf(stderr, "%sphongrast: error: %s\n", shown_ ? "\r\033[K" : "", text.c_str());
    show();
}

void BatchProgress::finish() const {
    if (!shown_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace phongrast::cli
