// Pixels of the side bar and of the frame never overlap: the frame is rendered for the image
// area (placeFrame) after the side bar took its width.

#include "workspace_ui.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "inspector.hpp"
#include "key_actions.hpp"
#include "light_input.hpp"
#include "panel_widgets.hpp"
#include "panels_accuracy.hpp"
#include "panels_camera.hpp"
#include "panels_compare.hpp"
#include "panels_light.hpp"
#include "panels_render.hpp"
#include "panels_scene.hpp"
#include "panels_screenshot.hpp"
#include "panels_stats.hpp"
#include "popups.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

/// Where the next overlay windows go: flags for a box that takes no input and no focus.
constexpr ImGuiWindowFlags kOverlay =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;

SidebarState sidebarState(const App& app) {
    if (!app.work.showPanels) return SidebarState::Hidden;
    const WorkspaceUi& w = app.work;
    // A narrow window starts with the strip, until << or >> says otherwise.
    const bool narrow = !w.keepSidebar && autoCollapsed(app.fbWidth, w.scale);
    const bool collapsed = w.collapseChosen ? w.collapsed : narrow || w.collapsed;
    return collapsed ? SidebarState::Collapsed : SidebarState::Open;
}

/// The title row: the scene's name, help and collapse buttons; then the view toggles.
void sidebarHeader(App& app) {
    WorkspaceUi& w = app.work;
    const float button = ImGui::GetFrameHeight();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("facet");
    ImGui::SameLine();
    // The file name, cut at the front ("...name") where it would run under the buttons.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttons =
        ImGui::GetWindowContentRegionMax().x - 2.0f * button - style.ItemSpacing.x;
    const float room = buttons - style.ItemSpacing.x - ImGui::GetCursorPosX();
    std::string name = std::filesystem::path(app.model.scene.path).filename().string();
    if (ImGui::CalcTextSize(name.c_str()).x > room) {
        while (!name.empty() && ImGui::CalcTextSize(("..." + name).c_str()).x > room)
            name.erase(0, 1);
        name = "..." + name;
    }
    ImGui::TextDisabled("%s", name.c_str());
    ImGui::SameLine(buttons);
    if (ImGui::Button("?", ImVec2(button, button))) w.help = !w.help;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Keys and mouse (F1 or ?)");
    ImGui::SameLine();
    if (ImGui::Button("<<", ImVec2(button, button))) w.collapsed = w.collapseChosen = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Collapse the side bar (Tab hides it)");
    ImGui::Checkbox("stats (S)", &w.statsOverlay);
    sameLineIfFits(checkWidth("light (M)"));
    ImGui::Checkbox("light (M)", &app.light.shown);
    sameLineIfFits(checkWidth("fullscreen"));
    bool full = w.fullscreen;
    if (ImGui::Checkbox("fullscreen", &full)) toggleFullscreen(app);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("F11");
    ImGui::Separator();
}

/// Hands the current window's background (Begin'd after SetNextWindowBgAlpha(0), so ImGui draws
/// no quad for it; ImGuiWindowFlags_NoBackground would drop the border too) to GlFrame, which
/// fills it with a clear: the same pixels (WindowBg is opaque, applyUiStyle) for a fraction of
/// what llvmpipe spends shading and blending ImGui's quad over them.
void leaveBackgroundToGl(App& app) {
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const ImVec2 p = ImGui::GetWindowPos();
    const ImVec2 s = ImGui::GetWindowSize();
    // The pixels whose centres the rectangle covers, as the rasterizer would fill them.
    const auto edge = [](float v) { return static_cast<int>(std::ceil(v - 0.5f)); };
    const int x0 = edge(p.x * scale.x), x1 = edge((p.x + s.x) * scale.x);
    const int y0 = edge(p.y * scale.y), y1 = edge((p.y + s.y) * scale.y);
    app.work.backdrop = {{x0, y0, x1 - x0, y1 - y0}, ImGui::GetColorU32(ImGuiCol_WindowBg)};
}

