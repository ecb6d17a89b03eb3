#pragma once
// The parent's side of the OpenGL peer (gl_peer.hpp says what the peer is and why it is a
// process of its own): a running `facet bench --peer` per LP_NUM_THREADS, asked for one
// measurement at a time.

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

}  // namespace facet::app
