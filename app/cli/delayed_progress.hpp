#pragma once
// The progress of a command that may run for seconds (a 16384² frame, a heavy supersample):
// nothing for the first second, so fast renders stay quiet; then the phase (loading, drawing,
// encoding) with its percentage where it is known, written through the one ProgressLine
// (accuracy/run_output.hpp): on a terminal one line rewritten in place and cleared at the end;
// into a file or pipe, a line per change of phase and at most one a second otherwise.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "accuracy/run_output.hpp"
#include "facet/load_control.hpp"

namespace facet::app {

/// Seconds before the first progress line; FACET_PROGRESS_AFTER overrides it (0: at once).
double progressDelaySeconds();

/// The progress of one command, shown by a thread of its own once `delaySeconds` have passed.
class DelayedProgress {
  public:
    /// `command` starts each line ("facet render"); nothing shows before `delaySeconds`.
    explicit DelayedProgress(std::string command, double delaySeconds = progressDelaySeconds());
    ~DelayedProgress();
    DelayedProgress(const DelayedProgress&) = delete;
    DelayedProgress& operator=(const DelayedProgress&) = delete;

    /// A new phase, e.g. "drawing", with the share of it done (negative: not known).
    void phase(const std::string& name, float done = -1.0f);
    /// The share of the current phase done, 0..1.
    void fraction(float done);
    /// A control whose progress reports go to fraction() (for loaders and the PNG writer).
    const LoadControl* control() const { return &control_; }

  private:
    void run();
    void show();  // under mutex_: the line, once the delay is over

    std::string command_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::duration<double> delay_;
    LoadControl control_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    ProgressLine line_{stderr, 1.0};  // under mutex_
    std::string phase_;
    float fraction_ = -1.0f;  // unknown
    bool stop_ = false;
    std::string shownPhase_;  // the phase of the last line: a new one is always written
    std::thread thread_;
};

}  // namespace facet::app
