#pragma once
// The OpenGL side of `facet bench`. llvmpipe reads LP_NUM_THREADS once, when its screen is
// created, so each thread count needs a process of its own: the bench re-runs its own executable
// as `facet bench --peer ...` with the variable set, once per thread count, and keeps it running.
// The parent asks for one measurement at a time ("run <case> <config>" on the peer's stdin), so
// it can take the engine's and the peer's measurements of a case one after the other, and the
// peer answers one line per event on stdout.
//
// What a peer frame is: the mesh stays resident, as in an application with a static mesh. Per
// (case, config) the peer uploads once, untimed (positions, vertex normals when lit, indices,
// texture); each timed frame is the clear and the draw up to glFinish; colour and depth are read
// back once, untimed, only when --images asks for the picture.

#include "bench_options.hpp"

namespace facet::app {

/// The peer's own main (`facet bench --peer`): answers "run <case> <config>" lines on stdin with
/// the OpenGL twin until stdin ends, writing the protocol on stdout. Returns the exit code.
int runGlPeer(const BenchOptions& options);

}  // namespace facet::app
