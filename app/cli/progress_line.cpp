#include "progress_line.hpp"

#include <unistd.h>

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

ProgressLine::ProgressLine(std::string command, double delaySeconds)
    : command_(std::move(command)),
      start_(std::chrono::steady_clock::now()),
      delay_(delaySeconds),
      terminal_(::isatty(STDERR_FILENO) != 0) {
    control_.progress = [this](float done) { fraction(done); };
    thread_ = std::thread([this] { run(); });
}

ProgressLine::~ProgressLine() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void ProgressLine::phase(const std::string& name, float done) {
    std::lock_guard lock(mutex_);
    phase_ = name;
    fraction_ = done;
    show();  // a phase shows as it starts, however short, once the delay is over
}

void ProgressLine::fraction(float done) {
    std::lock_guard lock(mutex_);
    fraction_ = done;
}

std::string ProgressLine::text() const {
    if (phase_.empty()) return {};
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char tail[48];
    if (fraction_ >= 0.0f)
        std::snprintf(tail, sizeof tail, " %d%% (%.1f s)", static_cast<int>(fraction_ * 100.0f),
                      seconds);
    else
        std::snprintf(tail, sizeof tail, " (%.1f s)", seconds);
    return command_ + ": " + phase_ + tail;
}

void ProgressLine::show() {
    using Clock = std::chrono::steady_clock;
    if (Clock::now() - start_ < delay_) return;
    const std::string line = text();
    if (line.empty()) return;
    if (terminal_) {
        std::fprintf(stderr, "\r%s%*s", line.c_str(),
                     static_cast<int>(shownWidth_ > line.size() ? shownWidth_ - line.size() : 0),
                     "");
        shownWidth_ = line.size();
    } else if (phase_ != shownPhase_ || Clock::now() - shownAt_ >= std::chrono::seconds(1)) {
        std::fprintf(stderr, "%s\n", line.c_str());
        shownPhase_ = phase_;
        shownAt_ = Clock::now();
    }
    std::fflush(stderr);
}

void ProgressLine::run() {
    std::unique_lock lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::milliseconds(100));
        if (!stop_) show();
    }
    if (terminal_ && shownWidth_ > 0)
        std::fprintf(stderr, "\r%*s\r", static_cast<int>(shownWidth_), "");
}

}  // namespace facet::app
