// The pixel inspector's click, window and marker (inspector.hpp). The window follows RenderDoc's
// pixel history: the pixel's final colour beside the reference's and the ground truth's, a
// summary row per triangle that reached the pixel (green: written, red: failed the depth test,
// grey: excluded by coverage), and under each a fold with every stage's values.

#include "inspector.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

#include "facet/evaluation/ground_truth.hpp"
#include "viewer_app.hpp"
#include "workspace_ui.hpp"

namespace facet::view {
namespace {

const ImVec4 kPass(0.45f, 0.9f, 0.45f, 1.0f);
const ImVec4 kFail(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kExcluded(0.62f, 0.62f, 0.62f, 1.0f);
const ImVec4 kWarn(1.0f, 0.85f, 0.3f, 1.0f);

ImVec4 rgbaColor(std::uint32_t p) {
    return {static_cast<float>(p & 0xFFu) / 255.0f, static_cast<float>((p >> 8) & 0xFFu) / 255.0f,
            static_cast<float>((p >> 16) & 0xFFu) / 255.0f, 1.0f};
}

ImVec4 vecColor(const glm::vec3& c) {
    return {std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f),
            1.0f};
}

/// A colour square (no picker) with `label` beside it.
void swatch(const char* id, const ImVec4& c, const char* label) {
    ImGui::ColorButton(id, c, ImGuiColorEditFlags_NoPicker | ImGuiColorEditFlags_NoTooltip,
                       ImVec2(ImGui::GetFontSize() * 1.2f, ImGui::GetFontSize() * 1.2f));
    ImGui::SameLine();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
}

std::string depthText(double d) {
    if (std::isinf(d)) return "+inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.5g", d);
    return buf;
}

/// What happened to the fragment, and its colour in the lists.
const char* verdict(const InspectedFragment& f, ImVec4& colour) {
    if (f.coverage != CoverageResult::Covered) {
        colour = kExcluded;
        return f.onEdge ? "excluded: top-left rule" : "excluded: outside";
    }
    colour = f.passed ? kPass : kFail;
    if (!f.depthTested) return "written (no depth test)";
    return f.passed ? "depth PASS: written" : "depth FAIL: discarded";
}

void cell(const char* fmt, ...) IM_FMTARGS(1);
void cell(const char* fmt, ...) {
    ImGui::TableNextColumn();
    va_list args;
    va_start(args, fmt);
    ImGui::TextV(fmt, args);
    va_end(args);
}

constexpr ImGuiTableFlags kTable =
    ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;

void vertexTable(const InspectedFragment& f) {
    if (!ImGui::BeginTable("vertices", 6, kTable)) return;
    for (const char* h :
         {"", "index", "world", "clip x, y, w (= z)", "screen px", "fixed 1/256 px"})
        ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (int j = 0; j < 3; ++j) {
        const InspectedVertex& v = f.vertices[j];
        ImGui::TableNextRow();
        cell("%s", vertexName(j));
        cell("%u", v.index);
        cell("%.3f %.3f %.3f", v.world.x, v.world.y, v.world.z);
        // Clip z is the depth, as w is (camera.hpp): one column for both.
        cell("%.1f %.1f %.3f", v.clip.x, v.clip.y, v.clip.w);
        cell("%.3f %.3f", v.screen.x, v.screen.y);
        cell("%lld %lld", static_cast<long long>(v.fixedX), static_cast<long long>(v.fixedY));
    }
    ImGui::EndTable();
}

void edgeTable(const InspectedFragment& f) {
    if (!ImGui::BeginTable("edges", 4, kTable)) return;
    for (const char* h : {"edge", "E at centre (1/65536 px²)", "top-left", "centre"})
        ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const InspectedEdge& e : f.edges) {
        ImGui::TableNextRow();
        cell("%s->%s", vertexName(e.from), vertexName(e.to));
        cell("%lld", static_cast<long long>(e.value));
        cell("%s", e.topLeft ? "yes" : "no");
        ImGui::TableNextColumn();
        if (e.value == 0)
            ImGui::TextColored(e.inside ? kPass : kFail, "on it: %s", e.inside ? "in" : "out");
        else
            ImGui::TextColored(e.inside ? kPass : kFail, "%s", e.inside ? "inside" : "outside");
    }
    ImGui::EndTable();
}

void weightTable(const InspectedFragment& f) {
    if (!ImGui::BeginTable("weights", 4, kTable)) return;
    for (const char* h : {"weights", "v0", "v1", "v2"}) ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    auto row = [](const char* name, const glm::vec3& w) {
        ImGui::TableNextRow();
        cell("%s", name);
        for (int k = 0; k < 3; ++k) cell("%.5f", w[k]);
    };
    row("screen-linear", f.screenWeights);
    row("perspective", f.perspectiveWeights);
    row("used", f.weights);
    ImGui::EndTable();
}

