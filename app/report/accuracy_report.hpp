#pragma once
// `facet accuracy`'s outputs: the table on stdout, the CSV and the gnuplot chart.

#include <string>
#include <vector>

#include "accuracy/accuracy_methods.hpp"
#include "facet/error.hpp"
#include "machine_info.hpp"

namespace facet::app {

/// The results as an aligned text table, one row per scene × method ("RMSE in": interior RMSE).
std::string accuracyTable(const std::vector<AccuracyResult>& results);

/// The CSV: `#` lines for the date, machine, samples and frames, a header, one row per result.
Status writeAccuracyCsv(const std::string& path, const MachineInfo& machine, int samples,
                        const std::vector<AccuracyResult>& results);

/// The methods of each scene on the same axes: median ms (log) against RMSE in 8-bit steps, one
/// labelled point per method, each scene's Pareto front (no other method both faster and more
/// accurate) as a line. Runs gnuplot; an Error when it cannot.
Status writeAccuracyChart(const std::string& path, const std::string& gnuplot,
                          const std::string& title, const std::vector<AccuracyResult>& results);

}  // namespace facet::app
