#pragma once
// The charts, drawn by gnuplot: the data is written to a temporary file in the layout the
// committed scripts (scripts/bench_chart.gp, scripts/bench_scaling_chart.gp) read, and gnuplot
// runs them. Without gnuplot a chart is an Error that says what to install.

#include <string>
#include <vector>

#include "bench_results.hpp"
#include "cli/bench/bench_suite.hpp"
#include "facet/error.hpp"

namespace facet::app {

/// What every chart needs besides the data.
struct ChartRequest {
    std::string output;   ///< the PNG to write
    std::string gnuplot;  ///< the gnuplot executable (a name looked up on PATH, or a path)
    std::string title;    ///< machine and date, shown above the plots
    std::vector<int> threads;
};

/// Where a committed chart script is: the source tree's scripts/, else scripts/ beside the
/// executable; empty when neither has it.
std::string findScript(const std::string& name);

/// A string as a gnuplot single-quoted literal ('' stands for a quote).
std::string gpString(const std::string& s);

/// Runs gnuplot with `args` (e.g. {"-e", variables, script}) and waits; an Error, saying how to
/// install it, when it cannot start or fails. Other commands' charts (facet accuracy) use it.
Status runGnuplotScript(const std::string& gnuplot, const std::vector<std::string>& args);

/// Checks that `gnuplot` runs; the Error says how to install it.
Status checkGnuplot(const std::string& gnuplot);

/// The main chart: one panel per config, per case the engine and OpenGL medians at each thread
/// count as bars on a log scale, with a dash at 0.5 × OpenGL on each engine bar (the target).
Status writeSuiteChart(const ChartRequest& request, const BenchSuite& suite,
                       const BenchResults& results);

/// The --scaling chart: ms against triangles and against Mpixels, log-log, the engine and OpenGL
/// at each thread count, with a line of slope 1 (linear growth) through the engine's largest
/// one-thread point.
/// Draws the first config of the suite.
Status writeScalingChart(const ChartRequest& request, const BenchSuite& suite,
                         const BenchResults& results);

}  // namespace facet::app