void shadingDetails(const InspectedFragment& f) {
    if (f.hasColor) {
        char label[96];
        std::snprintf(label, sizeof label, "colour %.4f %.4f %.4f", f.color.r, f.color.g,
                      f.color.b);
        swatch("##vc", vecColor(f.color), label);
    }
    if (f.hasUv) ImGui::Text("uv %.5f %.5f", f.uv.x, f.uv.y);
    if (f.hasNormal) {
        ImGui::Text("normal %.4f %.4f %.4f", f.normal.x, f.normal.y, f.normal.z);
        ImGui::Text("position %.4f %.4f %.4f", f.position.x, f.position.y, f.position.z);
    }
    if (f.lit) {
        const InspectedLighting& l = f.lighting;
        ImGui::Text("n·l %.4f   n·h %.4f", l.nDotL, l.nDotH);
        ImGui::Text("I = ambient %.4f + diffuse %.4f + specular %.4f = %.4f", l.ambient, l.diffuse,
                    l.specular, l.intensity);
    }
    if (f.textured) {
        ImGui::Text("texture level of detail %.3f, %zu texel%s", f.lod, f.texels.size(),
                    f.texels.size() == 1 ? "" : "s");
        if (ImGui::BeginTable("texels", 4, kTable)) {
            for (const char* h : {"level", "texel", "colour", "weight"}) ImGui::TableSetupColumn(h);
            ImGui::TableHeadersRow();
            int i = 0;
            for (const InspectedTexel& t : f.texels) {
                ImGui::TableNextRow();
                cell("%d", t.level);
                cell("%d, %d", t.x, t.y);
                ImGui::TableNextColumn();
                char id[16], label[64];
                std::snprintf(id, sizeof id, "##t%d", i++);
                std::snprintf(label, sizeof label, "%.3f %.3f %.3f", t.color.r, t.color.g,
                              t.color.b);
                swatch(id, vecColor(t.color), label);
                cell("%.4f", t.weight);
            }
            ImGui::EndTable();
        }
    }
    char out[96];
    std::snprintf(out, sizeof out, "fragment colour %.4f %.4f %.4f = %s", f.shaded.r, f.shaded.g,
                  f.shaded.b, hexFromRgba(f.rgba).c_str());
    swatch("##out", rgbaColor(f.rgba), out);
}

void fragmentDetails(const InspectedFragment& f, int samples) {
    if (samples > 1)
        ImGui::Text("sample %d, %d of the pixel's %d×%d", f.sample % samples, f.sample / samples,
                    samples, samples);
    ImGui::Text("%s-facing%s", f.backFacing ? "back" : "front",
                f.clipped ? ", clipped (near plane or guard band): edges of the piece" : "");
    vertexTable(f);
    edgeTable(f);
    if (f.coverage != CoverageResult::Covered) {
        ImGui::TextColored(kExcluded, f.onEdge ? "The centre is on an edge that is neither top nor "
                                                 "left: the rule gives it to the neighbour."
                                               : "The centre is outside an edge.");
        return;
    }
    ImVec4 c;
    const char* v = verdict(f, c);
    ImGui::TextColored(c, "depth %s vs stored %s: %s", depthText(f.depth).c_str(),
                       depthText(f.storedDepth).c_str(), v);
    weightTable(f);
    shadingDetails(f);
}

/// The top of the window: the three colours side by side and what was found.
void summary(App& app, const InspectorState& s) {
    const PixelHistory& h = s.history;
    ImGui::Text("Pixel %d, %d", h.x, h.y);
    ImGui::SameLine();
    ImGui::TextDisabled("(%.0f ms)", s.ms);
    ImGui::SameLine();
    if (ImGui::SmallButton("Re-inspect")) inspectPixelAt(app, h.x, h.y);
    const AccuracyView now =
        accuracyView(app.model.scene, app.model.sceneVersion, app.model.settings);
    if (!(now == s.view))
        ImGui::TextColored(kWarn, "stale: the view or settings changed since (Re-inspect)");
    if (app.model.rendererChoice != RendererChoice::Cpu || app.compare.settings.enabled)
        ImGui::TextDisabled("(the CPU engine's frame of these settings is inspected)");

    std::string label =
        "final " + hexFromRgba(h.finalColor) + "   depth " + depthText(h.finalDepth);
    swatch("##final", rgbaColor(h.finalColor), label.c_str());
    // Your pipeline's pixel (the lab's last frame) beside facet's, when it is drawn.
    const Framebuffer& mine = app.twin.frame;
    if (isLab(app.model.rendererChoice) && h.x >= 0 && h.y >= 0 && h.x < mine.width &&
        h.y < mine.height) {
        const std::size_t i = mine.index(h.x, h.y);
        label =
            "your pipeline " + hexFromRgba(mine.color[i]) + "   depth " + depthText(mine.depth[i]);
        swatch("##lab", rgbaColor(mine.color[i]), label.c_str());
    }
    if (h.hasReference) {
        label = "reference " + hexFromRgba(h.referenceRgba) + "   depth " +
                depthText(h.referenceDepth) +
                (h.referenceAmbiguous ? "   (ambiguous, rule 8)" : "");
        swatch("##ref", rgbaColor(h.referenceRgba), label.c_str());
    }
    if (s.truth.width == 1) {
        char buf[128];
        const glm::vec3& t = s.truth.color[0];
        std::snprintf(buf, sizeof buf, "ground truth %d×%d: %.3f %.3f %.3f, %.0f%% covered",
                      s.truth.samples, s.truth.samples, t.r, t.g, t.b, 100.0 * s.truth.coverage[0]);
        swatch("##truth", vecColor(t), buf);
    }
    for (const std::string& note : h.notes) ImGui::TextColored(kWarn, "%s", note.c_str());
}

