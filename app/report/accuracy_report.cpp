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

/// Per result, whether it is on its scene's Pareto front (onParetoFront(), the viewer's rule).
std::vector<bool> paretoMarks(const std::vector<AccuracyResult>& results) {
    std::vector<bool> marks(results.size());
    std::map<std::string, std::vector<std::size_t>> byScene;
    for (std::size_t k = 0; k < results.size(); ++k) byScene[results[k].scene].push_back(k);
    for (const auto& [scene, rows] : byScene) {
        std::vector<ParetoPoint> points;
        for (const std::size_t k : rows)
            points.push_back({results[k].times.median, results[k].error.rmse});
        const std::vector<bool> front = onParetoFront(points);
        for (std::size_t i = 0; i < rows.size(); ++i) marks[rows[i]] = front[i];
    }
    return marks;
}

/// Tics at 1, 2 and 5 times each power of ten between 10^lo and 10^hi, as a gnuplot tic list:
/// a log axis spanning less than two decades otherwise shows one number or none.
std::string logTics(double lo, double hi) {
    std::string list;
    for (int e = static_cast<int>(std::floor(lo)); e <= static_cast<int>(std::ceil(hi)); ++e) {
        for (const double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, e);
            if (std::log10(v) < lo || std::log10(v) > hi) continue;
            list += (list.empty() ? "(" : ", ") + fmt("%g", v);
        }
    }
    return list.empty() ? "autofreq" : list + ")";
}

/// A label's box in graph coordinates (0…1 across the plot area).
struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

}  // namespace

bool machineBusy(const MachineInfo& machine) {
    double load1 = 0.0;
    if (std::sscanf(machine.load.c_str(), "%lf", &load1) != 1) return false;  // unknown
    return load1 > 0.25 * std::max(machine.cores, 1);
}

std::string accuracyTable(const std::vector<AccuracyResult>& results) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-24s %-9s %-14s %9s %9s %8s %8s %8s %9s %s\n", "scene",
                  "axis", "method", "ms", "RMSE", "PSNR dB", "max", "% >2LSB", "RMSE in", "front");
    out += line;
    const std::vector<bool> front = paretoMarks(results);
    for (std::size_t k = 0; k < results.size(); ++k) {
        const AccuracyResult& r = results[k];
        std::snprintf(line, sizeof line,
                      "%-24s %-9s %-14s %9.3f %9.3f %8.2f %8.1f %8.2f %9.3f %s\n", r.scene.c_str(),
                      r.axis.c_str(), r.method.c_str(), r.times.median, r.error.rmse, r.error.psnr,
                      r.error.maxError, 100.0 * r.error.over2Lsb, r.error.interiorRmse,
                      front[k] ? "*" : "");
        out += line;
    }
    out += "front: * on the scene's Pareto front (no other method both faster and more accurate)\n";
    return out;
}

Status writeAccuracyCsv(const std::string& path, const MachineInfo& machine, const AccuracyRun& run,
                        const std::vector<AccuracyResult>& results) {
    std::ofstream out(path);
    if (!out) return Error{{path, 0}, "cannot open for writing"};
    out << "# facet accuracy: the engine's time per frame and its error against the ground truth\n"
        << "# date: " << machine.date << "\n"
        << "# cpu: " << machine.cpu << "\n"
        << "# cores: " << machine.cores << "\n"
        << "# compiler: " << machine.compiler << ", " << machine.build << "\n"
        << "# kernel: " << machine.kernel << "\n"
        << "# load average at start: " << machine.load
        << (machineBusy(machine) ? " (busy: the times are indicative only)" : " (idle)") << "\n"
        << "# ground truth: " << run.samples << "x" << run.samples
        << " samples per pixel, box filter, Phong, perspective, bilinear level 0\n"
        << "# timed frames per method: " << run.frames << " after " << run.warmup
        << " untimed, round-robin"
        << (run.quick ? "; --quick (a smoke run, not for publishing)" : "") << "\n";
    if (!run.leftOut.empty())
        out << "# not measured (as many samples per pixel as the truth or more): " << run.leftOut
            << "\n";
    out << "# errors in 8-bit steps (LSB); interior_rmse: over the pixels the ground truth covers "
           "fully\n"
        << "scene,axis,method,width,height,frames,median_ms,min_ms,max_ms,rmse,psnr_db,max_error,"
           "over_2lsb_percent,interior_rmse,pareto\n";
    const std::vector<bool> front = paretoMarks(results);
    for (std::size_t k = 0; k < results.size(); ++k) {
        const AccuracyResult& r = results[k];
        out << r.scene << "," << r.axis << "," << r.method << "," << r.width << "," << r.height
            << "," << r.times.frames << "," << fmt("%.4f", r.times.median) << ","
            << fmt("%.4f", r.times.min) << "," << fmt("%.4f", r.times.max) << ","
            << fmt("%.4f", r.error.rmse) << "," << fmt("%.3f", r.error.psnr) << ","
            << fmt("%.2f", r.error.maxError) << "," << fmt("%.3f", 100.0 * r.error.over2Lsb) << ","
            << fmt("%.4f", r.error.interiorRmse) << "," << (front[k] ? 1 : 0) << "\n";
    }
    out.close();
    if (!out) return Error{{path, 0}, "write failed"};
    return {};
}

