#pragma once
// What `facet accuracy` and `facet sweeps` share around their measurements: the folder their
// files go to (a new one unless the user names one, so a run never writes over files it was not
// asked to, such as the charts committed under docs/) and the progress they show on stderr.

#include <chrono>
#include <cstdio>
#include <string>

#include "facet/error.hpp"

namespace facet::app {

/// The folder a run writes to. With `named` empty, a new folder `<stem>-YYYYMMDD-HHMMSS` (local
/// time; `-2`, `-3`... appended when that exists) made in `parent`; otherwise `named`, made
/// with its parents when missing (files of the same names in it are replaced: the user asked
/// for that folder). An Error naming the folder when it cannot be made or is not a folder.
Result<std::string> prepareOutputFolder(const std::string& named, const std::string& stem,
                                        const std::string& parent = ".");

/// Progress on a stream (stderr): on a terminal one line rewritten in place as often as it
/// changes; in a log (a pipe or file) whole lines, each forced one and otherwise at most one
/// every `logSeconds`, so a log shows every phase without thousands of lines. The one progress
/// line of the command line: `facet accuracy` and `sweeps` use it, `render` through
/// DelayedProgress.
class ProgressLine {
  public:
    /// Writes to `out`; a terminal is told from its file descriptor.
    explicit ProgressLine(std::FILE* out = stderr, double logSeconds = 5.0);

    /// Shows `text` as the current step; `force` writes it to a log even within `logSeconds`
    /// of the last line (a phase starting, a tenth of the ground truth done).
    void update(const std::string& text, bool force = false);

    /// Writes `text` as a line of its own that stays (a result), replacing the current step.
    void finish(const std::string& text);

    /// Blanks the current step on a terminal (nothing to do in a log): no line stays.
    void clear();

    /// Whether the stream is a terminal.
    bool interactive() const { return interactive_; }

  private:
    std::FILE* out_;
    double logSeconds_;
    bool interactive_ = false;
    std::size_t shown_ = 0;  ///< length of the transient line on the terminal
    std::string last_;       ///< the transient line shown, not written again unchanged
    std::chrono::steady_clock::time_point lastLog_{};
    bool loggedOnce_ = false;
};

}  // namespace facet::app
