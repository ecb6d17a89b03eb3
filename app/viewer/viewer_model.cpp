#include "viewer_model.hpp"

#include <cmath>
#include <utility>

#include "facet/scene_io.hpp"
#include "file_list.hpp"

namespace facet::view {

Status ViewerModel::load(const std::string& path) {
    Result<Scene> loaded = loadScene(path);
    if (!loaded) return loaded.error();
    scene = std::move(loaded.value());
    ++sceneVersion;
    sceneCamera = scene.camera;
    resetCamera();
    pushRecent(recent, path, kMaxRecent);
    return std::nullopt;
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
    stats = renderer.render(scene, settings, frame);
    return frame;
}

}  // namespace facet::view
