#include "run_output.hpp"

#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <system_error>

namespace facet::app {

namespace fs = std::filesystem;

Result<std::string> prepareOutputFolder(const std::string& named, const std::string& stem,
                                        const std::string& parent) {
    std::error_code ec;
    if (!named.empty()) {
        fs::create_directories(named, ec);
        if (!fs::is_directory(named))
            return Error{{named, 0},
                         "cannot create the output folder" +
                             (ec ? " (" + ec.message() + ")" : std::string(" (not a folder)"))};
        return named;
    }
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const fs::path base = fs::path(parent) / (stem + "-" + stamp);
    // create_directory is false for a folder that exists: a run started in the same second
    // as another gets a name of its own rather than sharing (and overwriting) that one's.
    for (int k = 1; k < 1000; ++k) {
        const fs::path p = k == 1 ? base : fs::path(base.string() + "-" + std::to_string(k));
        if (fs::create_directory(p, ec)) return p.lexically_normal().string();
        if (ec)
            return Error{{p.string(), 0}, "cannot create the output folder (" + ec.message() + ")"};
    }
    return Error{{base.string(), 0}, "cannot create the output folder (1000 of that name exist)"};
}

ProgressLine::ProgressLine(std::FILE* out, double logSeconds)
    : out_(out), logSeconds_(logSeconds), interactive_(isatty(fileno(out)) != 0) {}

void ProgressLine::update(const std::string& text, bool force) {
    if (interactive_) {
        if (shown_ > 0 && text == last_) return;
        last_ = text;
        // Padded over the previous line's tail, so a shorter line leaves no letters behind.
        const std::size_t pad = shown_ > text.size() ? shown_ - text.size() : 0;
        std::fprintf(out_, "\r%s%*s", text.c_str(), static_cast<int>(pad), "");
        shown_ = text.size();
        std::fflush(out_);
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (!force && loggedOnce_ &&
        std::chrono::duration<double>(now - lastLog_).count() < logSeconds_)
        return;
    std::fprintf(out_, "%s\n", text.c_str());
    std::fflush(out_);
    lastLog_ = now;
    loggedOnce_ = true;
}

void ProgressLine::finish(const std::string& text) {
    if (interactive_ && shown_ > 0) {
        const std::size_t pad = shown_ > text.size() ? shown_ - text.size() : 0;
        std::fprintf(out_, "\r%s%*s\n", text.c_str(), static_cast<int>(pad), "");
    } else {
        std::fprintf(out_, "%s\n", text.c_str());
    }
    shown_ = 0;
    std::fflush(out_);
}

void ProgressLine::clear() {
    if (interactive_ && shown_ > 0) {
        std::fprintf(out_, "\r%*s\r", static_cast<int>(shown_), "");
        std::fflush(out_);
    }
    shown_ = 0;
    last_.clear();
}

}  // namespace facet::app
