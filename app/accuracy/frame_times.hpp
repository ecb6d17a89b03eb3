#pragma once
// Repeated timings and their summary: what `facet bench`, `facet accuracy`, the sweeps and the
// viewer's measurement report for a frame time.

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace facet::app {

/// Median, min and max of the timed frames, in milliseconds.
struct FrameTimes {
    int frames = 0;
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

/// Summarises frame times (any order); an empty list gives frames = 0. The median of an even
/// count is the mean of the middle two.
FrameTimes summarize(std::vector<double> ms);

/// Runs `body` once untimed (scratch buffers, caches), then `frames` times (at least once)
/// timed.
template <class Body>
FrameTimes timeRepeated(int frames, Body&& body) {
    body();
    std::vector<double> ms;
    for (int f = 0; f < std::max(1, frames); ++f) {
        const auto start = std::chrono::steady_clock::now();
        body();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    return summarize(std::move(ms));
}

}  // namespace facet::app
