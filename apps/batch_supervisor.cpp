#include "batch_supervisor.hpp"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "batch_log.hpp"
#include "batch_progress.hpp"
#include "batch_worker.hpp"
#include "phongrast/io/error.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// "killed by signal 9" / "exited with status 3" for a waitpid status.
std::string describe_exit(int status) {
    if (WIFSIGNALED(status)) {
        return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    }
    return "exited with status " + std::to_string(WEXITSTATUS(status));
}

class Supervisor {
public:
    Supervisor(const std::vector<const BatchJob*>& jobs, const ShardRun& run, BatchLog& log,
               BatchProgress& progress)
        : jobs_(jobs), run_(run), log_(log), progress_(progress) {}

    /// Runs every job; returns how many failed or timed out.
    int run() {
        while (next_ < jobs_.size()) {
            start_worker();
            watch_worker();
        }
        return failures_;
    }

private:
    struct Running {
        std::size_t position;
        Clock::time_point start;
    };

    void start_worker() {
        int ends[2];
        if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
        std::cout.flush();
        std::cerr.flush();
        const pid_t parent = ::getpid();
        pid_ = ::fork();
        if (pid_ < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
        if (pid_ == 0) {
            ::close(ends[0]);
            // Die with the supervisor: a killed shard must not leave a worker writing on.
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            if (::getppid() != parent) _exit(3);
            int status = 0;
            try {
                run_worker(jobs_, next_, run_.output_folder, run_.threads, run_.image_options, ends[1], one_lane_);
            } catch (const std::exception& error) {
                std::cerr << "phongrast: internal error in the batch worker: " << error.what() << '\n';
                status = 3;
            }
            _exit(status);  // not exit(): the supervisor's copies of streams and atexit handlers are not ours
        }
        ::close(ends[1]);
        descriptor_ = ends[0];
        buffer_.clear();
        running_.clear();
    }

    /// Reads the worker's reports until it ends or is killed.
    void watch_worker() {
        for (;;) {
            pollfd watched{descriptor_, POLLIN, 0};
            const int ready = ::poll(&watched, 1, poll_timeout_ms());
            if (ready < 0 && errno == EINTR) continue;
            if (ready == 0) return stop_worker("timeout", "stopped after the job timeout of " +
                                                              format_seconds(run_.job_timeout));
            char chunk[4096];
            const ssize_t got = ::read(descriptor_, chunk, sizeof chunk);
            if (got < 0 && errno == EINTR) continue;
            if (got <= 0) return worker_ended();
            buffer_.append(chunk, static_cast<std::size_t>(got));
            for (std::size_t end; (end = buffer_.find('\n')) != std::string::npos;) {
                handle_report(nlohmann::json::parse(buffer_.substr(0, end)));
                buffer_.erase(0, end + 1);
            }
        }
    }

    int poll_timeout_ms() const {
        if (run_.job_timeout <= 0.0 || running_.empty()) return -1;
        const auto deadline = running_.front().start + std::chrono::duration<double>(run_.job_timeout);
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        return static_cast<int>(std::max<long long>(0, left) + 1);
    }

    void handle_report(const nlohmann::json& report) {
        if (report.contains("start")) {
            running_.push_back({report["start"].get<std::size_t>(), Clock::now()});
            return;
        }
        const std::size_t position = report["finished"].get<std::size_t>();
        const Running running = running_.front();
        running_.pop_front();
        nlohmann::json record = record_of(position, report["status"].get<std::string>(), running.start);
        record["render_seconds"] = report["render_seconds"];
        if (report.contains("error")) record["error"] = report["error"];
        finish(position, std::move(record));
    }

    /// The worker closed its end: it finished, or died.
    void worker_ended() {
        int status = 0;
        ::waitpid(pid_, &status, 0);
        ::close(descriptor_);
        const bool finished = WIFEXITED(status) && WEXITSTATUS(status) == 0 && running_.empty();
        if (finished && next_ >= jobs_.size()) return;
        if (!finished && running_.size() > 1 && !one_lane_) {
            // Several jobs were rendering side by side (render lanes): which one
            // crashed is not known. Their partial files go, and a worker with one
            // lane starts again from the oldest, so that the culprit crashes alone
            // and only it is recorded as failed.
            next_ = running_.front().position;
            clean_up_running(next_);
            one_lane_ = true;
            return;
        }
        // Blame the job it was on (or the next one, if it died between jobs) so the shard moves on.
        const std::size_t position = running_.empty() ? next_ : running_.front().position;
        const Clock::time_point start = running_.empty() ? Clock::now() : running_.front().start;
        nlohmann::json record = record_of(position, "failed", start);
        record["error"] = "the worker process " + describe_exit(status) + " during this job";
        clean_up_running(position);
        finish(position, std::move(record));
    }

    void stop_worker(const std::string& status, const std::string& error) {
        ::kill(pid_, SIGKILL);
        int ignored = 0;
        ::waitpid(pid_, &ignored, 0);
        ::close(descriptor_);
        const Running running = running_.front();
        nlohmann::json record = record_of(running.position, status, running.start);
        record["error"] = error;
        clean_up_running(running.position);
        finish(running.position, std::move(record));
    }

    /// Removes the temporary files of the jobs the killed worker had started.
    void clean_up_running(std::size_t position) {
        std::vector<const BatchJob*> started{jobs_[position]};
        for (const Running& running : running_) started.push_back(jobs_[running.position]);
        remove_temporary_files(started, run_.output_folder);
        running_.clear();
    }

    nlohmann::json record_of(std::size_t position, const std::string& status, Clock::time_point start) const {
        const BatchJob& job = *jobs_[position];
        return {{"job", job.line},
                {"outputs", job.outputs},
                {"status", status},
                {"seconds", std::chrono::duration<double>(Clock::now() - start).count()},
                {"shard", std::to_string(run_.shard.index) + "/" + std::to_string(run_.shard.count)}};
    }

    void finish(std::size_t position, nlohmann::json record) {
        const bool failed = record["status"] != "done";
        if (failed) {
            ++failures_;
            progress_.error("manifest line " + std::to_string(jobs_[position]->line) + ": " +
                            record["status"].get<std::string>() + ": " + record.value("error", std::string()));
        }
        log_.append(std::move(record));
        progress_.job_ended(failed ? 0 : jobs_[position]->outputs.size(), failed);
        next_ = position + 1;
    }

    static std::string format_seconds(double seconds) {
        char text[32];
        std::snprintf(text, sizeof text, "%g s", seconds);
        return text;
    }

    const std::vector<const BatchJob*>& jobs_;
    const ShardRun& run_;
    BatchLog& log_;
    BatchProgress& progress_;
    std::size_t next_ = 0;
    int failures_ = 0;
    bool one_lane_ = false;  ///< after a crash with several jobs rendering: one render lane from then on
    pid_t pid_ = -1;
    int descriptor_ = -1;
    std::string buffer_;
    std::deque<Running> running_;
};

}  // namespace

