#include "viewer_model.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <utility>

#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"
#include "file_list.hpp"
#include "scene_defaults.hpp"

namespace facet::view {

Status ViewerModel::load(const std::string& path) {
    Result<LoadedScene> loaded = loadSceneOrMesh(path, openOptions());
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
    applyOpeningSettings(scene, settings);
    rememberFile(loaded.path);
    markSaved();
}

Camera ViewerModel::userCamera() const {
    Camera user = sceneCamera;
    if (orbitMoved) applyPose(orbit, user);
    if (focal > 0.0 && std::isfinite(focal)) user.focal = focal;
    return user;
}

Status ViewerModel::saveScene(const std::string& path, bool windowSize) {
    Scene out = scene;  // shares the mesh and texture
    if (!windowSize) out.camera = userCamera();
    if (Status error = writeScene(out, path); !error) return error;
    rememberFile(path);
    markSaved();
    return {};
}

DocumentState ViewerModel::documentState() const {
    DocumentState d;
    d.orbitMoved = orbitMoved;
    if (orbitMoved) {
        d.target = orbit.target;
        d.vertical = orbit.vertical;
        d.yaw = orbit.yaw;
        d.pitch = orbit.pitch;
        d.distance = orbit.distance;
    }
    d.focal = focal;
    d.lighting = scene.lighting;
    d.settings = settings;
    d.texturePath = scene.texturePath;
    return d;
}

void ViewerModel::markSaved() {
    saved = documentState();
}

bool ViewerModel::unsaved() const {
    return !(documentState() == saved);
}

void ViewerModel::rememberFile(const std::string& path) {
    pushRecent(recent, path, kMaxRecent);
    if (!recentFile.empty()) writeRecent(recentFile, recent);
}

Status ViewerModel::loadTexture(const std::string& path) {
    if (Status error = loadSceneTexture(scene, path); !error) return error;
    applyOpeningSettings(scene, settings);
    return {};
}

OpenOptions ViewerModel::openOptions() const {
    return OpenOptions{kBareMeshWidth, kBareMeshHeight, up};
}

void ViewerModel::setUpAxis(UpAxis axis) {
    up = axis;
    if (bareMesh) {
        // The scene as opening the mesh with this axis gives it (one copy of the mesh, once).
        const Scene framed =
            sceneForMesh(*scene.mesh, scene.meshPath, sceneCamera.width, sceneCamera.height, axis);
        sceneCamera = framed.camera;
        scene.lighting.light = framed.lighting.light;
        resetCamera();
        return;
    }
    // The view stays; yaw and pitch are measured about the new vertical from now on.
    const Pose pose = orbitPose(orbit);
    Orbit basis = orbit;
    basis.vertical = upVector(axis);
    const glm::dvec3 offset = pose.eye - pose.look;
    const glm::dvec3 flat = offset - glm::dot(offset, basis.vertical) * basis.vertical;
    const double n = glm::length(flat);
    if (n > 1e-9 * glm::length(offset))
        basis.reference = flat / n;
    else  // looking straight along the axis: any direction across it
        basis.reference = glm::normalize(glm::cross(basis.vertical, std::abs(basis.vertical.x) < 0.6
                                                                        ? glm::dvec3(1, 0, 0)
                                                                        : glm::dvec3(0, 1, 0)));
    orbit = orbitMeasure(basis, pose.eye, pose.look);
    orbitMoved = true;
}

std::optional<UpAxis> ViewerModel::orbitAxis() const {
    for (const UpAxis a : {UpAxis::X, UpAxis::Y, UpAxis::Z})
        if (std::abs(glm::dot(orbit.vertical, upVector(a))) > 0.9999) return a;
    return {};
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
    scene.camera = frameCamera(userCamera(), sizePolicy, windowWidth, windowHeight);
    return scene.camera;
}

const Framebuffer& ViewerModel::render() {
    // A refused frame (checkFrame: the camera, the size) keeps the last image, with no stats
    // and the reason, which the window shows over the image.
    Result<RenderStats> rendered = renderer.render(scene, settings, frame);
    stats = rendered ? rendered.value() : RenderStats{};
    refused = rendered ? std::string() : rendered.error().what();
    return frame;
}

}  // namespace facet::view
