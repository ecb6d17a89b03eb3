#pragma once
// The loaders' side of LoadControl: a load is split into phases (reading the file, checking it,
// parsing it, building the mesh), each a share of the whole, and reports through this meter.
// Calls are cheap when no control is given; reports are thinned to steps of 1/1000 so a viewer
// is not called back millions of times.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>

#include "facet/error.hpp"
#include "facet/load_control.hpp"

namespace facet::io {

/// How many lines a text loader reads between two step() calls.
inline constexpr std::uint64_t kLinesPerStep = 4096;

/// Progress of one load through its phases, and whether it was cancelled.
class ProgressMeter {
  public:
    /// `control` may be null (no reports, never cancelled); it must outlive the meter.
    explicit ProgressMeter(const LoadControl* control) : control_(control) {}

    /// Later step() calls fill [begin, end] of the whole load.
    void phase(float begin, float end) {
        begin_ = begin;
        end_ = end;
        report(begin);
    }

    /// `done` of `total` units of the current phase are through; false once cancelled.
    bool step(std::uint64_t done, std::uint64_t total) {
        if (!control_) return true;
        if (cancelled()) return false;
        const float f = total == 0
                            ? 1.0f
                            : static_cast<float>(std::min(
                                  1.0, static_cast<double>(done) / static_cast<double>(total)));
        report(begin_ + (end_ - begin_) * f);
        return true;
    }

    /// True once the caller asked to stop.
    bool cancelled() const {
        return control_ && control_->cancel && control_->cancel->load(std::memory_order_relaxed);
    }

    /// The load is complete: reports 1.
    void finish() { report(1.0f); }

    /// The error a cancelled load returns, naming the file it was reading.
    static Error cancelledError(const std::string& file) {
        return Error{{file, 0}, "loading cancelled", true};
    }

    /// A control for a nested load (a scene's mesh) whose 0..1 fills [begin, end] of this one.
    LoadControl sub(float begin, float end) {
        if (!control_) return {};
        LoadControl child;
        child.cancel = control_->cancel;
        child.progress = [this, begin, end](float f) { report(begin + (end - begin) * f); };
        return child;
    }

  private:
    void report(float f) {
        if (!control_ || !control_->progress) return;
        f = std::clamp(f, 0.0f, 1.0f);
        // Monotonic, and thinned: only a step of 1/1000 or the final 1 is passed on.
        if (f <= last_ || (f < 1.0f && f < last_ + 0.001f)) return;
        last_ = f;
        control_->progress(f);
    }

    const LoadControl* control_;
    float begin_ = 0.0f;
    float end_ = 1.0f;
    float last_ = -1.0f;
};

}  // namespace facet::io
