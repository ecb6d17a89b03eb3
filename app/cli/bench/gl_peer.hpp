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

#include <memory>
#include <string>

#include "bench_options.hpp"
#include "facet/error.hpp"
#include "report/bench_results.hpp"

namespace facet::app {

/// One running peer for one LP_NUM_THREADS. Move-only; the destructor ends it (see finish()).
class GlPeerProcess {
  public:
    /// Starts the peer over the suite the options select and waits for its context; an Error
    /// when it could not start or create its context.
    static Result<GlPeerProcess> start(const BenchOptions& options, int lpThreads);

    GlPeerProcess(GlPeerProcess&& other) noexcept;
    GlPeerProcess& operator=(GlPeerProcess&& other) noexcept;
    ~GlPeerProcess();

    /// The peer's renderer, e.g. "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (...)".
    const std::string& renderer() const;

    /// Times (case, config) in the peer; an Error when it failed or died (then ask no more).
    Result<FrameTimes> measure(const std::string& caseName, const std::string& config);

    /// Closes the peer's input and waits for it; an Error when it exited badly.
    Status finish();

  private:
    struct State;
    explicit GlPeerProcess(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

/// The peer's own main (`facet bench --peer`): answers "run <case> <config>" lines on stdin with
/// the OpenGL twin until stdin ends, writing the protocol on stdout. Returns the exit code.
int runGlPeer(const BenchOptions& options);

}  // namespace facet::app
