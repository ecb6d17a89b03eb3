#pragma once
// Opening a scene or a mesh on a worker thread, so a 2M-triangle file does not freeze the
// viewer: the old scene stays on screen until the new one is ready, and a failure keeps it.
// The loaders have no progress hook, so the job reports the time spent; Cancel returns at once
// (the worker finishes reading in the background and its result is dropped).

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/scene.hpp"

namespace facet::view {

/// What a finished load produced.
struct LoadedScene {
    std::string path;       ///< the file as the user named it
    Scene scene;            ///< the scene (a bare mesh's made per conventions §3b)
    bool bareMesh = false;  ///< the file was a mesh, not a .scene
};

/// One load at a time in flight; a new start() cancels the previous one.
class LoadJob {
  public:
    LoadJob() = default;
    LoadJob(const LoadJob&) = delete;
    LoadJob& operator=(const LoadJob&) = delete;
    /// Waits for the workers still reading (a cancelled load runs to its end).
    ~LoadJob();

    /// Starts opening `path`; a bare mesh gets a scene of `width` × `height`.
    void start(const std::string& path, int width, int height);
    /// True from start() until the result is taken or the load cancelled.
    bool running() const;
    /// Drops the load in flight; the viewer keeps its scene.
    void cancel();
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
Result<LoadedScene> loadSceneOrMesh(const std::string& path, int width, int height);

}  // namespace facet::view
