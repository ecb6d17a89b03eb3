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

/// Medians over the timed frames of the engine's stage times (RenderStats), in ms per frame:
/// the front end and binning summed over threads, raster (with them) the wall clock; 0 where
/// the engine does not split them out, and for the other renderers.
struct StageTimes {
    double frontEndMs = 0.0, binningMs = 0.0, rasterMs = 0.0;
};

/// What a timed frame includes, per renderer, for the table, the CSV and --help.
inline constexpr const char* kEngineTimeIncludes =
    "everything Renderer::render does per frame: clear, vertex transform, the check that the "
    "mesh's vertex normals are still current (a hash of the mesh), Gouraud lighting, front end, "
    "binning, raster and shading, MSAA resolve, into a frame in memory";
inline constexpr const char* kOpenGlTimeIncludes =
    "clear and draw up to glFinish, the mesh resident (uploaded once per case and config, "
    "untimed, with the vertex normals lit configs need); no readback";
inline constexpr const char* kStageColumnsMean =
    "engine CPU time per submitted triangle of the front end (reject, clip, snap, cull, set-up) "
    "and of binning, summed over threads, and of the rest of raster (raster wall time times "
    "the threads, minus both: tiles, shading and waits at barriers); blank where the engine does "
    "not report a stage";

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
    StageTimes stages;  ///< the engine's; zeros otherwise
};

/// Millions of submitted triangles per second at the median time.
double megaTrianglesPerSecond(const Measurement& m);

/// Millions of frame pixels (width × height, not fragments) per second at the median time.
double megaPixelsPerSecond(const Measurement& m);

/// Nanoseconds per submitted triangle of `ms` per frame; 0 without triangles.
double nsPerTriangle(const Measurement& m, double ms);

/// The rest of raster per triangle: raster minus the front end and binning (which are part of
/// it), in ns; 0 when the engine reported no raster time.
double rasterRestNsPerTriangle(const Measurement& m);

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