void sidebar(App& app) {
    WorkspaceUi& w = app.work;
    const Rect& bar = w.layout.sidebar;
    const float scale = w.scale;
    const float height = static_cast<float>(bar.h);
    const int imageShareWidth = static_cast<int>(ImGui::GetIO().DisplaySize.x);
    const float least = static_cast<float>(clampSidebarWidth(0, imageShareWidth, scale));
    const float most =
        std::max(least, static_cast<float>(clampSidebarWidth(1 << 20, imageShareWidth, scale)));
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    // The height is the window's, the width the user's (dragging the right edge), within limits.
    ImGui::SetNextWindowSizeConstraints(ImVec2(least, height), ImVec2(most, height));
    // Set every frame (the width follows the window until the user drags the edge); a drag
    // still wins, as ImGui applies it after this.
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(bar.w), height), ImGuiCond_Always);
    w.sidebarSizeSet = false;
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    ImGui::SetNextWindowBgAlpha(0.0f);  // GlFrame fills it (leaveBackgroundToGl)
    const bool open = ImGui::Begin("facet##sidebar", nullptr, flags);
    ImGui::PopStyleVar();
    leaveBackgroundToGl(app);
    if (open) {
        noteWindow(app.work, "sidebar");
        const int now = static_cast<int>(ImGui::GetWindowWidth());
        if (now != bar.w) {  // the user dragged the edge: that width from now on
            w.sidebarWidth = now;
            w.sidebarDragged = true;
        }
        sidebarHeader(app);
        ImGui::PushItemWidth(-130.0f * scale);  // room for the labels on the right
        // Text wraps at the side bar's edge: a narrow bar (an 800-pixel window) shows every
        // word of a note on two lines instead of cutting it off.
        ImGui::PushTextWrapPos(0.0f);
        if (ImGui::CollapsingHeader("Scene")) scenePanel(app);
        // Open at start: Render and Camera; Compare alone when the viewer starts comparing two
        // interpolations; Render and Compare (the renderer, then the numbers) side by side.
        const bool split = app.options.renderer == "split";
        auto openIf = [](bool on) {
            return on ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None;
        };
        if (ImGui::CollapsingHeader("Render", openIf(!app.options.compare)))
            renderPanel(app.model, app.compare.settings, app.twin, app.popups);
        if (ImGui::CollapsingHeader("Camera", openIf(!app.options.compare && !split)))
            cameraPanel(app.model, app.loop.vsync);
        if (ImGui::CollapsingHeader("Light and material")) lightPanel(app.model);
        if (ImGui::CollapsingHeader("Texture")) texturePanel(app);
        if (ImGui::CollapsingHeader("Compare", openIf(app.options.compare || split)))
            comparePanel(app.compare, app.model, app.accuracy);
        if (ImGui::CollapsingHeader("Screenshot")) screenshotPanel(app.screenshot);
        if (ImGui::CollapsingHeader("Stats")) statsPanel(app);
        ImGui::PopTextWrapPos();
        ImGui::PopItemWidth();
        ImGui::TextDisabled("F1 or ?: every key and mouse action");
    }
    ImGui::End();
}

/// The collapsed side bar: a strip with the button that opens it again.
void collapsedStrip(App& app) {
    const Rect& bar = app.work.layout.sidebar;
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(bar.w), static_cast<float>(bar.h)),
                             ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2.0f, 4.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::SetNextWindowBgAlpha(0.0f);  // GlFrame fills it (leaveBackgroundToGl)
    const bool open = ImGui::Begin("##sidebar-strip", nullptr, flags);
    leaveBackgroundToGl(app);
    if (open) {
        noteWindow(app.work, "sidebar");
        if (ImGui::Button(">>", ImVec2(-1.0f, 0.0f))) {
            app.work.collapsed = false;
            app.work.collapseChosen = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open the side bar");
        if (ImGui::Button("?", ImVec2(-1.0f, 0.0f))) app.work.help = !app.work.help;
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

/// fps and the renderers' times in the image area's top right corner; follows resizes.
void statsOverlay(App& app) {
    const Rect& image = app.work.layout.image;
    const float margin = 8.0f * app.work.scale;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(image.x + image.w) - margin,
                                   static_cast<float>(image.y) + margin),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.65f);
    if (ImGui::Begin("##stats-overlay", nullptr, kOverlay)) {
        noteWindow(app.work, "stats");
        const StageTimes m = app.stats.history.recentMedian(60);
        ImGui::Text("%.1f fps  %.2f ms", m.total > 0.0 ? 1000.0 / m.total : 0.0, m.total);
        const FramePlan plan = planFrame(app.model.rendererChoice, app.compare.settings.enabled);
        const Camera& c = app.model.scene.camera;
        // A small image area gets the first line only: the box never hides much of the picture.
        if (static_cast<float>(image.w) >= 600.0f * app.work.scale) {
            if (plan.engine) ImGui::Text("CPU engine %.2f ms", m.render);
            if (plan.twin)
                ImGui::Text("%s %.2f ms",
                            isLab(app.model.rendererChoice) ? "Your pipeline" : "OpenGL twin",
                            m.twin);
            ImGui::TextDisabled("%dx%d  (S hides)", c.width, c.height);
        }
    }
    ImGui::End();
}

