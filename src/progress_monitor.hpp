// Progress reports and cancellation inside a render (internal header): the
// pipeline's parallel loops count their pieces of work here, and the thread
// that called render() passes the fraction done to RenderOptions::progress.
#ifndef PHONGRAST_SRC_PROGRESS_MONITOR_HPP
#define PHONGRAST_SRC_PROGRESS_MONITOR_HPP

#include <atomic>
#include <chrono>
#include <algorithm>
#include <cstddef>
#include <functional>
#include <thread>

#include "phongrast/progress.hpp"

namespace phongrast::detail {

class ProgressMonitor {
public:
    /// `callback` may be empty: then every member is a cheap no-op and nothing is ever cancelled.
    /// The monitor keeps a reference to it: `callback` must outlive the monitor (not a temporary).
    explicit ProgressMonitor(const ProgressCallback& callback)
        : callback_(callback), caller_(std::this_thread::get_id()), last_report_(std::chrono::steady_clock::now()) {
        // poll() and, once a report asked to stop, RenderCancelled: the serial
        // and library-bound stages that call it (mesh order, normals, the sort,
        // binning) stop at their next poll instead of running to their end,
        // which took up to a second under load and kept Ctrl-C waiting.
        // Small enough for std::function's own storage: no allocation.
        if (enabled()) poll_ = [this] {
            poll();
            throw_if_cancelled();
        };
    }
    explicit ProgressMonitor(ProgressCallback&&) = delete;  // a temporary would die before the monitor
    ProgressMonitor(const ProgressMonitor&) = delete;
    ProgressMonitor& operator=(const ProgressMonitor&) = delete;

    bool enabled() const { return static_cast<bool>(callback_); }

    /// Stages of the next render pass report within pass `index` of `count`
    /// equal shares (supersampling with a rotated grid renders one pass per sample).
    void set_pass(int index, int count) {
        pass_index_ = index;
        pass_count_ = count > 0 ? count : 1;
    }

    /// The next stage covers [begin, end) of the whole render in `pieces` equal pieces.
    /// Called on the calling thread between parallel loops.
    void begin_stage(double begin, double end, std::size_t pieces) {
        stage_begin_ = begin;
        stage_end_ = end;
        stage_pieces_ = pieces > 0 ? pieces : 1;
        pieces_done_.store(0, std::memory_order_relaxed);
        throw_if_cancelled();
    }

    /// Whether the workers should skip their remaining pieces.
    bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

    /// A piece of the current stage is done (any thread). On the calling
    /// thread, reports when the interval has passed since the last report.
    void piece_done() {
        if (!enabled()) return;
        const std::size_t done = pieces_done_.fetch_add(1, std::memory_order_relaxed) + 1;
        if (std::this_thread::get_id() != caller_) return;
        report_if_due(done);
    }

    /// Inside serial work or loops without a piece count: on the calling
    /// thread, reports the stage's start fraction when the interval has passed.
    void poll() {
        if (!enabled() || std::this_thread::get_id() != caller_) return;
        report_if_due(pieces_done_.load(std::memory_order_relaxed));
    }

    /// poll() as a function for loops outside the pipeline (normals, the
    /// painter's sort), which also throws RenderCancelled once cancelled (on
    /// any thread: inside a parallel loop oneTBB carries it to the caller);
    /// empty without a callback, so they skip even the call.
    const std::function<void()>& poll_function() const { return poll_; }

    /// Between stages, on the calling thread: throws RenderCancelled if a report asked to stop.
    void throw_if_cancelled() const {
        if (cancelled()) throw RenderCancelled();
    }

    /// The render is complete: the last report, with 1.
    void finish() {
        if (!enabled()) return;
        report(1.0);
        throw_if_cancelled();
    }

private:
    // Reports come at least this often while the calling thread works (the
    // contract promises every 50 ms; a piece of work is far shorter than the difference).
    static constexpr std::chrono::milliseconds kInterval{20};

    void report_if_due(std::size_t pieces_done) {
        const auto now = std::chrono::steady_clock::now();
        if (now - last_report_ < kInterval) return;
        last_report_ = now;
        const double done = double(std::min(pieces_done, stage_pieces_)) / double(stage_pieces_);
        const double in_pass = stage_begin_ + (stage_end_ - stage_begin_) * done;
        report((double(pass_index_) + in_pass) / double(pass_count_));
    }

    void report(double fraction) {
        if (cancelled()) return;
        if (!callback_(fraction)) cancelled_.store(true, std::memory_order_relaxed);
    }

    const ProgressCallback& callback_;
    std::function<void()> poll_;
    const std::thread::id caller_;
    std::chrono::steady_clock::time_point last_report_;
    double stage_begin_ = 0.0, stage_end_ = 1.0;
    std::size_t stage_pieces_ = 1;
    int pass_index_ = 0, pass_count_ = 1;
    std::atomic<std::size_t> pieces_done_{0};
    std::atomic<bool> cancelled_{false};
};

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_PROGRESS_MONITOR_HPP
