#pragma once
// The table `facet bench` prints: per case its size, triangles and memory floor, then per config
// the engine's and OpenGL's times at each thread count, the engine/OpenGL ratios against the
// 0.5× target, and the 1→N scaling against the 1.8× target.

#include <cstdio>
#include <string>
#include <vector>

#include "bench_results.hpp"
#include "cli/bench/bench_suite.hpp"

namespace facet::app {

/// The targets the issue sets (reported, never asserted).
inline constexpr double kRatioTarget = 0.5;    ///< engine ≤ 0.5 × OpenGL
inline constexpr double kScalingTarget = 1.8;  ///< 1 → 2 threads, on 1080p and larger
inline constexpr std::size_t kScalingTargetPixels = 1920u * 1080u;

/// Prints the table for `threads` (1 first, then all cores) to `out`.
void printBenchTable(std::FILE* out, const BenchSuite& suite, const BenchResults& results,
                     const std::vector<int>& threads);

}  // namespace facet::app