/// Why the engine drew nothing (a frame too large for memory, a camera it cannot use), in the
/// middle of the image area for as long as it holds: the image under it is the last one drawn.
void refusedOverlay(App& app) {
    const std::string& why = app.model.refused;
    if (why.empty()) return;
    const Rect& image = app.work.layout.image;
    ImGui::SetNextWindowPos(
        ImVec2(static_cast<float>(image.x) + 0.5f * static_cast<float>(image.w),
               static_cast<float>(image.y) + 0.5f * static_cast<float>(image.h)),
        ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                        ImVec2(0.8f * static_cast<float>(image.w), 1e6f));
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("##refused", nullptr, kOverlay)) {
        noteWindow(app.work, "refused");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "Not drawn");
        ImGui::TextUnformatted(why.c_str());
        ImGui::TextDisabled("The image is the last one drawn; change the size or settings.");
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

/// The notice (a saved screenshot's path) at the bottom of the image area, for a few seconds.
void noticeOverlay(App& app) {
    const Notice& n = app.work.notice;
    if (n.text.empty() || std::chrono::steady_clock::now() >= n.until) return;
    const Rect& image = app.work.layout.image;
    const float margin = 12.0f * app.work.scale;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(image.x) + 0.5f * static_cast<float>(image.w),
                                   static_cast<float>(image.y + image.h) - margin),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("##notice", nullptr, kOverlay)) {
        noteWindow(app.work, "notice");
        ImGui::TextUnformatted(n.text.c_str());
    }
    ImGui::End();
}

/// One table of two columns: keys (or gestures) in colour, what they do.
void helpTable(const char* id, const std::vector<HelpRow>& rows, ImVec4 colour) {
    const ImGuiTableFlags table = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg;
    if (!ImGui::BeginTable(id, 2, table)) return;
    for (const HelpRow& r : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored(colour, "%s", r.keys.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%s  ", r.what.c_str());
    }
    ImGui::EndTable();
}

/// Every key and mouse action, from the key map (the same table the keys dispatch through):
/// keys and mouse side by side when the image area is wide enough, else one above the other;
/// centred on the image area when it fits there, else on the window, never larger than it.
void helpOverlay(App& app) {
    WorkspaceUi& w = app.work;
    const Rect& image = w.layout.image;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float margin = 4.0f * w.scale;
    std::vector<HelpRow> mouse;
    for (const MouseBinding& m : mouseBindings())
        mouse.push_back({std::string(m.gesture), std::string(m.what)});
    const bool fitsImage = w.helpSize.x > 0.0f &&
                           w.helpSize.x <= static_cast<float>(image.w) - 2.0f * margin &&
                           w.helpSize.y <= static_cast<float>(image.h) - 2.0f * margin;
    const ImVec2 centre =
        fitsImage ? ImVec2(static_cast<float>(image.x) + 0.5f * static_cast<float>(image.w),
                           static_cast<float>(image.y) + 0.5f * static_cast<float>(image.h))
                  : ImVec2(0.5f * display.x, 0.5f * display.y);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(0.0f, 0.0f), ImVec2(display.x - 2.0f * margin, display.y - 2.0f * margin));
    ImGui::SetNextWindowBgAlpha(0.96f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;
    if (ImGui::Begin("Keys and mouse (F1, ? or Esc closes)", &w.help, flags)) {
        noteWindow(app.work, "help");
        const std::vector<HelpRow> keys = helpRows();
        const ImVec4 keyColour(1, 0.85f, 0.4f, 1), mouseColour(0.5f, 0.8f, 1, 1);
        // Side by side when both tables fit the window's width next to each other.
        const ImGuiStyle& style = ImGui::GetStyle();
        auto widest = [](const std::vector<HelpRow>& rows) {
            float a = 0.0f, b = 0.0f;
            for (const HelpRow& r : rows) {
                a = std::max(a, ImGui::CalcTextSize(r.keys.c_str()).x);
                b = std::max(b, ImGui::CalcTextSize((r.what + "  ").c_str()).x);
            }
            return a + b;
        };
        const float wide = widest(keys) + widest(mouse) + 8.0f * style.CellPadding.x +
                           style.ItemSpacing.x + 2.0f * style.WindowPadding.x;
        const bool sideBySide = wide <= display.x - 2.0f * margin;
        if (sideBySide) {
            ImGui::BeginGroup();
            helpTable("keys", keys, keyColour);
            ImGui::EndGroup();
            ImGui::SameLine();
            ImGui::BeginGroup();
            helpTable("mouse", mouse, mouseColour);
            ImGui::EndGroup();
        } else {
            helpTable("keys", keys, keyColour);
            ImGui::Separator();
            helpTable("mouse", mouse, mouseColour);
        }
        ImGui::TextDisabled("Every action is also in the side bar (Tab shows it).");
        const ImVec2 size = ImGui::GetWindowSize();
        w.helpSize = {size.x, size.y};
        w.helpScrolls = ImGui::GetScrollMaxY() > 0.0f;
    }
    ImGui::End();
}

}  // namespace

