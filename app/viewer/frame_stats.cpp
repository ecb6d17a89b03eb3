#include "frame_stats.hpp"

#include <algorithm>
#include <cstdio>

namespace facet::view {
namespace {

/// Median of one field over frames [begin, end). The renderers' fields are 0 in frames where
/// that renderer sat out (the other was chosen), and those frames say nothing about its speed.
double medianOf(const std::vector<FrameTimes>& frames, std::size_t begin,
                double FrameTimes::*field) {
    const bool ranOnly = field == &FrameTimes::render || field == &FrameTimes::twin ||
                         field == &FrameTimes::twinUpload || field == &FrameTimes::twinDraw ||
                         field == &FrameTimes::twinReadback;
    std::vector<double> v;
    v.reserve(frames.size() - begin);
    for (std::size_t i = begin; i < frames.size(); ++i)
        if (!ranOnly || frames[i].*field > 0.0) v.push_back(frames[i].*field);
    if (v.empty()) return 0.0;
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    if (v.size() % 2) return v[mid];
    const double upper = v[mid];
    const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

FrameTimes mediansFrom(const std::vector<FrameTimes>& frames, std::size_t begin) {
    FrameTimes m;
    if (begin >= frames.size()) return m;
    for (double FrameTimes::*field :
         {&FrameTimes::render, &FrameTimes::twin, &FrameTimes::twinUpload, &FrameTimes::twinDraw,
          &FrameTimes::twinReadback, &FrameTimes::compare, &FrameTimes::upload, &FrameTimes::draw,
          &FrameTimes::ui, &FrameTimes::present, &FrameTimes::wait, &FrameTimes::total})
        m.*field = medianOf(frames, begin, field);
    return m;
}

}  // namespace

void FrameHistory::push(const FrameTimes& t) {
    if (frames.size() >= capacity && capacity > 1) {
        const std::size_t half = frames.size() / 2;
        frames.erase(frames.begin(), frames.begin() + static_cast<std::ptrdiff_t>(half));
        dropped += half;
    }
    frames.push_back(t);
    if (plot.size() >= window && !plot.empty()) plot.erase(plot.begin());
    plot.push_back(static_cast<float>(t.total));
}

FrameTimes FrameHistory::median(std::size_t skip) const {
    return mediansFrom(frames, skip > dropped ? skip - dropped : 0);
}

FrameTimes FrameHistory::recentMedian(std::size_t count) const {
    return mediansFrom(frames, frames.size() > count ? frames.size() - count : 0);
}

FrameTimes FrameHistory::medianFrameBy(std::size_t count, double FrameTimes::*field) const {
    std::vector<const FrameTimes*> ran;
    const std::size_t begin = frames.size() > count ? frames.size() - count : 0;
    for (std::size_t i = begin; i < frames.size(); ++i)
        if (frames[i].*field > 0.0) ran.push_back(&frames[i]);
    if (ran.empty()) return {};
    const auto mid = ran.begin() + static_cast<std::ptrdiff_t>((ran.size() - 1) / 2);
    std::nth_element(
        ran.begin(), mid, ran.end(),
        [field](const FrameTimes* a, const FrameTimes* b) { return a->*field < b->*field; });
    return **mid;
}

std::string fpsReport(const FrameHistory& history, std::size_t skip) {
    const std::size_t total = history.dropped + history.frames.size();
    const std::size_t n = total > skip ? total - skip : 0;
    const FrameTimes m = history.median(skip);
    char line[256];
    std::snprintf(line, sizeof line,
                  "median %.1f fps (%.2f ms: render %.2f, twin %.2f, compare %.2f, upload %.2f, "
                  "draw %.2f, ui %.2f, present %.2f, wait %.2f) over %zu frames",
                  m.total > 0.0 ? 1000.0 / m.total : 0.0, m.total, m.render, m.twin, m.compare,
                  m.upload, m.draw, m.ui, m.present, m.wait, n);
    return line;
}

}  // namespace facet::view