/// One row per entry, coloured by its fate; a click opens its fold below.
void historyTable(const InspectorState& s, int& openRow) {
    const PixelHistory& h = s.history;
    if (!ImGui::BeginTable("history", 5, kTable | ImGuiTableFlags_ScrollY,
                           ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() *
                                                static_cast<float>(std::min<std::size_t>(
                                                    h.fragments.size() + 1, 7)) +
                                            4.0f)))
        return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* c : {"#", "triangle", "result", "depth", "colour"}) ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < h.fragments.size(); ++i) {
        const InspectedFragment& f = h.fragments[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char id[32];
        std::snprintf(id, sizeof id, "%zu##row", i + 1);
        if (ImGui::Selectable(id, openRow == static_cast<int>(i),
                              ImGuiSelectableFlags_SpanAllColumns))
            openRow = static_cast<int>(i);
        cell("%zu", f.triangle);
        ImVec4 c;
        const char* v = verdict(f, c);
        ImGui::TableNextColumn();
        ImGui::TextColored(c, "%s", v);
        const bool covered = f.coverage == CoverageResult::Covered;
        cell("%s", covered ? depthText(f.depth).c_str() : "");
        ImGui::TableNextColumn();
        if (covered) {
            std::snprintf(id, sizeof id, "##c%zu", i);
            ImGui::ColorButton(id, rgbaColor(f.rgba), ImGuiColorEditFlags_NoTooltip,
                               ImVec2(ImGui::GetFontSize() * 2.0f, ImGui::GetFontSize() * 0.9f));
        }
    }
    ImGui::EndTable();
}

/// The square around the inspected pixel on the image (over the frame, under the windows).
void drawMarker(const App& app, const PixelHistory& h) {
    const Camera& c = app.model.scene.camera;
    if (c.width <= 0 || c.height <= 0 || app.view.w <= 0) return;
    const float sx = static_cast<float>(app.view.w) / static_cast<float>(c.width);
    const float sy = static_cast<float>(app.view.h) / static_cast<float>(c.height);
    const float x0 = static_cast<float>(app.view.x) + static_cast<float>(h.x) * sx;
    const float y0 = static_cast<float>(app.view.y) + static_cast<float>(h.y) * sy;
    const ImVec2 centre(x0 + 0.5f * sx, y0 + 0.5f * sy);
    const float r = std::max(6.0f * app.work.scale, 0.5f * std::max(sx, sy) + 2.0f);
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 dark = IM_COL32(0, 0, 0, 220), bright = IM_COL32(255, 230, 60, 255);
    const ImVec2 a(centre.x - r, centre.y - r), b(centre.x + r, centre.y + r);
    draw->AddRect(a, b, dark, 0.0f, 0, 4.0f);
    draw->AddRect(a, b, bright, 0.0f, 0, 2.0f);
    // Ticks pointing at the pixel from outside, so a small marker is found on a busy picture.
    const float t = 2.5f * r;
    const ImVec2 ends[4][2] = {{{centre.x - t, centre.y}, {centre.x - r - 2, centre.y}},
                               {{centre.x + r + 2, centre.y}, {centre.x + t, centre.y}},
                               {{centre.x, centre.y - t}, {centre.x, centre.y - r - 2}},
                               {{centre.x, centre.y + r + 2}, {centre.x, centre.y + t}}};
    for (const auto& e : ends) {
        draw->AddLine(e[0], e[1], dark, 4.0f);
        draw->AddLine(e[0], e[1], bright, 2.0f);
    }
}

}  // namespace

