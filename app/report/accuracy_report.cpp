#include "accuracy_report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "bench_chart.hpp"

namespace facet::app {
namespace fs = std::filesystem;
namespace {

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

/// The methods of one scene on its Pareto front, fastest first: walking by time, a method is
/// kept when it is more accurate than every faster one.
std::vector<const AccuracyResult*> paretoFront(std::vector<const AccuracyResult*> rows) {
    std::sort(rows.begin(), rows.end(), [](const auto* a, const auto* b) {
        return a->times.median != b->times.median ? a->times.median < b->times.median
                                                  : a->error.rmse < b->error.rmse;
    });
    std::vector<const AccuracyResult*> front;
    for (const AccuracyResult* r : rows) {
        if (front.empty() || r->error.rmse < front.back()->error.rmse) front.push_back(r);
    }
    return front;
}

}  // namespace

std::string accuracyTable(const std::vector<AccuracyResult>& results) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-24s %-9s %-14s %9s %9s %8s %8s %8s %9s\n", "scene", "axis",
                  "method", "ms", "RMSE", "PSNR dB", "max", "% >2LSB", "RMSE in");
    out += line;
    for (const AccuracyResult& r : results) {
        std::snprintf(line, sizeof line, "%-24s %-9s %-14s %9.3f %9.3f %8.2f %8.1f %8.2f %9.3f\n",
                      r.scene.c_str(), r.axis.c_str(), r.method.c_str(), r.times.median,
                      r.error.rmse, r.error.psnr, r.error.maxError, 100.0 * r.error.over2Lsb,
                      r.error.interiorRmse);
        out += line;
    }
    return out;
}

Status writeAccuracyCsv(const std::string& path, const MachineInfo& machine, int samples,
                        const std::vector<AccuracyResult>& results) {
    std::ofstream out(path);
    if (!out) return Error{{path, 0}, "cannot open for writing"};
    out << "# facet accuracy: the engine's time per frame and its error against the ground truth\n"
        << "# date: " << machine.date << "\n"
        << "# cpu: " << machine.cpu << "\n"
        << "# cores: " << machine.cores << "\n"
        << "# compiler: " << machine.compiler << ", " << machine.build << "\n"
        << "# kernel: " << machine.kernel << "\n"
        << "# load average at start: " << machine.load << "\n"
        << "# ground truth: " << samples << "x" << samples
        << " samples per pixel, box filter, Phong, perspective, bilinear level 0\n"
        << "# errors in 8-bit steps (LSB); interior_rmse: over the pixels the ground truth covers "
           "fully\n"
        << "scene,axis,method,width,height,frames,median_ms,min_ms,max_ms,rmse,psnr_db,max_error,"
           "over_2lsb_percent,interior_rmse\n";
    for (const AccuracyResult& r : results) {
        out << r.scene << "," << r.axis << "," << r.method << "," << r.width << "," << r.height
            << "," << r.times.frames << "," << fmt("%.4f", r.times.median) << ","
            << fmt("%.4f", r.times.min) << "," << fmt("%.4f", r.times.max) << ","
            << fmt("%.4f", r.error.rmse) << "," << fmt("%.3f", r.error.psnr) << ","
            << fmt("%.2f", r.error.maxError) << "," << fmt("%.3f", 100.0 * r.error.over2Lsb) << ","
            << fmt("%.4f", r.error.interiorRmse) << "\n";
    }
    out.close();
    if (!out) return Error{{path, 0}, "write failed"};
    return {};
}

