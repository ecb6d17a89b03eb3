#include "light_input.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "light_marker.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

/// Window pixels around the marker's centre that grab it, and the inset of a marker shown on
/// the frame's border (its light off-screen or behind the camera).
constexpr float kGrabRadius = 12.0f;
constexpr double kBorderInset = 16.0;

ImVec2 toWindow(const App& app, glm::dvec2 pixel) {
    const Camera& c = app.model.scene.camera;
    const Rect& v = app.view;
    return {static_cast<float>(v.x + pixel.x * v.w / std::max(1, c.width)),
            static_cast<float>(v.y + pixel.y * v.h / std::max(1, c.height))};
}

LightMarker marker(const App& app) {
    return lightMarker(app.model.scene.camera, lightPosition(app), app.model.orbit.target,
                       app.model.orbit.distance);
}

/// Where the marker is drawn, in frame pixels (on the border when the light is off-screen).
glm::dvec2 placeOf(const App& app, const LightMarker& m) {
    const Camera& c = app.model.scene.camera;
    const double inset = kBorderInset * app.work.scale * c.width / std::max(1, app.view.w);
    return markerPlace(m, c.width, c.height, inset);
}

}  // namespace

glm::dvec4& lightPosition(App& app) {
    return app.model.scene.lighting.light.position;
}

const glm::dvec4& lightPosition(const App& app) {
    return lightPosition(const_cast<App&>(app));
}

glm::dvec2 lightMarkerPlace(const App& app) {
    return placeOf(app, marker(app));
}

bool lightMarkerShown(const App& app) {
    return app.light.shown && app.model.settings.lighting != Lighting::Off;
}

bool startLightDrag(App& app) {
    if (!lightMarkerShown(app)) return false;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.KeyCtrl) {
        app.light.drag = LightDrag::Turn;
        return true;
    }
    const ImVec2 p = toWindow(app, placeOf(app, marker(app)));
    const float dx = io.MousePos.x - p.x, dy = io.MousePos.y - p.y;
    const float grab = kGrabRadius * app.work.scale;
    if (dx * dx + dy * dy > grab * grab) return false;
    app.light.drag = LightDrag::Follow;
    return true;
}

