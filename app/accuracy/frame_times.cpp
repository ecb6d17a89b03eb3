#include "frame_times.hpp"

namespace facet::app {

FrameTimes summarize(std::vector<double> ms) {
    FrameTimes t;
    if (ms.empty()) return t;
    std::sort(ms.begin(), ms.end());
    const std::size_t n = ms.size();
    t.frames = static_cast<int>(n);
    t.median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    t.min = ms.front();
    t.max = ms.back();
    return t;
}

}  // namespace facet::app
