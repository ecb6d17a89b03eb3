#include "viewer_model.hpp"

#include <cmath>
#include <utility>

#include "facet/scene_io.hpp"
#include "file_list.hpp"
#include "scene_defaults.hpp"

namespace facet::view {

Status ViewerModel::load(const std::string& path) {
    Result<LoadedScene> loaded = loadSceneOrMesh(path, kBareMeshWidth, kBareMeshHeight);
    if (!loaded) return loaded.error();
    adopt(std::move(loaded).value());
    return {};
}

void ViewerModel::adopt(LoadedScene loaded) {
    scene = std::move(loaded.scene);
    bareMesh = loaded.bareMesh;
    ++sceneVersion;
    sceneCamera = scene.camera;
    resetCamera();
    applySceneDefaults(scene, bareMesh, settings);
    rememberFile(loaded.path);
}

Status ViewerModel::saveScene(const std::string& path) {
    if (Status error = writeScene(scene, path); !error) return error;
    rememberFile(path);
    return {};
}

void ViewerModel::rememberFile(const std::string& path) {
    pushRecent(recent, path, kMaxRecent);
    if (!recentFile.empty()) writeRecent(recentFile, recent);
}

Status ViewerModel::loadTexture(const std::string& path) {
    return loadSceneTexture(scene, path);
}

void ViewerModel::resetCamera() {
    orbit = orbitFromCamera(sceneCamera);
    orbitMoved = false;
    focal = sceneCamera.focal;
}

void ViewerModel::rotate(double dx, double dy) {
    orbitRotate(orbit, dx, dy);
    orbitMoved = true;
}

void ViewerModel::pan(double dx, double dy) {
    orbitPan(orbit, dx, dy, scene.camera.focal);
    orbitMoved = true;
}

void ViewerModel::zoom(double steps) {
    orbitZoom(orbit, steps);
    orbitMoved = true;
}

void ViewerModel::orbitEdited() {
    orbitClamp(orbit);
    orbitMoved = true;
}

const Camera& ViewerModel::prepareFrame(int windowWidth, int windowHeight) {
    Camera user = sceneCamera;
    if (orbitMoved) applyPose(orbit, user);
    if (focal > 0.0 && std::isfinite(focal)) user.focal = focal;
    scene.camera = frameCamera(user, sizePolicy, windowWidth, windowHeight);
    return scene.camera;
}

const Framebuffer& ViewerModel::render() {
    // A refused frame (checkFrame: the camera, the size) keeps the last image, with no stats.
    Result<RenderStats> rendered = renderer.render(scene, settings, frame);
    stats = rendered ? rendered.value() : RenderStats{};
    return frame;
}

}  // namespace facet::view