Status writeAccuracyChart(const std::string& path, const std::string& gnuplot,
                          const std::string& title, const std::vector<AccuracyResult>& results) {
    std::vector<std::string> scenes;
    std::map<std::string, std::vector<std::size_t>> byScene;
    for (std::size_t k = 0; k < results.size(); ++k) {
        if (!byScene.count(results[k].scene)) scenes.push_back(results[k].scene);
        byScene[results[k].scene].push_back(k);
    }
    const std::vector<bool> front = paretoMarks(results);
    // Both axes logarithmic: times and errors each span orders of magnitude (Gouraud's 40 LSB
    // beside supersampling's 0.2), and a log axis cannot run below zero. An error of 0 (a
    // method that draws the truth's image) is drawn at the axis' floor.
    constexpr double kFloor = 1e-3;
    const auto err = [&](std::size_t k) { return std::max(results[k].error.rmse, kFloor); };
    // A time is never 0 (a clock tick at least), but a log axis must not meet one.
    const auto ms = [&](std::size_t k) { return std::max(results[k].times.median, 1e-6); };
    // Label placement in graph coordinates (0…1 over the plot area) of a 760×560 panel with an
    // 8-point font: about this wide per character and this tall per line.
    constexpr double kCharWidth = 0.0085, kLineHeight = 0.034, kGap = 0.012, kKeyBand = 0.07;

    // Per scene two data blocks for gnuplot's `index`: the points (front marked), the front.
    // Labels and their leader lines are `set label` / `set arrow` commands per panel.
    std::string data;
    std::vector<std::string> panelSetup;
    for (const std::string& s : scenes) {
        const std::vector<std::size_t>& rows = byScene[s];
        double tLo = ms(rows[0]), tHi = tLo, eLo = err(rows[0]), eHi = eLo;
        for (const std::size_t k : rows) {
            tLo = std::min(tLo, ms(k));
            tHi = std::max(tHi, ms(k));
            eLo = std::min(eLo, err(k));
            eHi = std::max(eHi, err(k));
        }
        // Ranges with room around the points (and on the right for their labels).
        const double x0 = std::log10(tLo) - 0.3, x1 = std::log10(tHi) + 0.7;
        // Room above the highest point for the key, a band no point or label enters.
        const double y0 = std::log10(eLo) - 0.25, y1 = std::log10(eHi) + 0.45;
        const auto gx = [&](double t) { return (std::log10(t) - x0) / (x1 - x0); };
        const auto gy = [&](double e) { return (std::log10(e) - y0) / (y1 - y0); };
        std::string setup =
            fmt("set xrange [%.6g:", std::pow(10.0, x0)) + fmt("%.6g]\n", std::pow(10.0, x1)) +
            fmt("set yrange [%.6g:", std::pow(10.0, y0)) + fmt("%.6g]\n", std::pow(10.0, y1)) +
            "set xtics " + logTics(x0, x1) + "\nset ytics " + logTics(y0, y1) + "\n";

        for (const std::size_t k : rows)
            data += fmt("%.6g ", ms(k)) + fmt("%.6g ", err(k)) + (front[k] ? "1\n" : "0\n");
        data += "\n\n";
        std::vector<std::size_t> frontRows;
        for (const std::size_t k : rows)
            if (front[k]) frontRows.push_back(k);
        std::sort(frontRows.begin(), frontRows.end(),
                  [&](std::size_t a, std::size_t b) { return ms(a) < ms(b); });
        for (const std::size_t k : frontRows) data += fmt("%.6g ", ms(k)) + fmt("%.6g\n", err(k));
        data += "\n\n";

        // Methods whose points coincide on the chart (within 1 % of its width and height: often
        // the very same image, e.g. perspective, phong and 1x1, which are the base settings)
        // share one label.
        struct Label {
            std::size_t at;
            std::string text;
        };
        std::vector<Label> labels;
        for (const std::size_t k : rows) {
            auto near = std::find_if(labels.begin(), labels.end(), [&](const Label& l) {
                return std::abs(gx(ms(k)) - gx(ms(l.at))) < 0.01 &&
                       std::abs(gy(err(k)) - gy(err(l.at))) < 0.01;
            });
            if (near == labels.end())
                labels.push_back({k, results[k].method});
            else
                near->text += ", " + results[k].method;
        }
        // Placed top to bottom, each beside its point when that is free, else at the nearest
        // free height within reach, right of the point or else left of it, with a leader line
        // from the point when it had to move: no label covers another, a point or the key.
        std::sort(labels.begin(), labels.end(),
                  [&](const Label& a, const Label& b) { return err(a.at) > err(b.at); });
        std::vector<Box> taken = {{0.0, 1.0 - kKeyBand, 1.0, 1.0}};
        for (const std::size_t k : rows) {
            const double px = gx(ms(k)), py = gy(err(k));
            taken.push_back({px - 0.008, py - 0.012, px + 0.008, py + 0.012});
        }
        int tag = 0;
        for (const Label& l : labels) {
            const double px = gx(ms(l.at)), py = gy(err(l.at));
            const double w = kCharWidth * static_cast<double>(l.text.size());
            Box placed{};
            bool found = false, left = false;
            for (int step = 0; step < 40 && !found; ++step) {
                // 0, -1, +1, -2, +2... lines from the point's height
                const double dy =
                    (step % 2 == 1 ? -1.0 : 1.0) * ((step + 1) / 2) * 0.5 * kLineHeight;
                for (const bool onLeft : {false, true}) {
                    const double y = py + dy;
                    const double xa = onLeft ? px - kGap - w : px + kGap;
                    const Box b{xa, y - 0.5 * kLineHeight, xa + w, y + 0.5 * kLineHeight};
                    if (b.x0 < 0.0 || b.x1 > 1.0 || b.y0 < 0.0 || b.y1 > 1.0) continue;
                    if (std::any_of(taken.begin(), taken.end(),
                                    [&](const Box& t) { return t.overlaps(b); }))
                        continue;
                    placed = b;
                    left = onLeft;
                    found = true;
                    break;
                }
            }
            if (!found)
                placed = {px + kGap, py - 0.5 * kLineHeight, px + kGap + w,
                          py + 0.5 * kLineHeight};  // nowhere free: beside the point
            // Kept a character and a half clear of the next label, so two labels side by
            // side do not read as one.
            taken.push_back(
                {placed.x0 - 1.5 * kCharWidth, placed.y0, placed.x1 + 1.5 * kCharWidth, placed.y1});
            const double ly = 0.5 * (placed.y0 + placed.y1);
            const double lx = left ? placed.x1 : placed.x0;
            setup += "set label " + std::to_string(++tag) + " " + gpString(l.text) +
                     fmt(" at graph %.4f,", lx) + fmt(" graph %.4f ", ly) +
                     (left ? "right" : "left") + " font ',8' front\n";
            if (std::abs(ly - py) > 0.3 * kLineHeight)
                setup += "set arrow " + std::to_string(tag) + fmt(" from first %.6g,", ms(l.at)) +
                         fmt(" first %.6g", err(l.at)) +
                         fmt(" to graph %.4f,", left ? lx + 0.004 : lx - 0.004) +
                         fmt(" graph %.4f nohead lc rgb '#555555' lw 1\n", ly);
        }
        panelSetup.push_back(setup);
    }
    const std::string stem =
        fs::temp_directory_path() / ("facet_accuracy_" + std::to_string(::getpid()));
    const std::string dataPath = stem + ".dat";
    const std::string scriptPath = stem + ".gp";
    // One panel per scene: their times and errors differ by orders of magnitude.
    const int n = static_cast<int>(scenes.size());
    const int cols = std::min(n, 3);
    const int rows = (n + cols - 1) / cols;
    std::string script = "set terminal pngcairo noenhanced size " + std::to_string(760 * cols) +
                         "," + std::to_string(560 * rows + 50) +
                         " font ',10'\n"
                         "set output outfile\n"
                         "set multiplot layout " +
                         std::to_string(rows) + "," + std::to_string(cols) +
                         " title title\n"
                         "set logscale xy\n"
                         "set xlabel 'engine time per frame, median (ms, log scale)'\n"
                         "set ylabel 'RMSE against the ground truth (8-bit steps, log scale)'\n"
                         "set key top center horizontal\n"
                         "set grid\n";
    // Dark colours that read on white (gnuplot's sixth default is a pale yellow).
    const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b",
                                   "#e377c2", "#7f7f7f", "#17becf", "#bcbd22"};
    for (int i = 0; i < n; ++i) {
        const std::string c = std::string("rgb '") + colours[i % 9] + "'";
        script += "unset label\nunset arrow\n" + panelSetup[static_cast<std::size_t>(i)];
        script += "set title " + gpString(scenes[static_cast<std::size_t>(i)]) + "\n";
        script += "plot datafile index " + std::to_string(2 * i + 1) +
                  " using 1:2 with lines lw 2 lc " + c + " title 'Pareto front', datafile index " +
                  std::to_string(2 * i) +
                  " using 1:($3 > 0 ? $2 : 1/0) with points pt 7 ps 1.3 lc " + c +
                  " title 'on the front', datafile index " + std::to_string(2 * i) +
                  " using 1:($3 > 0 ? 1/0 : $2) with points pt 6 ps 1.3 lc " + c +
                  " title 'beaten (off the front)'\n";
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