Status writeAccuracyChart(const std::string& path, const std::string& gnuplot,
                          const std::string& title, const std::vector<AccuracyResult>& results) {
    std::vector<std::string> scenes;
    std::map<std::string, std::vector<const AccuracyResult*>> byScene;
    for (const AccuracyResult& r : results) {
        if (!byScene.count(r.scene)) scenes.push_back(r.scene);
        byScene[r.scene].push_back(&r);
    }
    // Per scene three data blocks for gnuplot's `index`: every point, the labels, the front.
    // Methods whose points nearly coincide on the chart (within 15 % in time and 3 % of the
    // scene's RMSE range, often the very same image, e.g. perspective and subdivided on a wall
    // whose depth is constant along rows) share one label at the first of them, so no label is
    // printed over another.
    std::string data;
    for (const std::string& s : scenes) {
        const std::vector<const AccuracyResult*>& rows = byScene[s];
        for (const AccuracyResult* r : rows)
            data += fmt("%.6g ", r->times.median) + fmt("%.6g\n", r->error.rmse);
        data += "\n\n";
        double lo = rows.front()->error.rmse, hi = lo;
        for (const AccuracyResult* r : rows) {
            lo = std::min(lo, r->error.rmse);
            hi = std::max(hi, r->error.rmse);
        }
        std::vector<std::pair<const AccuracyResult*, std::string>> labels;
        for (const AccuracyResult* r : rows) {
            auto near = std::find_if(labels.begin(), labels.end(), [&](const auto& l) {
                return std::abs(std::log(r->times.median / l.first->times.median)) < 0.15 &&
                       std::abs(r->error.rmse - l.first->error.rmse) <= 0.03 * (hi - lo);
            });
            if (near == labels.end())
                labels.emplace_back(r, r->method);
            else
                near->second += ", " + r->method;
        }
        for (const auto& [at, text] : labels)
            data += fmt("%.6g ", at->times.median) + fmt("%.6g ", at->error.rmse) + "\"" + text +
                    "\"\n";
        data += "\n\n";
        for (const AccuracyResult* r : paretoFront(byScene[s]))
            data += fmt("%.6g ", r->times.median) + fmt("%.6g\n", r->error.rmse);
        data += "\n\n";
    }
    const std::string stem =
        fs::temp_directory_path() / ("facet_accuracy_" + std::to_string(::getpid()));
    const std::string dataPath = stem + ".dat";
    const std::string scriptPath = stem + ".gp";
    // One panel per scene: their times and errors differ by orders of magnitude.
    const int n = static_cast<int>(scenes.size());
    const int cols = std::min(n, 3);
    const int rows = (n + cols - 1) / cols;
    std::string script = "set terminal pngcairo noenhanced size " + std::to_string(700 * cols) +
                         "," + std::to_string(560 * rows + 40) +
                         " font ',10'\n"
                         "set output outfile\n"
                         "set multiplot layout " +
                         std::to_string(rows) + "," + std::to_string(cols) +
                         " title title\n"
                         "set logscale x\n"
                         "set xlabel 'engine time per frame, median (ms, log scale)'\n"
                         "set ylabel 'RMSE against the ground truth (8-bit steps)'\n"
                         "set key top right\n"
                         "set grid\n"
                         "set offsets graph 0.1, graph 0.45, graph 0.08, graph 0.08\n";
    for (int i = 0; i < n; ++i) {
        const std::string c = std::to_string(i + 1);
        const std::string idx = std::to_string(3 * i);
        script += "set title " + gpString(scenes[i]) + "\n";
        script +=
            "plot datafile index " + idx + " using 1:2 with points pt 7 ps 1.3 lc " + c +
            " title 'method', datafile index " + std::to_string(3 * i + 1) +
            " using 1:2:3 with labels offset 0.8,0.6 left font ',8' notitle, datafile index " +
            std::to_string(3 * i + 2) + " using 1:2 with lines lw 2 lc " + c +
            " title 'Pareto front'\n";
    }
    script += "unset multiplot\n";
    {
        std::ofstream d(dataPath), g(scriptPath);
        d << data;
        g << script;
        if (!d || !g) return Error{{dataPath, 0}, "cannot write the chart data"};
    }
    const std::string vars = "datafile=" + gpString(dataPath) + "; outfile=" + gpString(path) +
                             "; title=" + gpString(title);
    Status st = runGnuplotScript(gnuplot, {"-e", vars, scriptPath});
    std::error_code ec;
    fs::remove(dataPath, ec);
    fs::remove(scriptPath, ec);
    if (st && !fs::exists(path)) return Error{{path, 0}, "gnuplot ran but wrote no chart"};
    return st;
}

}  // namespace facet::app
