// Compare panel and the labels over the frame: which interpolation each side uses (or, with
// the CPU | OpenGL renderer, which renderer), split or difference, and the error numbers of the
// two pictures.

#include <imgui.h>

#include "panel_widgets.hpp"
#include "panels.hpp"
#include "settings_map.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

/// An interpolation picker with its N, for one side.
void sidePicker(const char* label, InterpSpec& spec) {
    static const auto names = interpNames();
    ImGui::PushID(label);
    int index = nameIndex(names, toString(spec.interp));
    if (comboNames(label, names, index))
        spec.interp = parseInterp(names[static_cast<std::size_t>(index)]).value_or(spec.interp);
    if (spec.interp == Interp::Subdivided)
        ImGui::SliderInt("N", &spec.subdivision, kMinSubdivision, kMaxSubdivision, "%d",
                         ImGuiSliderFlags_Logarithmic);
    ImGui::PopID();
}

/// The two sides' names: interpolations, or the renderers side by side.
void sideLabels(const App& app, std::string& left, std::string& right) {
    if (app.model.rendererChoice == RendererChoice::Split) {
        left = std::string(rendererLabel(RendererChoice::Cpu));
        right = std::string(rendererLabel(RendererChoice::OpenGl));
    } else {
        left = interpLabel(app.compare.left);
        right = interpLabel(app.compare.right);
    }
}

}  // namespace

void comparePanel(App& app) {
    CompareSettings& c = app.compare;
    const bool sideBySide = app.model.rendererChoice == RendererChoice::Split;
    bool on = c.enabled;
    if (ImGui::Checkbox("compare two interpolations", &on))
        setCompare(on, app.model.rendererChoice, c);
    if (sideBySide) {
        ImGui::TextDisabled("left: CPU engine, right: OpenGL twin");
    } else {
        sidePicker("left", c.left);
        sidePicker("right", c.right);
    }
    int display = c.display == CompareDisplay::Split ? 0 : 1;
    ImGui::RadioButton("split", &display, 0);
    ImGui::SameLine();
    ImGui::RadioButton("difference", &display, 1);
    c.display = display == 0 ? CompareDisplay::Split : CompareDisplay::Difference;
    if (c.display == CompareDisplay::Split)
        sliderDouble("divider", c.divider, 0.0, 1.0, "%.2f");
    else
        ImGui::SliderInt("heat scale", &c.heatScale, 0, 255, c.heatScale ? "%d" : "auto (max)");
    if (!c.enabled && !sideBySide) {
        ImGui::TextDisabled("(drag the divider on the image)");
    } else {
        const ImageDiff& d = app.sides.diff;
        const double share = d.pixels ? 100.0 * static_cast<double>(d.pixelsDiffering) /
                                            static_cast<double>(d.pixels)
                                      : 0.0;
        ImGui::Text("mean error %.4f, max error %d (8-bit steps)", d.meanError, d.maxError);
        ImGui::Text("pixels differing %zu of %zu (%.2f%%)", d.pixelsDiffering, d.pixels, share);
    }
    accuracySection(app);
}

void compareOverlay(App& app) {
    const CompareSettings& c = app.compare;
    const Rect& v = app.view;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the frame, under the panels
    const ImU32 text = IM_COL32(255, 255, 255, 255);
    const ImU32 shade = IM_COL32(0, 0, 0, 160);
    auto label = [&](float x, float y, const std::string& s) {
        const ImVec2 size = ImGui::CalcTextSize(s.c_str());
        draw->AddRectFilled(ImVec2(x - 4, y - 2), ImVec2(x + size.x + 4, y + size.y + 2), shade);
        draw->AddText(ImVec2(x, y), text, s.c_str());
    };
    const float y =
        static_cast<float>(v.y + v.h) - 28.0f;  // near the bottom: panels sit at the top
    const FramePlan plan = planFrame(app.model.rendererChoice, c.enabled);
    if (!plan.twoSides()) {  // the twin alone says so, so no screenshot passes for the engine's
        if (plan.twin) label(static_cast<float>(v.x + 8), y, "OpenGL twin");
        return;
    }
    std::string left, right;
    sideLabels(app, left, right);
    if (c.display == CompareDisplay::Difference) {
        label(static_cast<float>(v.x + 8), y,
              "difference " + left + " vs " + right + " (black: equal)");
        return;
    }
    const float split = static_cast<float>(v.x + c.divider * v.w);
    label(split - 12.0f - ImGui::CalcTextSize(left.c_str()).x, y, left);
    label(split + 12.0f, y, right);
}

}  // namespace facet::view