void inspectPixelAt(App& app, int x, int y) {
    InspectorState& s = app.inspector;
    const auto t0 = std::chrono::steady_clock::now();
    s.history = inspectPixel(app.model.scene, app.model.settings, x, y);
    // 8×8 for one pixel costs what 64 reference pixels cost: no need for the Compare panel's
    // coarser setting.
    s.truth = renderGroundTruthPixel(app.model.scene, app.model.settings, x, y);
    s.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    s.view = accuracyView(app.model.scene, app.model.sceneVersion, app.model.settings);
    s.valid = true;
    s.open = true;
    s.placed = false;
    ++s.clicks;
    std::printf("inspected pixel %d %d: %zu entries\n", x, y, s.history.fragments.size());
    std::fflush(stdout);
}

bool inspectorClick(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || !io.KeyShift || io.KeyCtrl ||
        !ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        return false;
    const Camera& c = app.model.scene.camera;
    const glm::dvec2 p = windowToFrame(app.view, c.width, c.height, {io.MousePos.x, io.MousePos.y});
    const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
    if (x < 0 || y < 0 || x >= c.width || y >= c.height) return false;
    inspectPixelAt(app, x, y);
    return true;
}

void inspectorWindow(App& app) {
    InspectorState& s = app.inspector;
    if (!s.open || !s.valid) return;
    drawMarker(app, s.history);
    // Beside the pixel, on the image's other half, so the marker stays in sight.
    const Rect& image = app.work.layout.image;
    const float scale = app.work.scale;
    const float margin = 10.0f * scale;
    const float width = std::min(600.0f * scale, static_cast<float>(image.w) - 2.0f * margin);
    const float height = static_cast<float>(image.h) - 2.0f * margin;
    const Camera& c = app.model.scene.camera;
    const bool pixelOnRight = c.width > 0 && s.history.x * 2 >= c.width;
    if (!s.placed) {
        const float x = pixelOnRight ? static_cast<float>(image.x) + margin
                                     : static_cast<float>(image.x + image.w) - margin - width;
        ImGui::SetNextWindowPos(ImVec2(x, static_cast<float>(image.y) + margin), ImGuiCond_Always);
        // Its content's height (0: fit), at most the image area's: a background pixel's five
        // lines get a small window.
        ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
        s.placed = true;
        s.openRow = -1;
        for (std::size_t i = 0; i < s.history.fragments.size() && s.openRow < 0; ++i)
            if (s.history.fragments[i].coverage == CoverageResult::Covered)
                s.openRow = static_cast<int>(i);
        if (s.openRow < 0 && !s.history.fragments.empty()) s.openRow = 0;
    }
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(std::min(width, 200.0f * scale), 0.0f),
        ImVec2(static_cast<float>(image.w) - 2.0f * margin, height));
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("Pixel inspector", &s.open, ImGuiWindowFlags_NoSavedSettings)) {
        noteWindow(app.work, "inspector");
        summary(app, s);
        const PixelHistory& h = s.history;
        std::size_t covered = 0;
        for (const InspectedFragment& f : h.fragments)
            covered += f.coverage == CoverageResult::Covered ? 1 : 0;
        ImGui::Separator();
        ImGui::Text("%zu triangle%s reach the pixel's box: %zu fragment%s, %zu excluded",
                    h.fragments.size(), h.fragments.size() == 1 ? "" : "s", covered,
                    covered == 1 ? "" : "s", h.fragments.size() - covered);
        if (h.fragments.empty()) {
            ImGui::TextDisabled("Nothing drew here: the pixel keeps the background.");
        } else {
            historyTable(s, s.openRow);
            if (s.openRow >= 0 && s.openRow < static_cast<int>(h.fragments.size())) {
                const InspectedFragment& f = h.fragments[static_cast<std::size_t>(s.openRow)];
                ImVec4 colour;
                const char* v = verdict(f, colour);
                ImGui::Separator();
                ImGui::TextColored(colour, "#%d  triangle %zu: %s", s.openRow + 1, f.triangle, v);
                ImGui::BeginChild("details", ImVec2(0.0f, 0.0f), false);
                fragmentDetails(f, h.samples);
                ImGui::EndChild();
            }
        }
    }
    ImGui::End();
}

std::string inspectorStateText(const App& app) {
    const InspectorState& s = app.inspector;
    std::ostringstream out;
    out << "inspector " << (s.open && s.valid ? 1 : 0) << " " << s.clicks << "\n";
    if (!s.valid) return out.str();
    const PixelHistory& h = s.history;
    std::size_t covered = 0, passed = 0;
    for (const InspectedFragment& f : h.fragments) {
        covered += f.coverage == CoverageResult::Covered ? 1 : 0;
        passed += f.coverage == CoverageResult::Covered && f.passed ? 1 : 0;
    }
    out << "inspector_pixel " << h.x << " " << h.y << "\n";
    out << "inspector_entries " << h.fragments.size() << " " << covered << " " << passed << "\n";
    out << "inspector_final " << hexFromRgba(h.finalColor) << "\n";
    return out.str();
}

}  // namespace facet::view
