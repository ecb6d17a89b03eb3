#pragma once
// The options of `facet bench` as the user typed them. The OpenGL peer process receives the
// selecting ones again on its command line (gl_peer.cpp), so both sides build the same suite.

#include <string>

namespace facet::app {

/// `facet bench` options; empty strings mean "not given".
struct BenchOptions {
    int threads = 0;      ///< the "all cores" thread count; <= 0: hardware concurrency
    std::string csv;      ///< CSV output path
    std::string chart;    ///< PNG chart output path
    std::string cases;    ///< ECMAScript regex searched in case names
    std::string configs;  ///< ECMAScript regex searched in config names
    std::string shared;   ///< the shared data folder (course scenes, bunny, Spot)
    std::string images;   ///< folder for the last frame of each measurement (sanity check)
    std::string gnuplot = "gnuplot";  ///< the gnuplot executable
    int frames = 0;                   ///< timed frames per measurement; 0: the mode's default
    int warmup = -1;                  ///< untimed frames first; < 0: the mode's default
    double budget = 5.0;   ///< seconds of timed frames after which a measurement may stop
    bool scaling = false;  ///< the triangle and pixel sweeps instead of the suite
    bool quick = false;    ///< tiny sizes, few frames, generated cases only
    bool peer = false;     ///< hidden: be the OpenGL side, results on stdout
};

/// How many frames one measurement draws.
struct FramePlan {
    int warmup = 2;  ///< untimed frames first (fewer once they took over a second in all)
    int frames = 9;  ///< timed frames at most
    /// Timing stops early once kMinTimedFrames frames took this many seconds in all, so the
    /// slowest cases do not dominate the run; <= 0: always `frames`.
    double budgetSeconds = 5.0;
};

/// The fewest timed frames a measurement keeps when the budget cuts it short.
inline constexpr int kMinTimedFrames = 3;

/// The plan once the defaults are applied (--quick: 1 warm-up, 2 frames).
FramePlan framePlan(const BenchOptions& options);

/// The shared data folder: --shared, else the one beside the source tree, else ../shared.
std::string sharedDir(const BenchOptions& options);

/// The "all cores" thread count: --threads, else the hardware concurrency (at least 1).
int allCoresThreads(const BenchOptions& options);

}  // namespace facet::app
