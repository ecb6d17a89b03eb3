#pragma once
// What `facet bench` measures: the cases (a scene at a size) and the configs (settings), after
// the --cases / --configs filters. The engine side and the OpenGL peer build the same suite from
// the same options, so a (case, config) name pair identifies a measurement in both processes.

#include <cstddef>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "facet/error.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::app {

/// Which chart a case belongs to: the main suite, or one of the two --scaling sweeps.
enum class CaseSeries { Suite, Triangles, Pixels };

/// A scene ready to draw in every config.
struct BenchCase {
    std::string name;   ///< e.g. "bunny_1080p"
    std::string notes;  ///< what was generated or added, e.g. "planar uvs, checker texture"
    CaseSeries series = CaseSeries::Suite;
    Scene scene;
};

/// One way of drawing a case.
struct BenchConfig {
    std::string name;  ///< "painter", "gouraud", "phong", "textured"
    RenderSettings settings;
};

/// A case that was selected but could not be built (missing shared data).
struct SkippedCase {
    std::string name;
    std::string reason;
};

/// The cases and configs of one run.
struct BenchSuite {
    std::vector<BenchCase> cases;
    std::vector<BenchConfig> configs;
    std::vector<SkippedCase> skipped;
};

/// Builds the suite the options select (scaling sweeps with --scaling, tiny generated cases with
/// --quick). An invalid regex returns an Error naming the option.
Result<BenchSuite> buildSuite(const BenchOptions& options);

/// Triangles a case submits per frame.
std::size_t triangleCount(const BenchCase& c);

/// Pixels of a case's frame.
std::size_t pixelCount(const BenchCase& c);

}  // namespace facet::app
