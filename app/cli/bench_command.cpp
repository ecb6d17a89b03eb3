// `facet bench`: times the engine against the OpenGL twin on a fixed suite (or, with --scaling,
// on a triangle and a pixel sweep), at one thread and at all cores, and prints a table, a CSV
// and a chart. The OpenGL side runs in child processes (app/cli/bench/gl_peer.hpp).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_options.hpp"
#include "bench/bench_suite.hpp"
#include "bench/bench_timing.hpp"
#include "bench/gl_peer.hpp"
#include "bench/gl_peer_process.hpp"
#include "bench_command.hpp"
#include "exit_code.hpp"
#include "facet/image_io.hpp"
#include "report/bench_chart.hpp"
#include "report/bench_csv.hpp"
#include "report/bench_table.hpp"
#include "report/machine_info.hpp"

namespace facet::app {
namespace {

/// One line per measurement on stderr: "[12/160] bunny_1080p phong engine t=2 ... 23.1 ms".
struct Progress {
    int total = 0;
    int done = 0;
    bool open = false;  // a line was begun and not finished

    void begin(const std::string& caseName, const std::string& config, const char* renderer,
               int threads) {
        std::fprintf(stderr, "[%d/%d] %s %s %s t=%d ... ", ++done, total, caseName.c_str(),
                     config.c_str(), renderer, threads);
        open = true;
    }
    void end(const FrameTimes& t) {
        std::fprintf(stderr, "%.3g ms (min %.3g, max %.3g)\n", t.median, t.min, t.max);
        open = false;
    }
    void fail() {
        if (open) std::fprintf(stderr, "failed\n");
        open = false;
    }
};

Measurement measurement(const BenchCase& c, const std::string& config, const char* renderer,
                        int threads, const FrameTimes& t) {
    return {
        c.name,           config, renderer, threads, c.scene.camera.width, c.scene.camera.height,
        triangleCount(c), t,      {}};
}

void measureEngine(const BenchOptions& o, Renderer& renderer, Framebuffer& frame,
                   const BenchCase& c, const BenchConfig& config, int threads, Progress& progress,
                   BenchResults& results) {
    progress.begin(c.name, config.name, kEngine, threads);
    const EngineTimes t = timeEngine(renderer, c, config, threads, framePlan(o), frame);
    progress.end(t.times);
    Measurement m = measurement(c, config.name, kEngine, threads, t.times);
    m.stages = t.stages;
    results.all.push_back(m);
    if (!o.images.empty()) {
        const std::string name =
            c.name + "_" + config.name + "_engine_t" + std::to_string(threads) + ".png";
        if (Status st = writePng(frame, (std::filesystem::path(o.images) / name).string()); !st)
            std::fprintf(stderr, "facet bench: %s\n", st.error().what().c_str());
    }
}

/// The OpenGL peers, one per thread count, while they work; empty once one failed.
struct Peers {
    std::vector<GlPeerProcess> running;
    bool failed = false;

