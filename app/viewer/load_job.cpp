#include "load_job.hpp"

#include <mutex>
#include <utility>

#include "facet/scene_io.hpp"

namespace facet::view {

struct LoadJob::Shared {
    std::mutex mutex;
    bool done = false;
    bool cancelled = false;
    std::optional<Result<LoadedScene>> result;
};

Result<LoadedScene> loadSceneOrMesh(const std::string& path, int width, int height) {
    const bool bareMesh = fileKind(path) == FileKind::mesh;
    Result<Scene> scene = openSceneFile(path, width, height);
    if (!scene) return scene.error();
    return LoadedScene{path, std::move(scene).value(), bareMesh};
}

LoadJob::~LoadJob() {
    cancel();
    for (auto& [thread, shared] : workers_) thread.join();
}

void LoadJob::start(const std::string& path, int width, int height) {
    cancel();
    std::erase_if(workers_, [](auto& worker) {
        bool done = false;
        {
            const std::lock_guard lock(worker.second->mutex);
            done = worker.second->done;
        }
        if (done) worker.first.join();
        return done;
    });
    auto shared = std::make_shared<Shared>();
    current_ = shared;
    path_ = path;
    started_ = std::chrono::steady_clock::now();
    std::thread worker([shared, path, width, height] {
        Result<LoadedScene> loaded = loadSceneOrMesh(path, width, height);
        const std::lock_guard lock(shared->mutex);
        if (!shared->cancelled) shared->result.emplace(std::move(loaded));
        shared->done = true;
    });
    workers_.emplace_back(std::move(worker), shared);
}

bool LoadJob::running() const {
    return current_ != nullptr;
}

void LoadJob::cancel() {
    if (!current_) return;
    {
        const std::lock_guard lock(current_->mutex);
        current_->cancelled = true;
        current_->result.reset();  // a big scene is freed now, not at the next load
    }
    current_.reset();
    path_.clear();
}

double LoadJob::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

std::optional<Result<LoadedScene>> LoadJob::take() {
    if (!current_) return std::nullopt;
    std::optional<Result<LoadedScene>> out;
    {
        const std::lock_guard lock(current_->mutex);
        if (!current_->done) return std::nullopt;
        out = std::move(current_->result);
    }
    current_.reset();
    path_.clear();
    return out;
}

}  // namespace facet::view
