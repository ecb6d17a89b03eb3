#pragma once
// Opening a scene or a mesh on a worker thread, so a 2M-triangle file does not freeze the
// viewer: the old scene stays on screen until the new one is ready, and a failure keeps it.
// The worker passes a LoadControl to the loaders: they report the fraction read, and Cancel sets
// its flag, which stops the read within a chunk of the file (the worker then ends on its own).

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include <thread>
#include <utility>
#include <vector>
#include "facet/scene_io.hpp"

#include "facet/error.hpp"
#include "facet/load_control.hpp"
#include "facet/scene.hpp"

namespace facet::view {

/// What a finished load produced.
struct LoadedScene {
    std::string path;       ///< the file as the user named it
    Scene scene;            ///< the scene (a bare mesh's made per spec §3b)
    bool bareMesh = false;  ///< the file was a mesh, not a .scene
};

/// One load at a time in flight; a new start() cancels the previous one.
class LoadJob {
  public:
    LoadJob() = default;
    LoadJob(const LoadJob&) = delete;
    LoadJob& operator=(const LoadJob&) = delete;
    /// Cancels the load in flight and waits for its worker (a cancelled read stops quickly).
    ~LoadJob();

    /// Starts opening `path`; a bare mesh gets a scene framed by `options` (size, up axis).
    void start(const std::string& path, const OpenOptions& options);
    /// True from start() until the result is taken or the load cancelled.
    bool running() const;
    /// Stops the load in flight and drops it; the viewer keeps its scene. Returns at once.
    void cancel();
    /// Fraction of the load in flight done so far, in [0, 1] (0 when none).
    float progress() const;
    /// The file being loaded (empty when none).
    const std::string& path() const { return path_; }
    /// Seconds since start().
    double seconds() const;
    /// The finished load, once; nullopt while it runs or when none is in flight.
    std::optional<Result<LoadedScene>> take();

  private:
    struct Shared;
    std::shared_ptr<Shared> current_;
    /// Every worker started, with its state: finished ones are joined at the next start(), the
    /// rest in the destructor.
    std::vector<std::pair<std::thread, std::shared_ptr<Shared>>> workers_;
    std::string path_;
    std::chrono::steady_clock::time_point started_;
};

/// Opens `path` on the calling thread as LoadJob does on its worker.
Result<LoadedScene> loadSceneOrMesh(const std::string& path, const OpenOptions& options,
                                    const LoadControl* control = nullptr);

}  // namespace facet::view
