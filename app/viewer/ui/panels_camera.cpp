#include "panels_camera.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framing.hpp"
#include "panel_widgets.hpp"
#include "viewer_model.hpp"

namespace facet::view {

void cameraPanel(ViewerModel& m, bool& vsync) {
    Orbit& o = m.orbit;
    bool edited = false;
    // Angles that round to zero read "0.0", never "-0.0".
    auto degrees = [](double v) { return std::abs(v) < 0.05 ? "0.0 deg" : "%.1f deg"; };
    edited |= sliderDouble("yaw", o.yaw, -180.0, 180.0, degrees(o.yaw));
    edited |= sliderDouble("pitch", o.pitch, -kMaxPitch, kMaxPitch, degrees(o.pitch));
    edited |= sliderDouble("distance", o.distance, o.minDistance, o.maxDistance, "%.4g", true);
    edited |= dragDouble3("look-at", &o.target.x, std::max(1e-6, o.distance * 0.005), "%.3f");
    if (edited) m.orbitEdited();
    sliderDouble("focal (px)", m.focal, 10.0, 100000.0, "%.1f", true);
    // The world axis shown up: a bare mesh is framed again for it, a scene turns its orbit.
    const std::optional<UpAxis> axis = m.orbitAxis();
    ImGui::TextUnformatted("up axis");
    for (const UpAxis a : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
        ImGui::SameLine();
        const char* names[] = {"X", "Y", "Z"};
        if (ImGui::RadioButton(names[static_cast<int>(a)], axis == a)) m.setUpAxis(a);
    }
    if (!axis) {
        sameLineIfFits(ImGui::CalcTextSize("(the scene's own)").x);
        ImGui::TextDisabled("(the scene's own)");
    }
    if (ImGui::Button("Frame the model (F)")) frameModel(m);
    sameLineIfFits(buttonWidth("Scene's camera (Home, R)"));
    if (ImGui::Button("Scene's camera (Home, R)")) m.resetCamera();

    const Camera& frame = m.scene.camera;
    int policy = m.sizePolicy == SizePolicy::FollowWindow ? 0 : 1;
    ImGui::RadioButton("follow the window", &policy, 0);
    char label[64];
    std::snprintf(label, sizeof label, "scene size %dx%d", m.sceneCamera.width,
                  m.sceneCamera.height);
    sameLineIfFits(checkWidth(label));
    ImGui::RadioButton(label, &policy, 1);
    m.sizePolicy = policy == 0 ? SizePolicy::FollowWindow : SizePolicy::SceneSize;
    ImGui::TextDisabled("frame %dx%d, focal %.1f px", frame.width, frame.height, frame.focal);
    ImGui::Checkbox("vsync", &vsync);
}

}  // namespace facet::view
