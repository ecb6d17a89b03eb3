#include "panels_light.hpp"

#include <imgui.h>

#include "panel_widgets.hpp"
#include "viewer_model.hpp"

namespace facet::view {

void lightPanel(ViewerModel& model) {
    LightingParams& lighting = model.scene.lighting;
    Light& light = lighting.light;
    ImGui::TextUnformatted("Light");
    dragDouble3("x y z", &light.position.x, 0.05);
    int kind = light.position.w == 0.0 ? 1 : 0;
    if (ImGui::RadioButton("point", &kind, 0) && light.position.w == 0.0) light.position.w = 1.0;
    sameLineIfFits(checkWidth("directional (w = 0)"));
    if (ImGui::RadioButton("directional (w = 0)", &kind, 1)) light.position.w = 0.0;
    // One line whatever the kind, so the rows below do not move.
    if (light.position.w == 0.0)
        ImGui::TextDisabled("coming from direction x y z");
    else if (light.position.w != 1.0)
        ImGui::TextDisabled("w = %.3g: the light sits at xyz / w", light.position.w);
    else
        ImGui::TextDisabled("a point at x y z");
    fineDouble("Ia (ambient)", lighting.ambient, 0.005);
    fineDouble("Id (light)", light.intensity, 0.01);

    Material& mat = lighting.material;
    ImGui::Separator();
    ImGui::TextUnformatted("Material");
    fineDouble("Ka", mat.ka, 0.002);
    fineDouble("Kd", mat.kd, 0.002);
    fineDouble("Ks", mat.ks, 0.002);
    logSliderDouble("s (shininess)", mat.s, 1.0, 1000.0);
    if (model.settings.lighting == Lighting::Off)
        ImGui::TextDisabled("lighting is off: L, or gouraud / phong in Render");
    else
        ImGui::TextDisabled("drag the light's marker; Ctrl + drag turns it");
}

}  // namespace facet::view
