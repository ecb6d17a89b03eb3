#include "delayed_progress.hpp"

#include <cstdio>
#include <cstdlib>
#include <utility>

namespace facet::app {

double progressDelaySeconds() {
    if (const char* text = std::getenv("FACET_PROGRESS_AFTER")) {
        char* end = nullptr;
        const double s = std::strtod(text, &end);
        if (end != text && s >= 0.0) return s;
    }
    return 1.0;
}

DelayedProgress::DelayedProgress(std::string command, double delaySeconds)
    : command_(std::move(command)), start_(std::chrono::steady_clock::now()), delay_(delaySeconds) {
    control_.progress = [this](float done) { fraction(done); };
    thread_ = std::thread([this] { run(); });
}

DelayedProgress::~DelayedProgress() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void DelayedProgress::phase(const std::string& name, float done) {
    std::lock_guard lock(mutex_);
    phase_ = name;
    fraction_ = done;
    show();  // a phase shows as it starts, however short, once the delay is over
}

void DelayedProgress::fraction(float done) {
    std::lock_guard lock(mutex_);
    fraction_ = done;
}

void DelayedProgress::show() {
    const auto now = std::chrono::steady_clock::now();
    if (now - start_ < delay_ || phase_.empty()) return;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    char tail[48];
    if (fraction_ >= 0.0f)
        std::snprintf(tail, sizeof tail, " %d%% (%.1f s)", static_cast<int>(fraction_ * 100.0f),
                      seconds);
    else
        std::snprintf(tail, sizeof tail, " (%.1f s)", seconds);
    line_.update(command_ + ": " + phase_ + tail, phase_ != shownPhase_);
    shownPhase_ = phase_;
}

void DelayedProgress::run() {
    std::unique_lock lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::milliseconds(100));
        if (!stop_) show();
    }
    line_.clear();
}

}  // namespace facet::app
