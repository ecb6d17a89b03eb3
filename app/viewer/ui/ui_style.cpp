// A 4K laptop screen reports a content scale of 2: the 13-pixel font becomes 26 pixels, paddings
// and the side bar twice as wide. Windows and pop-ups are opaque: a combo's list over the
// picture was unreadable at 95 % opacity.

#include "ui_style.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace facet::view {

void applyUiStyle(float scale, bool rebuild) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig font;
    // The built-in font is a pixel font: whole pixel sizes keep it crisp.
    font.SizePixels = std::max(8.0f, std::round(13.0f * scale));
    io.Fonts->AddFontDefault(&font);
    if (rebuild) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    style.Colors[ImGuiCol_PopupBg].w = 1.0f;
    style.Colors[ImGuiCol_ChildBg].w = 0.0f;
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
}

float windowUiScale(GLFWwindow* window, double uiScaleOption) {
    if (uiScaleOption > 0.0) return static_cast<float>(uiScaleOption);
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window, &sx, &sy);
    // Where window coordinates are already scaled points (macOS), ImGui works in points: only
    // the rest of the content scale applies.
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window, &ww, &wh);
    glfwGetFramebufferSize(window, &fw, &fh);
    const float framebufferScale =
        ww > 0 && fw > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
    const float scale = std::max(sx, sy) / std::max(framebufferScale, 1e-3f);
    return std::clamp(std::isfinite(scale) ? scale : 1.0f, 0.5f, 4.0f);
}

}  // namespace facet::view
