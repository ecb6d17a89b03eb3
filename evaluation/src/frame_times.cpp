// Frame-time summaries (frame_times.hpp).

#include "facet/evaluation/frame_times.hpp"

#include <cstddef>

namespace facet {

double medianOf(std::vector<double> values) {
    if (values.empty()) return 0.0;
    // nth_element, not a sort: the viewer takes medians of every stage each frame.
    const std::size_t mid = values.size() / 2;
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(mid);
    std::nth_element(values.begin(), at, values.end());
    if (values.size() % 2) return *at;
    const double lower = *std::max_element(values.begin(), at);
    return 0.5 * (lower + *at);
}

FrameTimes summarize(std::vector<double> ms) {
    FrameTimes t;
    if (ms.empty()) return t;
    const auto [lo, hi] = std::minmax_element(ms.begin(), ms.end());
    t.frames = static_cast<int>(ms.size());
    t.min = *lo;
    t.max = *hi;
    t.median = medianOf(std::move(ms));
    return t;
}

}  // namespace facet
