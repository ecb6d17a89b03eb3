// `facet sweeps`: the stability sweeps of issue 6 as data and charts. Each sweep measures one
// way a method fails (view angle, highlights, depth precision, sub-pixel precision, extreme
// triangles, camera paths), writes <out>/<name>.csv and draws <out>/<name>.png with its
// committed gnuplot script (scripts/sweep_<name>.gp). The tests assert bounds on the same
// functions' results, so the charts show what the tests pin down.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "accuracy/sweep_camera.hpp"
#include "accuracy/sweep_depth.hpp"
#include "accuracy/sweep_extreme.hpp"
#include "accuracy/sweep_highlights.hpp"
#include "accuracy/sweep_subpixel.hpp"
#include "accuracy/sweep_table.hpp"
#include "accuracy/sweep_view_angle.hpp"
#include "commands.hpp"
#include "report/bench_chart.hpp"
#include "report/machine_info.hpp"

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
    std::string out = "docs/sweeps";
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
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec || !fs::is_directory(o.out)) {
        std::fprintf(stderr, "%s: cannot create the output folder (%s)\n", o.out.c_str(),
                     ec.message().c_str());
        return kBadInput;
    }
    const MachineInfo machine = collectMachineInfo();
    SweepOptions so;
    so.shared = o.shared;
    so.quick = o.quick;
    so.samples = o.samples;
    so.frames = o.frames;
    const bool interactive = isatty(STDERR_FILENO) != 0;
    int code = kOk;
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
        const Sweep& sweep = sweeps[k];
        const auto start = std::chrono::steady_clock::now();
        int step = 0;
        // On a terminal each step overwrites the line; in a log only the summary is kept.
        so.progress = [&](const std::string& line) {
            ++step;
            if (!interactive) return;
            std::fprintf(stderr, "\r[%zu/%zu] %-70.70s", k + 1, sweeps.size(), line.c_str());
            std::fflush(stderr);
        };
        const SweepTable table = sweep.run(so);
        std::fprintf(stderr, "%s[%zu/%zu] %s: %d steps, %zu rows in %.1f s%s\n",
                     interactive ? "\r" : "", k + 1, sweeps.size(), sweep.name, step,
                     table.rows.size(), secondsSince(start),
                     interactive ? "                                        " : "");
        const std::string csv = (fs::path(o.out) / (table.name + ".csv")).string();
        const std::vector<std::string> notes = {
            "facet sweeps: " + table.title,
            machine.date + "; " + machine.cpu + ", " + std::to_string(machine.cores) + " cores; " +
                machine.compiler,
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
        const std::string png = (fs::path(o.out) / (table.name + ".png")).string();
        const std::string title = table.title + " (" + machine.cpu + ", " + machine.date + ")";
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
    cmd->add_option("--out", o->out, "Folder for the CSV and PNG files")->capture_default_str();
    cmd->add_option("--only", o->only, "Run only these sweeps (names as the files are named)")
        ->delimiter(',');
    cmd->add_option("--shared", o->shared, "The shared data folder (meshes, brick.jpg)")
        ->capture_default_str();
    cmd->add_flag("--quick", o->quick, "Fewer, smaller steps (a smoke run)");
    cmd->add_flag("--no-chart", o->noChart, "Write the CSV files only");
    cmd->add_option("--samples", o->samples, "Ground-truth samples per pixel axis (N×N)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    cmd->add_option("--frames", o->frames, "Timed frames per point (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--gnuplot", o->gnuplot, "The gnuplot executable")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runSweeps(*o); });
}

}  // namespace facet::app