void dragLightStep(App& app) {
    LightMarkerState& w = app.light;
    if (w.drag == LightDrag::None) return;
    const ImGuiIO& io = ImGui::GetIO();
    const Camera& camera = app.model.scene.camera;
    glm::dvec4& light = lightPosition(app);
    if (w.drag == LightDrag::Follow) {
        const glm::dvec2 pixel =
            windowToFrame(app.view, camera.width, camera.height, {io.MousePos.x, io.MousePos.y});
        light = dragLight(camera, light, app.model.orbit.target, app.model.orbit.distance, pixel);
    } else if ((io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) &&
               !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {  // the travel before the press
                                                                 // is no turn
        light = turnLight(camera, light, app.model.orbit.target, app.model.orbit.distance,
                          io.MouseDelta.x, io.MouseDelta.y);
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) w.drag = LightDrag::None;
}

void drawLightMarker(App& app) {
    app.light.note.clear();
    app.light.noteRect = {};
    if (!lightMarkerShown(app)) return;
    const LightMarker m = marker(app);
    const Camera& c = app.model.scene.camera;
    const bool inFrame = markerInFrame(m, c.width, c.height);
    const ImVec2 p = toWindow(app, placeOf(app, m));
    ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the frame, under the windows
    const float s = app.work.scale;
    const bool active = app.light.drag != LightDrag::None;
    const ImU32 fill = active ? IM_COL32(255, 240, 120, 255) : IM_COL32(255, 215, 60, 255);
    const ImU32 edge = IM_COL32(0, 0, 0, 220);
    if (!inFrame) {
        // Off-screen: on the border, a pointer outwards towards where the light is.
        const ImVec2 centre = toWindow(app, {0.5 * c.width, 0.5 * c.height});
        const float dx = p.x - centre.x, dy = p.y - centre.y;
        const float len = std::max(1e-3f, std::sqrt(dx * dx + dy * dy));
        const float ux = dx / len, uy = dy / len, h = 16.0f * s, half = 6.0f * s;
        const ImVec2 tip(p.x + ux * h, p.y + uy * h);
        const ImVec2 base(p.x + ux * 8.0f * s, p.y + uy * 8.0f * s);
        draw->AddTriangleFilled(tip, ImVec2(base.x - uy * half, base.y + ux * half),
                                ImVec2(base.x + uy * half, base.y - ux * half), fill);
        // Said in words, beside it on the image's side: a marker on the border is no light
        // sitting there.
        app.light.note = "light off screen: drag the sun in";
        const ImVec2 size = ImGui::CalcTextSize(app.light.note.c_str());
        const float gap = 16.0f * s;
        ImVec2 at(p.x - ux * gap - 0.5f * size.x * (1.0f + ux),
                  p.y - uy * gap - 0.5f * size.y * (1.0f + uy));
        const Rect& v = app.view;
        at.x = std::clamp(at.x, static_cast<float>(v.x) + 2.0f,
                          std::max(static_cast<float>(v.x) + 2.0f,
                                   static_cast<float>(v.x + v.w) - size.x - 2.0f));
        at.y = std::clamp(at.y, static_cast<float>(v.y) + 2.0f,
                          std::max(static_cast<float>(v.y) + 2.0f,
                                   static_cast<float>(v.y + v.h) - size.y - 2.0f));
        draw->AddRectFilled(ImVec2(at.x - 3.0f * s, at.y - 1.0f * s),
                            ImVec2(at.x + size.x + 3.0f * s, at.y + size.y + 1.0f * s),
                            IM_COL32(0, 0, 0, 170), 3.0f * s);
        draw->AddText(at, fill, app.light.note.c_str());
        app.light.noteRect = {
            static_cast<int>(at.x - 3.0f * s) - 1, static_cast<int>(at.y - 1.0f * s) - 1,
            static_cast<int>(size.x + 6.0f * s) + 3, static_cast<int>(size.y + 2.0f * s) + 3};
    } else if (m.directional && m.aimVisible) {
        // The way the light travels: from the handle to the look-at point, head at the end.
        const ImVec2 a = toWindow(app, m.aim);
        const float dx = a.x - p.x, dy = a.y - p.y;
        const float len = std::sqrt(dx * dx + dy * dy);
        if (len > 16.0f * s) {
            const float ux = dx / len, uy = dy / len;
            const ImVec2 tip(p.x + ux * (len - 4.0f * s), p.y + uy * (len - 4.0f * s));
            draw->AddLine(p, tip, edge, 4.0f * s);
            draw->AddLine(p, tip, fill, 2.0f * s);
            const float h = 9.0f * s, half = 5.0f * s;
            const ImVec2 b(tip.x - ux * h, tip.y - uy * h);
            draw->AddTriangleFilled(tip, ImVec2(b.x - uy * half, b.y + ux * half),
                                    ImVec2(b.x + uy * half, b.y - ux * half), fill);
        }
    }
    // A small sun: rays, a disc, an outline (readable on white and on black).
    for (int i = 0; i < 8; ++i) {
        const float a = static_cast<float>(i) * 0.785398f;
        const ImVec2 r0(p.x + std::cos(a) * 8.0f * s, p.y + std::sin(a) * 8.0f * s);
        const ImVec2 r1(p.x + std::cos(a) * 12.0f * s, p.y + std::sin(a) * 12.0f * s);
        draw->AddLine(r0, r1, edge, 3.0f * s);
        draw->AddLine(r0, r1, fill, 1.5f * s);
    }
    draw->AddCircleFilled(p, 6.0f * s, fill);
    draw->AddCircle(p, 6.0f * s, edge, 0, 1.5f * s);
}

}  // namespace facet::view
