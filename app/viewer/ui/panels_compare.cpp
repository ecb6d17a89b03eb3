#include "panels_compare.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "compare_stats.hpp"
#include "panel_widgets.hpp"
#include "panels_accuracy.hpp"
#include "settings_map.hpp"
#include "viewer_model.hpp"

namespace facet::view {
namespace {

/// An interpolation picker with its N, for one side.
void sidePicker(const char* label, InterpSpec& spec) {
    static const auto names = interpNames();
    ImGui::PushID(label);
    int index = nameIndex(names, toString(spec.interp));
    if (comboNames(label, names, index))
        spec.interp = parseInterp(names[static_cast<std::size_t>(index)]).value_or(spec.interp);
    ImGui::BeginDisabled(spec.interp != Interp::Subdivided);  // kept: the rows stay put
    ImGui::SliderInt("N", &spec.subdivision, kMinSubdivision, kMaxSubdivision, "%d",
                     ImGuiSliderFlags_Logarithmic);
    ImGui::EndDisabled();
    ImGui::PopID();
}

/// The two sides' names: interpolations, or the renderers side by side.
void sideLabels(const CompareSettings& c, RendererChoice renderer, std::string& left,
                std::string& right) {
    if (renderer == RendererChoice::Split) {
        left = std::string(rendererLabel(RendererChoice::Cpu));
        right = std::string(rendererLabel(RendererChoice::OpenGl));
    } else if (renderer == RendererChoice::LabSplit) {
        left = std::string(rendererLabel(RendererChoice::Lab));
        right = "facet (" + std::string(rendererLabel(RendererChoice::Cpu)) + ")";
    } else {
        left = interpLabel(c.left);
        right = interpLabel(c.right);
    }
}

/// The heat map's scale: a viridis bar from 0 to the brightest error with its numbers, at the
/// top left of the frame (the stats box has the top right, the labels the bottom).
void colourBar(const CompareState& compare, const Rect& v, float s) {
    const CompareSettings& c = compare.settings;
    const CompareView& sides = compare.sides;
    const int top = heatTop(c.heatScale, sides.diff.maxError);
    const char* caption = "error, 8-bit steps";
    const char* note =
        c.heatScale ? "black: equal; top: heat scale" : "black: equal; top: max (16 or more)";
    const float w =
        std::min(std::max(160.0f * s, ImGui::CalcTextSize(note).x), 0.6f * static_cast<float>(v.w));
    const float h = 12.0f * s;
    const float pad = 6.0f * s;
    const float line = ImGui::GetTextLineHeight();
    const float x0 = static_cast<float>(v.x) + 2.0f * pad;
    const float y0 = static_cast<float>(v.y) + 2.0f * pad + line;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddRectFilled(ImVec2(x0 - pad, y0 - pad - line),
                        ImVec2(x0 + w + pad, y0 + h + 2.0f * line + 2.0f * pad),
                        IM_COL32(0, 0, 0, 190));
    const ImU32 text = IM_COL32(255, 255, 255, 255);
    draw->AddText(ImVec2(x0, y0 - line - 2.0f), text, caption);
    constexpr int kSteps = 48;
    const float step = w / static_cast<float>(kSteps);
    for (int i = 0; i < kSteps; ++i) {
        // Step i shows the error at its middle, from just above 0 to `top`.
        const glm::dvec3 col = heatColour(top * (i + 0.5) / kSteps, top);
        const ImU32 fill =
            IM_COL32(static_cast<int>(col.r * 255.0 + 0.5), static_cast<int>(col.g * 255.0 + 0.5),
                     static_cast<int>(col.b * 255.0 + 0.5), 255);
        draw->AddRectFilled(ImVec2(x0 + step * static_cast<float>(i), y0),
                            ImVec2(x0 + step * static_cast<float>(i + 1), y0 + h), fill);
    }
    draw->AddRect(ImVec2(x0, y0), ImVec2(x0 + w, y0 + h), IM_COL32(255, 255, 255, 200));
    auto tick = [&](double value, float fx, float anchor) {
        char num[16];
        std::snprintf(num, sizeof num, "%g", value);
        const float tw = ImGui::CalcTextSize(num).x;
        const float x = x0 + fx * w;
        draw->AddLine(ImVec2(x, y0 + h), ImVec2(x, y0 + h + 3.0f * s), text);
        draw->AddText(ImVec2(x - anchor * tw, y0 + h + 3.0f * s), text, num);
    };
    tick(0, 0.0f, 0.0f);
    tick(0.5 * top, 0.5f, 0.5f);
    tick(top, 1.0f, 1.0f);
    draw->AddText(ImVec2(x0, y0 + h + line + 4.0f * s), IM_COL32(200, 200, 200, 255), note);
}

}  // namespace

void comparePanel(CompareState& compare, ViewerModel& model, AccuracyState& accuracy) {
    CompareSettings& c = compare.settings;
    const bool sideBySide = model.rendererChoice == RendererChoice::Split ||
                            model.rendererChoice == RendererChoice::LabSplit;
    bool on = c.enabled;
    if (ImGui::Checkbox("compare two interpolations", &on)) setCompare(on, model.rendererChoice, c);
    // Side by side, the two sides are the renderers (labelled on the image): the pickers stay,
    // greyed out, so the rows below do not move.
    ImGui::BeginDisabled(sideBySide);
    sidePicker("left", c.left);
    sidePicker("right", c.right);
    ImGui::EndDisabled();
    int display = c.display == CompareDisplay::Split ? 0 : 1;
    ImGui::RadioButton("split", &display, 0);
    ImGui::SameLine();
    ImGui::RadioButton("difference", &display, 1);
    c.display = display == 0 ? CompareDisplay::Split : CompareDisplay::Difference;
    if (c.display == CompareDisplay::Split)
        sliderDouble("divider", c.divider, 0.0, 1.0, "%.2f");
    else
        ImGui::SliderInt("heat scale", &c.heatScale, 0, 255, c.heatScale ? "%d" : "auto (max)");
    // Always three lines, so the rows below stay where they are when Compare goes on or off
    // (in a narrow side bar each wraps, and they move).
    if (!c.enabled && !sideBySide) {
        ImGui::TextDisabled("off: tick it, or press C (G for CPU | OpenGL)");
        ImGui::TextDisabled("then drag the divider on the image, or D for");
        ImGui::TextDisabled("the difference heat map");
    } else {
        const ImageDiff& d = compare.sides.diff;
        const double share = d.pixels ? 100.0 * static_cast<double>(d.pixelsDiffering) /
                                            static_cast<double>(d.pixels)
                                      : 0.0;
        ImGui::Text("mean error %.3f, max %d (8-bit steps)", d.meanError, d.maxError);
        ImGui::Text("differing: %zu of %zu pixels (%.2f%%)", d.pixelsDiffering, d.pixels, share);
        ImGui::TextDisabled("over the covered pixels (background left out)");
    }
    accuracySection(accuracy, model);
}

void compareOverlay(const CompareState& compare, RendererChoice renderer, const Rect& v,
                    float scale) {
    const CompareSettings& c = compare.settings;
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
    const FramePlan plan = planFrame(renderer, c.enabled);
    if (!plan.twoSides()) {  // the twin alone says so, so no screenshot passes for the engine's
        if (plan.twin)
            label(
                static_cast<float>(v.x + 8), y,
                std::string(rendererLabel(renderer == RendererChoice::Lab ? RendererChoice::Lab
                                                                          : RendererChoice::OpenGl))
                    .c_str());
        return;
    }
    std::string left, right;
    sideLabels(c, renderer, left, right);
    if (c.display == CompareDisplay::Difference) {
        label(static_cast<float>(v.x + 8), y, "difference " + left + " vs " + right);
        colourBar(compare, v, scale);
        return;
    }
    const float split = static_cast<float>(v.x + c.divider * v.w);
    label(split - 12.0f - ImGui::CalcTextSize(left.c_str()).x, y, left);
    label(split + 12.0f, y, right);
}

}  // namespace facet::view
