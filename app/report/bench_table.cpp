#include "bench_table.hpp"

#include <cmath>
#include <string>

namespace facet::app {
namespace {

/// One thread count's columns: the time cell, Mtri/s and Mpix/s.
constexpr int kTimeWidth = 28;
constexpr int kGroupWidth = kTimeWidth + 2 * 8;

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    return buf;
}

void printCaseHeader(std::FILE* out, const BenchCase& c, const BenchResults& r,
                     const std::vector<int>& threads) {
    std::fprintf(out, "\n== %s: %dx%d (%.2f Mpix), %zu triangles%s%s\n", c.name.c_str(),
                 c.scene.camera.width, c.scene.camera.height,
                 static_cast<double>(pixelCount(c)) / 1e6, triangleCount(c),
                 c.notes.empty() ? "" : "; ", c.notes.c_str());
    std::fprintf(out,
                 "   memory floor (1 thread): fill colour %.3f ms, fill colour+depth %.3f ms, "
                 "copy colour %.3f ms\n",
                 r.median(c.name, "-", kFloorFill, 1), r.median(c.name, "-", kFloorFillDepth, 1),
                 r.median(c.name, "-", kFloorCopy, 1));
    std::fprintf(out, "   %-9s %-13s", "config", "renderer");
    for (int t : threads) {
        const std::string head = "t=" + std::to_string(t) + ": median ms (min..max)";
        std::fprintf(out, " | %-*s%8s%8s", kTimeWidth, head.c_str(), "Mtri/s", "Mpix/s");
    }
    if (threads.size() > 1) std::fprintf(out, " | 1->%-7d", threads.back());
    std::fprintf(out, " | t=%d/floor\n", threads.back());
}

/// The time cell and rates of one measurement, or dashes when it was not measured.
void printTime(std::FILE* out, const Measurement* m) {
    if (!m || m->times.frames == 0) {
        std::fprintf(out, " | %*s%-*s%8s%8s", 9, "-", kTimeWidth - 9, "", "-", "-");
        return;
    }
    const std::string cell =
        format("%9.3f (%.3f..%.3f)", m->times.median, m->times.min, m->times.max);
    std::fprintf(out, " | %-*s%8.2f%8.1f", kTimeWidth, cell.c_str(), megaTrianglesPerSecond(*m),
                 megaPixelsPerSecond(*m));
}

/// A per-triangle cost in ns, or "-" when the engine did not measure it.
std::string nsCell(double ns) {
    return ns == 0.0 ? std::string("-") : format("%.1f", ns);
}

/// The engine's stage costs per triangle at each thread count (kStageColumnsMean).
void printStages(std::FILE* out, const BenchCase& c, const BenchConfig& config,
                 const BenchResults& r, const std::vector<int>& threads) {
    std::fprintf(out, "   %-9s %-13s", "", "ns/triangle");
    for (int t : threads) {
        const Measurement* m = r.find(c.name, config.name, kEngine, t);
        const std::string cell = m ? "front " + nsCell(nsPerTriangle(*m, m->stages.frontEndMs)) +
                                         ", bin " + nsCell(nsPerTriangle(*m, m->stages.binningMs)) +
                                         ", raster rest " + nsCell(rasterRestNsPerTriangle(*m))
                                   : std::string("-");
        std::fprintf(out, " | %-*s", kGroupWidth, cell.c_str());
    }
    std::fprintf(out, "%s |\n", threads.size() > 1 ? " |           " : "");
}

/// Tallies of the targets over the table.
struct Tally {
    int ratioMet = 0, ratioTotal = 0, scaleMet = 0, scaleTotal = 0;
};

void printConfig(std::FILE* out, const BenchCase& c, const BenchConfig& config,
                 const BenchResults& r, const std::vector<int>& threads, Tally& tally) {
    const int tn = threads.back();
    // The scaling target applies to the engine on 1080p and larger frames.
    const bool scalingTarget = pixelCount(c) >= kScalingTargetPixels && threads.size() > 1;
    const double floorMs = r.median(c.name, "-", kFloorFillDepth, 1);
    for (const char* renderer : {kEngine, kOpenGl}) {
        const bool engine = std::string(renderer) == kEngine;
        std::fprintf(out, "   %-9s %-13s", engine ? config.name.c_str() : "", renderer);
        for (int t : threads) printTime(out, r.find(c.name, config.name, renderer, t));
        if (threads.size() > 1) {
            const double s = r.median(c.name, config.name, renderer, 1) /
                             r.median(c.name, config.name, renderer, tn);
            const bool judged = engine && scalingTarget && !std::isnan(s);
            const std::string cell = std::isnan(s) ? "    -" : format("%5.2fx", s);
            std::fprintf(out, " | %-6s %-4s", cell.c_str(),
                         !judged               ? ""
                         : s >= kScalingTarget ? "ok"
                                               : "miss");
            tally.scaleTotal += judged;
            tally.scaleMet += judged && s >= kScalingTarget;
        }
        const double vsFloor = r.median(c.name, config.name, renderer, tn) / floorMs;
        const std::string cell = std::isnan(vsFloor) ? "-" : format("%.0fx", vsFloor);
        std::fprintf(out, " | %9s\n", cell.c_str());
    }
    std::fprintf(out, "   %-9s %-13s", "", "engine/opengl");
    for (int t : threads) {
        const double ratio =
            r.median(c.name, config.name, kEngine, t) / r.median(c.name, config.name, kOpenGl, t);
        const bool judged = !std::isnan(ratio);
        const std::string cell =
            judged ? format("%9.2f", ratio) + (ratio <= kRatioTarget ? " ok" : " miss")
                   : "        -";
        std::fprintf(out, " | %-*s", kGroupWidth, cell.c_str());
        tally.ratioTotal += judged;
        tally.ratioMet += judged && ratio <= kRatioTarget;
    }
    std::fprintf(out, "%s |\n", threads.size() > 1 ? " |           " : "");
    printStages(out, c, config, r, threads);
}

}  // namespace

void printBenchTable(std::FILE* out, const BenchSuite& suite, const BenchResults& r,
                     const std::vector<int>& threads) {
    Tally tally;
    std::fprintf(out,
                 "engine time: %s.\nopengl time: %s.\nns/triangle: %s.\nEngine and opengl are "
                 "measured one after the other for each case and config.\n",
                 kEngineTimeIncludes, kOpenGlTimeIncludes, kStageColumnsMean);
    for (const BenchCase& c : suite.cases) {
        printCaseHeader(out, c, r, threads);
        for (const BenchConfig& config : suite.configs)
            printConfig(out, c, config, r, threads, tally);
    }
    std::fprintf(out,
                 "\ntargets (reported, not asserted): engine <= %.1f x OpenGL: %d of %d met; "
                 "engine 1->%d threads >= %.1fx on 1080p and larger: %d of %d met\n",
                 kRatioTarget, tally.ratioMet, tally.ratioTotal, threads.back(), kScalingTarget,
                 tally.scaleMet, tally.scaleTotal);
    for (const SkippedCase& s : suite.skipped)
        std::fprintf(out, "skipped %s: %s\n", s.name.c_str(), s.reason.c_str());
}

}  // namespace facet::app
