#pragma once
// `facet accuracy`'s outputs: the table on stdout, the CSV and the gnuplot chart.

#include <string>
#include <vector>

#include "accuracy/accuracy_methods.hpp"
#include "facet/error.hpp"
#include "machine_info.hpp"

namespace facet::app {

/// How a run measured, for the CSV's notes.
struct AccuracyRun {
    int samples = 0;      ///< ground truth per pixel axis
    int frames = 0;       ///< timed frames per method
    int warmup = 0;       ///< untimed frames per method first
    bool quick = false;   ///< --quick: small images, few frames
    std::string leftOut;  ///< methods not measured (methodsBelowTruth()), comma separated
};

/// Whether the machine was busy when the run started: a 1-minute load average above a quarter
/// of its cores. Its times then say more about the other work than about the engine.
bool machineBusy(const MachineInfo& machine);

/// The results as an aligned text table, one row per scene × method ("RMSE in": interior RMSE,
/// "front": * on the scene's Pareto front).
std::string accuracyTable(const std::vector<AccuracyResult>& results);

/// The CSV: `#` lines for the date, machine and its load, samples and frames, a header, one row
/// per result (its last column 1 on the scene's Pareto front).
Status writeAccuracyCsv(const std::string& path, const MachineInfo& machine, const AccuracyRun& run,
                        const std::vector<AccuracyResult>& results);

/// One panel per scene: median ms against RMSE in 8-bit steps, both on log axes, one point per
/// method (filled on the Pareto front, onParetoFront(), drawn as a line), labels placed so none
/// covers another (coinciding methods share one; a label moved off its point has a leader
/// line). Runs gnuplot; an Error when it cannot.
Status writeAccuracyChart(const std::string& path, const std::string& gnuplot,
                          const std::string& title, const std::vector<AccuracyResult>& results);

}  // namespace facet::app
