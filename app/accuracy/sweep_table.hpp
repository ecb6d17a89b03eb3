#pragma once
// A stability sweep's measurements as one table: `facet sweeps` writes it as CSV and hands it to
// the sweep's gnuplot script (scripts/sweep_<name>.gp); the tests read the typed results the
// table is built from, so the chart and the asserted bounds come from the same measurement.

#include <functional>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/evaluation/reference_compare.hpp"

namespace facet::app {

/// What every sweep is given.
struct SweepOptions {
    std::string shared;  ///< the shared data folder (../shared), for the meshes of the sweeps
    bool quick = false;  ///< fewer and smaller steps: a smoke run for tests
    int frames = 5;      ///< timed frames per point where a sweep times (median)
    int samples = 8;     ///< ground-truth samples per pixel axis, where a sweep uses one
    /// Called once per measured point with a short line ("view angle: wall 40° affine"), for
    /// the progress display; may be empty.
    std::function<void(const std::string&)> progress;

    /// Calls `progress` when set.
    void report(const std::string& line) const {
        if (progress) progress(line);
    }
};

/// One sweep's table: the CSV and the chart script read the same columns.
struct SweepTable {
    std::string name;   ///< file stem: <name>.csv, <name>.png and scripts/sweep_<name>.gp
    std::string title;  ///< the chart's title (what is swept, what is measured)
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;  ///< one cell per column

    /// Appends a row; the cells must match the columns in number (asserted).
    void add(std::vector<std::string> cells);
};

/// A number as a CSV cell: %.9g; NaN as "nan", infinities as "inf" / "-inf".
std::string cell(double v);

/// The sweep tables' columns for a ReferenceDiff: fast_covered, ref_covered, ambiguous,
/// coverage_diff, max_color_diff, nan_depth.
std::vector<std::string> referenceDiffColumns();

/// The cells of those columns for `d`.
std::vector<std::string> referenceDiffCells(const ReferenceDiff& d);

/// Writes the table: `# ` comment lines (`notes`, one per element), the header, the rows.
Status writeSweepCsv(const std::string& path, const SweepTable& table,
                     const std::vector<std::string>& notes);

}  // namespace facet::app
