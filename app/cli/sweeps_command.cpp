// `facet sweeps`: the stability sweeps of issue 6 as data and charts. Each sweep measures one
// way a method fails (view angle, highlights, depth precision, sub-pixel precision, extreme
// triangles, camera paths), writes <out>/<name>.csv (out: a new folder unless named) and draws
// <out>/<name>.png with its committed gnuplot script (scripts/sweep_<name>.gp). The tests assert
// bounds on the same functions' results, so the charts show what the tests pin down.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "accuracy/run_output.hpp"
#include "accuracy/sweep_camera.hpp"
#include "accuracy/sweep_depth.hpp"
#include "accuracy/sweep_extreme.hpp"
#include "accuracy/sweep_highlights.hpp"
#include "accuracy/sweep_subpixel.hpp"
#include "accuracy/sweep_table.hpp"
#include "accuracy/sweep_view_angle.hpp"
#include "exit_code.hpp"
#include "report/accuracy_report.hpp"
#include "report/bench_chart.hpp"
#include "report/machine_info.hpp"
#include "sweeps_command.hpp"

namespace facet::app {
namespace {

namespace fs = std::filesystem;

/// A sweep by name: runs it and returns its table.
struct Sweep {
    const char* name;
    std::function<SweepTable(const SweepOptions&)> run;
};

std::vector<Sweep> allSweeps() {
    return {
        {"view_angle", [](const SweepOptions& o) { return viewAngleTable(sweepViewAngle(o)); }},
        {"highlights", [](const SweepOptions& o) { return highlightsTable(sweepHighlights(o)); }},
        {"depth", [](const SweepOptions& o) { return depthTable(sweepDepth(o)); }},
        {"subpixel", [](const SweepOptions& o) { return subPixelTable(sweepSubPixel(o)); }},
        {"extreme", [](const SweepOptions& o) { return extremeTable(sweepExtreme(o)); }},
        {"camera_paths", [](const SweepOptions& o) { return cameraTable(sweepCameraPaths(o)); }},
    };
}

struct SweepsOptions {
    std::string out;  ///< the folder; empty: a new one in the current folder
    std::vector<std::string> only;
    std::string shared = FACET_SHARED_DIR;
    std::string gnuplot = "gnuplot";
    bool quick = false;
    bool noChart = false;
    int samples = 8;
    int frames = 5;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int runSweeps(const SweepsOptions& o) {
    std::vector<Sweep> sweeps;
    for (Sweep& s : allSweeps()) {
        bool wanted = o.only.empty();
        for (const std::string& n : o.only) wanted = wanted || n == s.name;
        if (wanted) sweeps.push_back(std::move(s));
    }
    for (const std::string& n : o.only) {
        bool known = false;
        for (const Sweep& s : allSweeps()) known = known || n == s.name;
        if (!known) {
            std::string names;
            for (const Sweep& s : allSweeps())
                names += std::string(names.empty() ? "" : ", ") + s.name;
            std::fprintf(stderr, "--only: no sweep named '%s' (there are: %s)\n", n.c_str(),
                         names.c_str());
            return kBadInput;
        }
    }
    if (!o.noChart) {
        if (Status st = checkGnuplot(o.gnuplot); !st) {
            std::fprintf(stderr, "%s\n(--no-chart writes the CSV files only)\n",
                         st.error().what().c_str());
            return kBadInput;
        }
    }
    const Result<std::string> folder = prepareOutputFolder(o.out, "facet-sweeps");
    if (!folder) {
        std::fprintf(stderr, "%s\n", folder.error().what().c_str());
        return kBadInput;
    }
    const fs::path out(folder.value());
    const MachineInfo machine = collectMachineInfo();
    SweepOptions so;
    so.shared = o.shared;
    so.quick = o.quick;
    so.samples = o.samples;
    so.frames = o.frames;
    const bool busy = machineBusy(machine);
    if (busy)
        std::fprintf(stderr,
                     "sweeps: warning: load average %s on %d cores: the times will be those of a "
                     "busy machine (the CSV and charts say so)\n",
                     machine.load.c_str(), machine.cores);
    std::fprintf(stderr, "sweeps: %zu sweep%s%s, writing to %s\n", sweeps.size(),
                 sweeps.size() == 1 ? "" : "s", o.quick ? " (quick)" : "", out.c_str());
    ProgressLine progress;
    int code = kOk;
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
        const Sweep& sweep = sweeps[k];
        const auto start = std::chrono::steady_clock::now();
        int step = 0;
        // Every step on a terminal; in a log the first of each sweep and one every few seconds.
        so.progress = [&](const std::string& line) {
            ++step;
            char head[64];
            std::snprintf(head, sizeof head, "[%zu/%zu] step %d (%.0f s): ", k + 1, sweeps.size(),
                          step, secondsSince(start));
            progress.update(head + line, step == 1);
        };
        const SweepTable table = sweep.run(so);
        char summary[160];
        std::snprintf(summary, sizeof summary, "[%zu/%zu] %s: %d steps, %zu rows in %.1f s", k + 1,
                      sweeps.size(), sweep.name, step, table.rows.size(), secondsSince(start));
        progress.finish(summary);
        const std::string csv = (out / (table.name + ".csv")).string();
        const std::vector<std::string> notes = {
            "facet sweeps: " + table.title,
            machine.date + "; " + machine.cpu + ", " + std::to_string(machine.cores) + " cores; " +
                machine.compiler + "; load average at start " + machine.load +
                (busy ? " (busy: times indicative only)" : " (idle)"),
            "ground truth " + std::to_string(o.samples) + "x" + std::to_string(o.samples) +
                " samples; " + std::to_string(o.frames) + " timed frames per point" +
                (o.quick ? "; quick" : "")};
        if (Status st = writeSweepCsv(csv, table, notes); !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            code = kFailed;
            continue;
        }
        std::printf("%s\n", csv.c_str());
        if (o.noChart) continue;
        const std::string script = findScript("sweep_" + table.name + ".gp");
        if (script.empty()) {
            std::fprintf(stderr, "sweep_%s.gp: chart script not found (expected in scripts/)\n",
                         table.name.c_str());
            code = kFailed;
            continue;
        }
        const std::string png = (out / (table.name + ".png")).string();
        const std::string title = table.title + " (" + machine.cpu + ", load average " +
                                  machine.load + " at start" + (busy ? ", BUSY" : "") + ", " +
                                  machine.date + ")";
        if (Status st = runGnuplotScript(
                o.gnuplot, {"-e",
                            "datafile=" + gpString(csv) + "; outfile=" + gpString(png) +
                                "; title=" + gpString(title),
                            script});
            !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            code = kFailed;
            continue;
        }
        std::printf("%s\n", png.c_str());
    }
    return code;
}

}  // namespace

void addSweepsCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<SweepsOptions>();
    CLI::App* cmd = app.add_subcommand(
        "sweeps",
        "Run the stability sweeps (where each method fails) and chart them: one CSV and one PNG "
        "per sweep");
    cmd->add_option("-o,--out", o->out,
                    "Folder for the CSV and PNG files (made if missing; files of the same names "
                    "in it are replaced). Default: a new facet-sweeps-DATE-TIME folder here");
    cmd->add_option("--only", o->only, "Run only these sweeps (names as the files are named)")
        ->delimiter(',');
    cmd->add_option("--shared", o->shared, "The shared data folder (meshes, brick.jpg)")
        ->capture_default_str();
    auto* quick = cmd->add_flag(
        "--quick", o->quick,
        "Fewer, smaller steps, a 2x2 truth and 1 timed frame (unless given): a smoke run of "
        "seconds");
    cmd->add_flag("--no-chart", o->noChart, "Write the CSV files only");
    auto* samples =
        cmd->add_option("--samples", o->samples, "Ground-truth samples per pixel axis (N×N)")
            ->check(CLI::Range(1, 16))
            ->capture_default_str();
    auto* frames = cmd->add_option("--frames", o->frames, "Timed frames per point (median)")
                       ->check(CLI::Range(1, 1000))
                       ->capture_default_str();
    cmd->add_option("--gnuplot", o->gnuplot, "The gnuplot executable")->capture_default_str();
    cmd->callback([o, &exitCode, quick, samples, frames] {
        SweepsOptions run = *o;
        if (quick->count() > 0) {
            if (samples->count() == 0) run.samples = 2;
            if (frames->count() == 0) run.frames = 1;
        }
        exitCode = runSweeps(run);
    });
}

}  // namespace facet::app
