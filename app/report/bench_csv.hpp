#pragma once
// The CSV of a run: `#` comment lines saying when, where and how it was measured, then one row
// per measurement (case × config × renderer × threads, and the memory floors).

#include <string>
#include <vector>

#include "bench_results.hpp"
#include "cli/bench/bench_options.hpp"
#include "cli/bench/bench_suite.hpp"
#include "facet/error.hpp"
#include "machine_info.hpp"

namespace facet::app {

/// How the run was made, for the header.
struct RunDescription {
    std::string mode;  ///< "suite", "scaling", with ", quick"
    std::vector<int> threads;
    FramePlan plan;
};

/// Writes the CSV; an Error names the file when it cannot be written.
Status writeBenchCsv(const std::string& path, const MachineInfo& machine, const RunDescription& run,
                     const BenchSuite& suite, const BenchResults& results);

}  // namespace facet::app
