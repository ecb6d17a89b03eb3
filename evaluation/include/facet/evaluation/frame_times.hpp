#pragma once
// Repeated timings and their summary: what `facet render --frames`, `facet bench`, `facet
// accuracy`, the sweeps and the viewer (its Stats panel, its accuracy job) report for a time.

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace facet {

/// Median, min and max of the timed frames, in milliseconds.
struct FrameTimes {
    int frames = 0;       ///< frames timed; 0: none, every time below is 0
    double median = 0.0;  ///< of an even count, the mean of the middle two
    double min = 0.0;     ///< fastest frame
    double max = 0.0;     ///< slowest frame

    /// Field by field (a report measured once compares equal to itself).
    bool operator==(const FrameTimes&) const = default;
};

/// The median of `values` (any order), the mean of the middle two for an even count; 0 when
/// empty.
double medianOf(std::vector<double> values);

/// Summarises frame times (any order); an empty list gives frames = 0.
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

}  // namespace facet
