#include "frame_stats.hpp"

#include <cstdio>
#include <utility>

#include "facet/evaluation/frame_times.hpp"

namespace facet::view {
namespace {

/// Median of one field over frames [begin, end). The renderers' fields are 0 in frames where
/// that renderer sat out (the other was chosen), and those frames say nothing about its speed.
double fieldMedian(const std::vector<StageTimes>& frames, std::size_t begin,
                   double StageTimes::*field) {
    const bool ranOnly = field == &StageTimes::render || field == &StageTimes::twin ||
                         field == &StageTimes::twinUpload || field == &StageTimes::twinDraw ||
                         field == &StageTimes::twinReadback;
    std::vector<double> v;
    v.reserve(frames.size() - begin);
    for (std::size_t i = begin; i < frames.size(); ++i)
        if (!ranOnly || frames[i].*field > 0.0) v.push_back(frames[i].*field);
    return medianOf(std::move(v));
}

StageTimes mediansFrom(const std::vector<StageTimes>& frames, std::size_t begin) {
    StageTimes m;
    if (begin >= frames.size()) return m;
    for (double StageTimes::*field :
         {&StageTimes::render, &StageTimes::twin, &StageTimes::twinUpload, &StageTimes::twinDraw,
          &StageTimes::twinReadback, &StageTimes::compare, &StageTimes::upload, &StageTimes::draw,
          &StageTimes::ui, &StageTimes::uiDraw, &StageTimes::present, &StageTimes::wait,
          &StageTimes::total})
        m.*field = fieldMedian(frames, begin, field);
    return m;
}

}  // namespace

void FrameHistory::push(const StageTimes& t) {
    if (frames.size() >= capacity && capacity > 1) {
        const std::size_t half = frames.size() / 2;
        frames.erase(frames.begin(), frames.begin() + static_cast<std::ptrdiff_t>(half));
        dropped += half;
    }
    frames.push_back(t);
    if (plot.size() >= window && !plot.empty()) plot.erase(plot.begin());
    plot.push_back(static_cast<float>(t.total));
}

StageTimes FrameHistory::median(std::size_t skip) const {
    return mediansFrom(frames, skip > dropped ? skip - dropped : 0);
}

StageTimes FrameHistory::recentMedian(std::size_t count) const {
    return mediansFrom(frames, frames.size() > count ? frames.size() - count : 0);
}

StageTimes FrameHistory::medianFrameBy(std::size_t count, double StageTimes::*field) const {
    std::vector<const StageTimes*> ran;
    const std::size_t begin = frames.size() > count ? frames.size() - count : 0;
    for (std::size_t i = begin; i < frames.size(); ++i)
        if (frames[i].*field > 0.0) ran.push_back(&frames[i]);
    if (ran.empty()) return {};
    const auto mid = ran.begin() + static_cast<std::ptrdiff_t>((ran.size() - 1) / 2);
    std::nth_element(
        ran.begin(), mid, ran.end(),
        [field](const StageTimes* a, const StageTimes* b) { return a->*field < b->*field; });
    return **mid;
}

std::string fpsReport(const FrameHistory& history, std::size_t skip) {
    const std::size_t total = history.dropped + history.frames.size();
    const std::size_t n = total > skip ? total - skip : 0;
    const StageTimes m = history.median(skip);
    char line[256];
    std::snprintf(line, sizeof line,
                  "median %.1f fps (%.2f ms: render %.2f, twin %.2f, compare %.2f, upload %.2f, "
                  "draw %.2f, ui %.2f (drawing %.2f), present %.2f, wait %.2f) over %zu frames",
                  m.total > 0.0 ? 1000.0 / m.total : 0.0, m.total, m.render, m.twin, m.compare,
                  m.upload, m.draw, m.ui, m.uiDraw, m.present, m.wait, n);
    return line;
}

}  // namespace facet::view
