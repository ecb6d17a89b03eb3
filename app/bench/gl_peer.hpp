#pragma once
// The OpenGL side of `facet bench`. llvmpipe reads LP_NUM_THREADS once, when its screen is
// created, so each thread count needs a process of its own: the bench re-runs its own executable
// as `facet bench --peer ...` with the variable set, and the peer reports over a pipe, one line
// per event, so the parent shows progress while the peer works.

#include <functional>
#include <string>

#include "bench_options.hpp"
#include "bench_results.hpp"
#include "facet/error.hpp"

namespace facet::app {

/// What the parent hears from a peer, in order: info once, then start/result per measurement.
struct PeerEvents {
    std::function<void(const std::string& renderer)> info;
    std::function<void(const std::string& caseName, const std::string& config)> start;
    std::function<void(const std::string& caseName, const std::string& config,
                       const FrameTimes& times)>
        result;
};

/// Runs the peer for LP_NUM_THREADS = `lpThreads` over the suite the options select, calling
/// `events` as lines arrive. An Error when the peer could not start, create its context or
/// draw, or exited badly; measurements already reported stay reported.
Status runGlPeerProcess(const BenchOptions& options, int lpThreads, const PeerEvents& events);

/// The peer's own main (`facet bench --peer`): draws every case × config with the OpenGL twin
/// and writes the protocol on stdout. Returns the exit code.
int runGlPeer(const BenchOptions& options);

}  // namespace facet::app
