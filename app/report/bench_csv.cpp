#include "bench_csv.hpp"

#include <cstdio>
#include <fstream>

namespace facet::app {
namespace {

std::string joined(const std::vector<int>& v) {
    std::string s;
    for (int x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
    return s;
}

/// A per-triangle cost, blank when the engine did not measure that stage (and off the engine).
std::string nsCell(double ns) {
    if (ns == 0.0) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", ns);
    return buf;
}

std::string row(const Measurement& m) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s,%s,%s,%d,%d,%d,%zu,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%s,%s,%s",
                  m.caseName.c_str(), m.config.c_str(), m.renderer.c_str(), m.threads, m.width,
                  m.height, m.triangles, m.times.frames, m.times.median, m.times.min, m.times.max,
                  megaTrianglesPerSecond(m), megaPixelsPerSecond(m),
                  nsCell(nsPerTriangle(m, m.stages.frontEndMs)).c_str(),
                  nsCell(nsPerTriangle(m, m.stages.binningMs)).c_str(),
                  nsCell(rasterRestNsPerTriangle(m)).c_str());
    return buf;
}

}  // namespace

Status writeBenchCsv(const std::string& path, const MachineInfo& machine, const RunDescription& run,
                     const BenchSuite& suite, const BenchResults& results) {
    std::ofstream out(path);
    if (!out) return Error{{path, 0}, "cannot write the CSV"};
    out << "# facet bench (" << run.mode << ")\n"
        << "# date: " << machine.date << "\n"
        << "# cpu: " << machine.cpu << "\n"
        << "# cores: " << machine.cores << "\n"
        << "# opengl: " << results.glRenderer << "\n"
        << "# compiler: " << machine.compiler << ", " << machine.build << "\n"
        << "# kernel: " << machine.kernel << "\n"
        << "# load average at start: " << machine.load << "\n"
        << "# threads: " << joined(run.threads)
        << " (engine: RenderSettings::threads; opengl: LP_NUM_THREADS, one process each)\n"
        << "# frames: up to " << run.plan.frames << " timed per measurement (stopping after "
        << run.plan.budgetSeconds << " s once " << kMinTimedFrames << " are timed), after up to "
        << run.plan.warmup
        << " warm-up frames (stopping after 1 s); ms per frame, wall clock; engine and opengl "
           "measured one after the other per case and config\n"
        << "# engine time: " << kEngineTimeIncludes << "\n"
        << "# opengl time: " << kOpenGlTimeIncludes << "\n"
        << "# *_ns_per_tri: " << kStageColumnsMean << "\n"
        << "# mpix_per_s counts frame pixels (width x height), not fragments; the floor_* rows "
           "are one-thread memory writes of a frame of that size\n";
    for (const BenchCase& c : suite.cases)
        if (!c.notes.empty()) out << "# case " << c.name << ": " << c.notes << "\n";
    for (const SkippedCase& s : suite.skipped)
        out << "# skipped " << s.name << ": " << s.reason << "\n";
    out << "case,config,renderer,threads,width,height,triangles,frames,median_ms,min_ms,max_ms,"
           "mtri_per_s,mpix_per_s,frontend_ns_per_tri,binning_ns_per_tri,raster_rest_ns_per_tri\n";
    for (const Measurement& m : results.all) out << row(m) << "\n";
    out.close();
    if (!out) return Error{{path, 0}, "cannot write the CSV"};
    return {};
}

}  // namespace facet::app
