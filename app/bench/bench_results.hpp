#pragma once
// What a benchmark run measured: one record per case × config × renderer × threads, in plain
// structs the table, the CSV and the charts all read.

#include <cstddef>
#include <string>
#include <vector>

#include "facet/evaluation/frame_times.hpp"

namespace facet::app {

/// Renderer names as they appear in the CSV.
inline constexpr const char* kEngine = "engine";
inline constexpr const char* kOpenGl = "opengl";
inline constexpr const char* kFloorFill = "floor_fill_color";             ///< fill the colour plane
inline constexpr const char* kFloorFillDepth = "floor_fill_color_depth";  ///< colour + depth
inline constexpr const char* kFloorCopy = "floor_copy_color";  ///< memcpy of the colour plane

/// One measurement.
struct Measurement {
    std::string caseName;
    std::string config;    ///< "-" for the floors
    std::string renderer;  ///< kEngine, kOpenGl or a floor
    int threads = 1;       ///< engine: RenderSettings::threads; OpenGL: LP_NUM_THREADS
    int width = 0;
    int height = 0;
    std::size_t triangles = 0;
    FrameTimes times;
};

/// Millions of submitted triangles per second at the median time.
double megaTrianglesPerSecond(const Measurement& m);

/// Millions of frame pixels (width × height, not fragments) per second at the median time.
double megaPixelsPerSecond(const Measurement& m);

/// Every measurement of a run, in the order taken.
struct BenchResults {
    std::vector<Measurement> all;
    std::string glRenderer;  ///< the peer's renderer string, or why OpenGL was unavailable

    /// The measurement with these keys, or null.
    const Measurement* find(const std::string& caseName, const std::string& config,
                            const std::string& renderer, int threads) const;
    /// Its median, or NaN when it was not measured.
    double median(const std::string& caseName, const std::string& config,
                  const std::string& renderer, int threads) const;
};

}  // namespace facet::app