void noteWindow(WorkspaceUi& work, const char* name) {
    const ImVec2 p = ImGui::GetWindowPos();
    const ImVec2 s = ImGui::GetWindowSize();
    work.drawn[name] = {static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(s.x),
                        static_cast<int>(s.y)};
}

void placeFrame(App& app) {
    WorkspaceUi& w = app.work;
    if (w.sidebarWidth <= 0) w.sidebarWidth = static_cast<int>(kSidebarWidth * w.scale + 0.5f);
    if (w.keepWidthAt < 0) w.keepWidthAt = app.fbWidth;
    if (w.keepWidthAt > 0 && app.fbWidth != w.keepWidthAt) w.keepWidthAt = 0;  // resized
    w.keepSidebar = w.keepWidthAt > 0;
    const int width =
        w.sidebarDragged || w.keepSidebar ? w.sidebarWidth : autoSidebarWidth(app.fbWidth, w.scale);
    w.sidebarState = sidebarState(app);
    w.layout = workspaceLayout(app.fbWidth, app.fbHeight, width, w.sidebarState, w.scale);
    const Rect& image = w.layout.image;
    const Camera& camera = app.model.prepareFrame(image.w, image.h);
    app.view = frameRect(w.layout, camera.width, camera.height);
}

void drawPanels(App& app) {
    app.work.drawn.clear();
    app.work.backdrop = {};
    drawLightMarker(app);
    if (planFrame(app.model.rendererChoice, app.compare.settings.enabled).twin ||
        app.compare.settings.enabled)
        compareOverlay(app.compare, app.model.rendererChoice, app.view, app.work.scale);
    sceneFileEvents(app);
    errorPopup(app.popups);
    quitPopup(app);
    saveDialog(app);
    switch (sidebarState(app)) {
        case SidebarState::Open:
            sidebar(app);
            break;
        case SidebarState::Collapsed:
            collapsedStrip(app);
            break;
        case SidebarState::Hidden:
            break;
    }
    if (app.work.statsOverlay) statsOverlay(app);
    accuracyWindow(app.accuracy, app.model, app.work);
    inspectorWindow(app);
    noticeOverlay(app);
    refusedOverlay(app);
    if (app.work.help) helpOverlay(app);
}

void showNotice(WorkspaceUi& work, const std::string& text) {
    work.notice.text = text;
    work.notice.until = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(kNoticeSeconds));
}

}  // namespace facet::view
