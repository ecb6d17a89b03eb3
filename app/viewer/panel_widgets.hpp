#pragma once
// Small ImGui helpers shared by the panels: combo boxes over the engine's name lists and
// sliders over doubles.

#include <imgui.h>

#include <string>
#include <string_view>
#include <vector>

namespace facet::view {

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

/// A drag field over three doubles.
inline bool dragDouble3(const char* label, double* v, double speed, const char* format = "%.3f") {
    return ImGui::DragScalarN(label, ImGuiDataType_Double, v, 3, static_cast<float>(speed), nullptr,
                              nullptr, format);
}

}  // namespace facet::view
