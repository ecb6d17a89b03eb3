#pragma once
// A progress line on stderr for a command that may run for seconds (a 16384² frame, a heavy
// supersample): nothing for the first second, so fast renders stay quiet; then the phase
// (loading, drawing, encoding) with its percentage where it is known. On a terminal one line is
// rewritten in place and cleared at the end; into a file or pipe, a line per change of phase
// and at most one a second otherwise.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "facet/load_control.hpp"

namespace facet::app {

/// Seconds before the first progress line; FACET_PROGRESS_AFTER overrides it (0: at once).
double progressDelaySeconds();

/// The progress of one command, shown by a thread of its own.
class ProgressLine {
  public:
    /// `command` starts each line ("facet render"); nothing shows before `delaySeconds`.
    explicit ProgressLine(std::string command, double delaySeconds = progressDelaySeconds());
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    /// A new phase, e.g. "drawing", with the share of it done (negative: not known).
    void phase(const std::string& name, float done = -1.0f);
    /// The share of the current phase done, 0..1.
    void fraction(float done);
    /// A control whose progress reports go to fraction() (for loaders and the PNG writer).
    const LoadControl* control() const { return &control_; }

  private:
    void run();
    std::string text() const;  // under mutex_
    void show();               // under mutex_: the line, if it is time and there is news

    std::string command_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::duration<double> delay_;
    bool terminal_ = false;
    LoadControl control_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::string phase_;
    float fraction_ = -1.0f;  // unknown
    bool stop_ = false;
    std::string shownPhase_;  // what the last line (off a terminal) showed, and when
    std::chrono::steady_clock::time_point shownAt_;
    std::size_t shownWidth_ = 0;  // of the terminal line, to blank what a shorter one leaves
    std::thread thread_;
};

}  // namespace facet::app
