#include "bench_chart.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

extern char** environ;

namespace facet::app {
namespace fs = std::filesystem;

std::string findScript(const std::string& name) {
#ifdef FACET_SCRIPTS_DIR
    if (fs::exists(fs::path(FACET_SCRIPTS_DIR) / name))
        return (fs::path(FACET_SCRIPTS_DIR) / name).string();
#endif
    std::error_code ec;
    const fs::path beside = fs::read_symlink("/proc/self/exe", ec).parent_path() / "scripts" / name;
    return !ec && fs::exists(beside) ? beside.string() : "";
}

std::string gpString(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

namespace {

/// Runs gnuplot with `args` and waits; an Error when it cannot start or fails.
Status runGnuplot(const std::string& gnuplot, const std::vector<std::string>& args, bool quiet) {
    std::vector<std::string> words;
    words.reserve(args.size() + 1);
    words.push_back(gnuplot);
    for (const std::string& a : args) words.push_back(a);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (quiet) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0)
        return Error{{gnuplot, 0},
                     std::string("cannot run gnuplot (") + std::strerror(rc) +
                         "); install it (Debian: apt-get install gnuplot-nox, or "
                         "scripts/setup-debian.sh) or name it with --gnuplot PATH"};
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return Error{{gnuplot, 0}, "gnuplot failed (its messages are above)"};
    return {};
}

/// Writes the data file, runs `script` with the variables, removes the data file.
Status plot(const ChartRequest& req, const std::string& script, const std::string& data,
            std::string variables) {
    const std::string scriptPath = findScript(script);
    if (scriptPath.empty())
        return Error{{script, 0},
                     "chart script not found (expected in the source tree's scripts/)"};
    const fs::path dataPath =
        fs::temp_directory_path() / ("facet_bench_" + std::to_string(::getpid()) + ".dat");
    {
        std::ofstream out(dataPath);
        out << data;
        if (!out) return Error{{dataPath.string(), 0}, "cannot write the chart data"};
    }
    const std::string t1 = "t=" + std::to_string(req.threads.front());
    const std::string tn = req.threads.size() > 1 ? "t=" + std::to_string(req.threads.back()) : "";
    variables += "datafile=" + gpString(dataPath.string()) + "; outfile=" + gpString(req.output) +
                 "; title=" + gpString(req.title) + "; t1=" + gpString(t1) + "; tn=" + gpString(tn);
    Status st = runGnuplot(req.gnuplot, {"-e", variables, scriptPath}, false);
    std::error_code ec;
    fs::remove(dataPath, ec);
    if (st && !fs::exists(req.output))
        return Error{{req.output, 0}, "gnuplot ran but wrote no chart"};
    return st;
}

/// A number for gnuplot: NaN is skipped by its plots.
std::string num(double v) {
    if (std::isnan(v)) return "NaN";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

/// The four medians of a case × config: engine and OpenGL at the first and last thread count.
std::string medians(const BenchResults& r, const std::string& c, const std::string& config,
                    const std::vector<int>& threads) {
    const int t1 = threads.front(), tn = threads.back();
    const bool two = threads.size() > 1;
    const double nan = std::nan("");
    return num(r.median(c, config, kEngine, t1)) + " " + num(r.median(c, config, kOpenGl, t1)) +
           " " + num(two ? r.median(c, config, kEngine, tn) : nan) + " " +
           num(two ? r.median(c, config, kOpenGl, tn) : nan);
}

}  // namespace

Status runGnuplotScript(const std::string& gnuplot, const std::vector<std::string>& args) {
    return runGnuplot(gnuplot, args, false);
}

Status checkGnuplot(const std::string& gnuplot) {
    return runGnuplot(gnuplot, {"--version"}, true);
}

Status writeSuiteChart(const ChartRequest& req, const BenchSuite& suite, const BenchResults& r) {
    std::string data, names;
    for (const BenchConfig& config : suite.configs) {
        names += (names.empty() ? "" : " ") + config.name;
        data += "# " + config.name + ": x case engine_t1 opengl_t1 engine_tn opengl_tn\n";
        int x = 0;
        for (const BenchCase& c : suite.cases)
            data += std::to_string(x++) + " " + c.name + " " +
                    medians(r, c.name, config.name, req.threads) + "\n";
        data += "\n\n";  // two blank lines end a gnuplot index block
    }
    return plot(req, "bench_chart.gp", data, "configs=" + gpString(names) + "; ");
}

Status writeScalingChart(const ChartRequest& req, const BenchSuite& suite, const BenchResults& r) {
    if (suite.configs.empty()) return Error{{req.output, 0}, "no config to chart"};
    for (CaseSeries series : {CaseSeries::Triangles, CaseSeries::Pixels}) {
        bool any = false;
        for (const BenchCase& c : suite.cases) any = any || c.series == series;
        if (!any)
            return Error{{req.output, 0},
                         "the scaling chart needs both sweeps (tri_* and pix_*); --cases left "
                         "one out"};
    }
    const std::string& config = suite.configs.front().name;
    std::string data, trilabel = "triangles", pixlabel = "Mpixels";
    for (CaseSeries series : {CaseSeries::Triangles, CaseSeries::Pixels}) {
        // The slope-1 line goes through the engine's largest point on one thread, the curve
        // that shows the algorithm's growth without the threading overheads.
        double lastX = 0.0, lastMs = std::nan("");
        std::vector<std::pair<double, std::string>> rows;
        for (const BenchCase& c : suite.cases) {
            if (c.series != series) continue;
            const double x = series == CaseSeries::Triangles
                                 ? static_cast<double>(triangleCount(c))
                                 : static_cast<double>(pixelCount(c)) / 1e6;
            rows.emplace_back(x, medians(r, c.name, config, req.threads));
            const double ms = r.median(c.name, config, kEngine, req.threads.front());
            if (x > lastX && !std::isnan(ms)) lastX = x, lastMs = ms;
            const std::string size =
                std::to_string(c.scene.camera.width) + "x" + std::to_string(c.scene.camera.height);
            if (series == CaseSeries::Triangles)
                trilabel = "triangles (UV sphere at " + size + ", " + config + ")";
            else
                pixlabel = "Mpixels (" + std::to_string(triangleCount(c)) +
                           "-triangle sphere, 16:9, " + config + ")";
        }
        data += "# x engine_t1 opengl_t1 engine_tn opengl_tn linear\n";
        for (const auto& [x, row] : rows)
            data += num(x) + " " + row + " " + num(lastMs * x / lastX) + "\n";
        data += "\n\n";
    }
    return plot(req, "bench_scaling_chart.gp", data,
                "trilabel=" + gpString(trilabel) + "; pixlabel=" + gpString(pixlabel) + "; ");
}

}  // namespace facet::app
