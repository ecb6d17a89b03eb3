// Camera, Light and Material panels: sliders bound straight to the orbit and to the Scene's
// fields; the next frame renders with them, nothing is reloaded.

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "panel_widgets.hpp"
#include "panels.hpp"
#include "viewer_app.hpp"

namespace facet::view {

void cameraPanel(App& app) {
    ViewerModel& m = app.model;
    Orbit& o = m.orbit;
    bool edited = false;
    edited |= sliderDouble("yaw", o.yaw, -180.0, 180.0, "%.1f deg");
    edited |= sliderDouble("pitch", o.pitch, -kMaxPitch, kMaxPitch, "%.1f deg");
    edited |= sliderDouble("distance", o.distance, o.minDistance, o.maxDistance, "%.4g", true);
    edited |= dragDouble3("look-at", &o.target.x, std::max(1e-6, o.distance * 0.005), "%.3f");
    if (edited) m.orbitEdited();
    sliderDouble("focal (px)", m.focal, 10.0, 100000.0, "%.1f", true);
    if (ImGui::Button("Reset to the scene's camera (R)")) m.resetCamera();

    const Camera& frame = m.scene.camera;
    int policy = m.sizePolicy == SizePolicy::FollowWindow ? 0 : 1;
    ImGui::RadioButton("follow the window", &policy, 0);
    ImGui::SameLine();
    char label[64];
    std::snprintf(label, sizeof label, "scene size %dx%d", m.sceneCamera.width,
                  m.sceneCamera.height);
    ImGui::RadioButton(label, &policy, 1);
    m.sizePolicy = policy == 0 ? SizePolicy::FollowWindow : SizePolicy::SceneSize;
    ImGui::TextDisabled("frame %dx%d, focal %.1f px", frame.width, frame.height, frame.focal);
    ImGui::Checkbox("vsync", &app.ui.vsync);
}

void lightPanel(App& app) {
    LightingParams& lighting = app.model.scene.lighting;
    Light& light = lighting.light;
    ImGui::TextUnformatted("Light");
    dragDouble3("x y z", &light.position.x, 0.05);
    int kind = light.position.w == 0.0 ? 1 : 0;
    if (ImGui::RadioButton("point", &kind, 0) && light.position.w == 0.0) light.position.w = 1.0;
    ImGui::SameLine();
    if (ImGui::RadioButton("directional (w = 0)", &kind, 1)) light.position.w = 0.0;
    if (kind == 0 && light.position.w != 1.0)
        ImGui::TextDisabled("w = %.3g: the light sits at xyz / w", light.position.w);
    sliderDouble("Ia (ambient)", lighting.ambient, 0.0, 4.0);
    sliderDouble("Id (light)", light.intensity, 0.0, 10.0);

    Material& mat = lighting.material;
    ImGui::Separator();
    ImGui::TextUnformatted("Material");
    sliderDouble("Ka", mat.ka, 0.0, 2.0);
    sliderDouble("Kd", mat.kd, 0.0, 2.0);
    sliderDouble("Ks", mat.ks, 0.0, 2.0);
    sliderDouble("s (shininess)", mat.s, 0.0, 1024.0, "%.2f", true);
    if (app.model.settings.lighting == Lighting::Off)
        ImGui::TextDisabled("lighting is off: choose gouraud or phong in Render");
}

}  // namespace facet::view
