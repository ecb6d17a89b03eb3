#pragma once
// Where a benchmark ran, for the CSV header: numbers mean little without the machine.

#include <string>

namespace facet::app {

/// The machine and build a run measured.
struct MachineInfo {
    std::string date;      ///< local time, ISO 8601 with the UTC offset
    std::string cpu;       ///< "model name" from /proc/cpuinfo
    int cores = 0;         ///< hardware concurrency
    std::string compiler;  ///< e.g. "GCC 12.2.0"
    std::string build;     ///< "optimised" or "debug (assertions on)"
    std::string kernel;    ///< uname -sr
    std::string load;      ///< /proc/loadavg's 1, 5 and 15 minute figures: was the machine busy?
};

/// Collects it now; fields it cannot find say "unknown". Call it before measuring, so the load
/// average is the machine's, not the benchmark's.
MachineInfo collectMachineInfo();

}  // namespace facet::app
