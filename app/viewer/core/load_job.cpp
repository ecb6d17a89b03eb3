#include "load_job.hpp"

#include <atomic>
#include <mutex>
#include <utility>

#include "facet/scene_io.hpp"

namespace facet::view {

struct LoadJob::Shared {
    std::atomic<bool> stop{false};  // read by the loaders, set by cancel()
    std::atomic<float> progress{0.0f};
    std::mutex mutex;
    bool done = false;
    bool cancelled = false;
    std::optional<Result<LoadedScene>> result;
};

Result<LoadedScene> loadSceneOrMesh(const std::string& path, const OpenOptions& options,
                                    const LoadControl* control) {
    const bool bareMesh = fileKind(path) == FileKind::mesh;
    Result<Scene> scene = openSceneFile(path, options, control);
    if (!scene) return scene.error();
    return LoadedScene{path, std::move(scene).value(), bareMesh};
}

LoadJob::~LoadJob() {
    cancel();
    for (auto& [thread, shared] : workers_) thread.join();
}

void LoadJob::start(const std::string& path, const OpenOptions& options) {
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
    std::thread worker([shared, path, options] {
        LoadControl control;
        control.progress = [&shared = *shared](float f) {
            shared.progress.store(f, std::memory_order_relaxed);
        };
        control.cancel = &shared->stop;
        Result<LoadedScene> loaded = loadSceneOrMesh(path, options, &control);
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
    current_->stop.store(true, std::memory_order_relaxed);
    {
        const std::lock_guard lock(current_->mutex);
        current_->cancelled = true;
        current_->result.reset();  // a big scene is freed now, not at the next load
    }
    current_.reset();
    path_.clear();
}

float LoadJob::progress() const {
    return current_ ? current_->progress.load(std::memory_order_relaxed) : 0.0f;
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