void remove_temporary_files(const std::vector<const BatchJob*>& jobs, const std::string& output_folder) {
    // io::replace_file_atomically names them ".STEM.tmp-XXXXXX.EXT" in the output's folder.
    std::map<fs::path, std::set<std::string>> names_by_folder;
    for (const BatchJob* job : jobs) {
        std::vector<std::string> files = job->files_of_job();
        for (std::size_t view = 0; view < job->outputs.size(); ++view) {
            for (const std::string& output : job->files_of_view(view)) files.push_back(output);
        }
        for (const std::string& file : files) {
            const fs::path path = fs::path(output_folder) / file;
            names_by_folder[path.parent_path()].insert(path.filename().string());
        }
    }
    for (const auto& [folder, names] : names_by_folder) {
        std::error_code error;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
            const std::string name = entry.path().filename().string();
            const std::size_t marker = name.rfind(".tmp-");
            if (name.empty() || name[0] != '.' || marker == std::string::npos || name.size() < marker + 11) continue;
            const std::string original = name.substr(1, marker - 1) + name.substr(marker + 11);
            if (names.count(original) != 0) fs::remove(entry.path(), error);
        }
    }
}

int run_shard(const std::vector<const BatchJob*>& jobs, const ShardRun& run) {
    fs::create_directories(log_folder(run.output_folder));
    BatchLog log((fs::path(log_folder(run.output_folder)) / shard_log_name(run.shard)).string());
    remove_temporary_files(jobs, run.output_folder);

    std::vector<const BatchJob*> to_render;
    std::size_t images = 0;
    const std::string shard = std::to_string(run.shard.index) + "/" + std::to_string(run.shard.count);
    for (const BatchJob* job : jobs) {
        if (!run.force && outputs_exist(*job, run.output_folder)) {
            log.append({{"job", job->line}, {"outputs", job->outputs}, {"status", "skipped"}, {"shard", shard}});
            continue;
        }
        to_render.push_back(job);
        images += job->outputs.size();
    }
    BatchProgress progress(run.quiet, to_render.size(), images);
    Supervisor supervisor(to_render, run, log, progress);
    const int failures = supervisor.run();
    progress.finish();
    if (!run.quiet) {
        std::cout << "shard " << shard << ": " << jobs.size() << " jobs: " << to_render.size() - failures
                  << " rendered, " << jobs.size() - to_render.size() << " already done, " << failures
                  << " failed; log " << (fs::path(log_folder(run.output_folder)) / shard_log_name(run.shard)).string()
                  << std::endl;
    }
    return failures > 0 ? 1 : 0;
}

}  // namespace phongrast::cli