    void fail(BenchResults& results, int threads, const std::string& message) {
        std::fprintf(stderr, "facet bench: OpenGL with LP_NUM_THREADS=%d: %s\n", threads,
                     message.c_str());
        if (results.glRenderer.empty()) results.glRenderer = "unavailable: " + message;
        failed = true;
        running.clear();  // the destructors end them
    }
};

/// Starts a peer per thread count; on failure none runs (message printed).
Peers startPeers(const BenchOptions& o, const std::vector<int>& threads, BenchResults& results) {
    Peers peers;
    for (int t : threads) {
        Result<GlPeerProcess> p = GlPeerProcess::start(o, t);
        if (!p) {
            peers.fail(results, t, p.error().what());
            break;
        }
        results.glRenderer = p->renderer();
        peers.running.push_back(std::move(p).value());
    }
    return peers;
}

/// The peers' measurement of (case, config) at every thread count; stops them all on failure.
void measureOpenGl(const BenchCase& c, const BenchConfig& config, const std::vector<int>& threads,
                   Peers& peers, Progress& progress, BenchResults& results) {
    for (std::size_t i = 0; i < threads.size() && !peers.running.empty(); ++i) {
        progress.begin(c.name, config.name, kOpenGl, threads[i]);
        const Result<FrameTimes> t = peers.running[i].measure(c.name, config.name);
        if (!t) {
            progress.fail();
            peers.fail(results, threads[i], t.error().what());
            return;
        }
        progress.end(t.value());
        results.all.push_back(measurement(c, config.name, kOpenGl, threads[i], t.value()));
    }
}

int runBench(const BenchOptions& o) {
    if (o.peer) return runGlPeer(o);
    const auto start = std::chrono::steady_clock::now();
    const MachineInfo machine = collectMachineInfo();
    // Say at once that the chart will fail, rather than after minutes of measuring.
    Status gnuplot = o.chart.empty() ? Status{} : checkGnuplot(o.gnuplot);
    if (!gnuplot)
        std::fprintf(stderr, "facet bench: warning: %s; the table and CSV will still be written\n",
                     gnuplot.error().what().c_str());
    Result<BenchSuite> built = buildSuite(o);
    if (!built) {
        std::fprintf(stderr, "facet bench: %s\n", built.error().what().c_str());
        return kBadInput;
    }
    const BenchSuite& suite = built.value();
    for (const SkippedCase& s : suite.skipped)
        std::fprintf(stderr, "facet bench: skipping %s: %s\n", s.name.c_str(), s.reason.c_str());
    if (suite.cases.empty() || suite.configs.empty()) {
        std::fprintf(stderr, "facet bench: no %s matches (--cases '%s', --configs '%s')\n",
                     suite.cases.empty() ? "case" : "config", o.cases.c_str(), o.configs.c_str());
        return kBadInput;
    }
    if (!o.images.empty()) std::filesystem::create_directories(o.images);

    std::vector<int> threads = {1};
    if (allCoresThreads(o) > 1) threads.push_back(allCoresThreads(o));
    Progress progress;
    progress.total =
        static_cast<int>(suite.cases.size() * suite.configs.size() * threads.size() * 2);
    BenchResults results;
    for (const BenchCase& c : suite.cases)
        for (Measurement& m : measureFloors(c, framePlan(o).frames)) results.all.push_back(m);
    // Interleaved: each (case, config) is measured by the engine and then by the peers before
    // the next, so a machine whose speed drifts during the run moves both sides of a ratio.
    Peers peers = startPeers(o, threads, results);
    Renderer renderer;
    Framebuffer frame;
    for (const BenchCase& c : suite.cases)
        for (const BenchConfig& config : suite.configs) {
            for (int t : threads)
                measureEngine(o, renderer, frame, c, config, t, progress, results);
            measureOpenGl(c, config, threads, peers, progress, results);
        }
    for (std::size_t i = 0; i < peers.running.size(); ++i)
        if (Status st = peers.running[i].finish(); !st)
            peers.fail(results, threads[i], st.error().what());
    const bool glFailed = peers.failed;

    printBenchTable(stdout, suite, results, threads);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("\n%s on %s (%d cores, load average %s at start), OpenGL: %s; took %.0f s\n",
                machine.date.c_str(), machine.cpu.c_str(), machine.cores, machine.load.c_str(),
                results.glRenderer.c_str(), seconds);
    std::fflush(stdout);

    // Without OpenGL the run did not do what it is for (the comparison): say so in the status,
    // after writing what was measured.
    int code = glFailed ? kFailed : kOk;
    if (!o.csv.empty()) {
        const RunDescription run{
            std::string(o.scaling ? "scaling" : "suite") + (o.quick ? ", quick" : ""), threads,
            framePlan(o)};
        if (Status st = writeBenchCsv(o.csv, machine, run, suite, results); !st) {
            std::fprintf(stderr, "facet bench: %s\n", st.error().what().c_str());
            code = kFailed;
        }
    }
    if (!o.chart.empty()) {
        const ChartRequest req{o.chart, o.gnuplot,
                               "facet bench" + std::string(o.scaling ? " --scaling" : "") + ": " +
                                   machine.cpu + ", " + std::to_string(machine.cores) +
                                   " cores; OpenGL " + results.glRenderer + "; " + machine.date,
                               threads};
        Status st = !gnuplot    ? gnuplot
                    : o.scaling ? writeScalingChart(req, suite, results)
                                : writeSuiteChart(req, suite, results);
        if (!st) {
            std::fprintf(stderr, "facet bench: --chart: %s\n", st.error().what().c_str());
            code = kFailed;
        }
    }
    return code;
}

}  // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Time the engine against the OpenGL twin (llvmpipe) on a fixed suite");
    cmd->add_option("--threads", o->threads,
                    "The 'all cores' thread count, measured besides 1 (0: every core)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    cmd->add_option("--csv", o->csv, "Write every measurement to this CSV file");
    cmd->add_option("--chart", o->chart, "Draw a PNG chart with gnuplot");
    cmd->add_flag("--scaling", o->scaling,
                  "Sweep triangles (1k..1M) and pixels (0.25..8 M) instead of the suite");
    cmd->add_flag("--quick", o->quick, "Tiny generated cases and 2 frames: checks it all runs");
    cmd->add_option("--cases", o->cases, "Only cases whose name matches this regex");
    cmd->add_option("--configs", o->configs,
                    "Only configs matching this regex (painter, gouraud, phong, textured; "
                    "--scaling: gouraud by default)");
    cmd->add_option("--frames", o->frames, "Timed frames per measurement (default 9; quick 2)")
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--warmup", o->warmup, "Untimed frames first (default 2; quick 1)")
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--budget", o->budget,
                    "Seconds of timed frames after which a measurement stops once it has 3 "
                    "(0: always --frames)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--shared", o->shared, "The shared data folder (course scenes, bunny, Spot)");
    cmd->add_option("--images", o->images, "Write the last frame of each measurement here");
    cmd->add_option("--gnuplot", o->gnuplot, "The gnuplot executable")->capture_default_str();
    cmd->footer(std::string("Times per frame (median of the timed frames):\n  engine: ") +
                kEngineTimeIncludes + ".\n  opengl: " + kOpenGlTimeIncludes +
                ".\n  ns/triangle (engine): " + kStageColumnsMean +
                ".\nEach case and config is measured by the engine, then by OpenGL, before the "
                "next.");
    // The OpenGL side re-runs this command in a child process (bench/gl_peer.hpp).
    cmd->add_flag("--peer", o->peer)->group("");
    cmd->callback([o, &exitCode] { exitCode = runBench(*o); });
}

}  // namespace facet::app
