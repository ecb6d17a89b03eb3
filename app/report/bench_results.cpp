#include "bench_results.hpp"

#include <algorithm>
#include <limits>

namespace facet::app {

double megaTrianglesPerSecond(const Measurement& m) {
    if (m.times.median <= 0.0) return 0.0;
    return static_cast<double>(m.triangles) / (m.times.median * 1e3);
}

double megaPixelsPerSecond(const Measurement& m) {
    if (m.times.median <= 0.0) return 0.0;
    return static_cast<double>(m.width) * m.height / (m.times.median * 1e3);
}

double nsPerTriangle(const Measurement& m, double ms) {
    return m.triangles > 0 ? ms * 1e6 / static_cast<double>(m.triangles) : 0.0;
}

double rasterRestNsPerTriangle(const Measurement& m) {
    const StageTimes& s = m.stages;
    // Thread time throughout: the front end and binning are summed over threads, so the raster
    // wall time counts once per thread (what is left includes waits at the batch barriers).
    const double threadMs = s.rasterMs * std::max(1, m.threads);
    return s.rasterMs > 0.0 ? nsPerTriangle(m, threadMs - s.frontEndMs - s.binningMs) : 0.0;
}

const Measurement* BenchResults::find(const std::string& caseName, const std::string& config,
                                      const std::string& renderer, int threads) const {
    for (const Measurement& m : all)
        if (m.caseName == caseName && m.config == config && m.renderer == renderer &&
            m.threads == threads)
            return &m;
    return nullptr;
}

double BenchResults::median(const std::string& caseName, const std::string& config,
                            const std::string& renderer, int threads) const {
    const Measurement* m = find(caseName, config, renderer, threads);
    return m && m->times.frames > 0 ? m->times.median : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace facet::app
