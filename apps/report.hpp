// What the program says: notes and warnings on stderr (silenced by --quiet),
// progress on stderr only when it is a terminal, the one-line render summary,
// and the --stats-json file.
#ifndef PHONGRAST_APPS_REPORT_HPP
#define PHONGRAST_APPS_REPORT_HPP

#include <string>
#include <vector>

#include "phongrast/render.hpp"

namespace phongrast::cli {

class Messages {
public:
    explicit Messages(bool quiet);
    bool quiet() const { return quiet_; }
    /// Whether progress is shown: stderr is a terminal and not --quiet.
    bool shows_progress() const { return !quiet_ && terminal_; }
    void note(const std::string& text) const;     ///< stderr, "phongrast: ..."
    void warning(const std::string& text) const;  ///< stderr, "phongrast: warning: ..."
    void result(const std::string& text) const;   ///< stdout (where the image went, summaries)
    /// "\r[step/steps] what" on stderr when it is a terminal; done() ends the line.
    void progress(int step, int steps, const std::string& what) const;
    void progress_done() const;

private:
    bool quiet_;
    bool terminal_;
};

/// "12288 triangles in, 6020 drawn, 0 dropped, 12 clipped, 6268 culled, ... render 41.3 ms";
/// with `load_seconds` >= 0, "...; load 812.40 ms, render 41.30 ms".
std::string summary_line(const RenderStats& stats, double seconds, double load_seconds = -1.0);

struct Timing {
    std::vector<double> seconds;  ///< one per timed run, in order
    bool warm_up = false;
    double warm_up_seconds = -1.0;  ///< the warm-up render (a Renderer's first frame); < 0: none
    double load_seconds = -1.0;  ///< reading the mesh file; < 0: not measured
    double median() const;
    double min() const;
    double max() const;
};

/// The --stats-json document: timing and the last run's RenderStats.
std::string stats_json(const Timing& timing, const RenderStats& stats, const Scene& scene,
                       const RenderOptions& options);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_REPORT_HPP
