#pragma once
// Small ImGui helpers shared by the panels: combo boxes over the engine's name lists, sliders
// over doubles, and rows that wrap in a narrow side bar.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "log_slider.hpp"

namespace facet::view {

/// The width of a checkbox or radio button labelled `label`.
inline float checkWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
           ImGui::CalcTextSize(label, nullptr, true).x;
}

/// The width of a button labelled `label`.
inline float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

/// Puts the next item, `width` pixels wide, beside the last one when it fits before the
/// window's right edge, else on the next line: a row of buttons in a narrow side bar (an
/// 800-pixel window) wraps instead of being cut off.
inline void sameLineIfFits(float width) {
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

/// A combo box over `names`; returns true when the selection changed.
inline bool comboNames(const char* label, const std::vector<std::string_view>& names, int& index) {
    bool changed = false;
    const std::string current(names.empty() ? std::string_view()
                                            : names[static_cast<std::size_t>(index)]);
    if (ImGui::BeginCombo(label, current.c_str())) {
        for (int i = 0; i < static_cast<int>(names.size()); ++i) {
            const std::string name(names[static_cast<std::size_t>(i)]);
            if (ImGui::Selectable(name.c_str(), i == index)) {
                changed = i != index;
                index = i;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

/// A slider over a double; `log` for ranges spanning decades (distance, focal, shininess).
inline bool sliderDouble(const char* label, double& v, double min, double max,
                         const char* format = "%.3f", bool log = false) {
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &min, &max, format,
                               log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
}

/// A slider over a double on a log scale from `min` to `max` (log_slider.hpp), with a field
/// beside it that takes any typed value ≥ 0 (beyond the slider's range too) on Enter.
inline bool logSliderDouble(const char* label, double& v, double min, double max) {
    ImGui::PushID(label);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float full = ImGui::CalcItemWidth();
    const float field = std::min(0.35f * full, ImGui::GetFontSize() * 4.5f);
    ImGui::SetNextItemWidth(std::max(1.0f, full - field - style.ItemInnerSpacing.x));
    float t = static_cast<float>(logSliderPosition(v, min, max));
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);  // shown as it is: no % in a number
    bool changed = ImGui::SliderFloat("##log", &t, 0.0f, 1.0f, text, ImGuiSliderFlags_NoInput);
    if (changed) v = roundSignificant(logSliderValue(t, min, max), 3);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("log scale %g to %g; type beyond it at right", min, max);
    ImGui::SameLine(0.0f, style.ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(field);
    double typed = v;
    if (ImGui::InputDouble("##typed", &typed, 0.0, 0.0, "%.4g",
                           ImGuiInputTextFlags_EnterReturnsTrue) &&
        std::isfinite(typed) && typed >= 0.0) {
        v = typed;
        changed = true;
    }
    ImGui::SameLine(0.0f, style.ItemInnerSpacing.x);
    ImGui::TextUnformatted(label, std::strstr(label, "##"));  // the visible part
    ImGui::PopID();
    return changed;
}

/// A drag field over a double ≥ `min` for fine values: `perPixel` per pixel of drag, Alt for a
/// hundredth of it, Shift for ten times; double-click or Ctrl+click types a value.
inline bool fineDouble(const char* label, double& v, double perPixel, double min = 0.0,
                       const char* format = "%.4f") {
    const double max = 1e9;
    const bool changed = ImGui::DragScalar(label, ImGuiDataType_Double, &v,
                                           static_cast<float>(perPixel), &min, &max, format);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("drag: %g a pixel, Alt finer, Shift coarser; double-click types",
                          perPixel);
    return changed;
}

/// A drag field over three doubles.
inline bool dragDouble3(const char* label, double* v, double speed, const char* format = "%.3f") {
    return ImGui::DragScalarN(label, ImGuiDataType_Double, v, 3, static_cast<float>(speed), nullptr,
                              nullptr, format);
}

}  // namespace facet::view
