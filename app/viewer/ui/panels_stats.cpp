#include "panels_stats.hpp"

#include <imgui.h>

#include <algorithm>

#include "viewer_app.hpp"

namespace facet::view {
namespace {

void drawCounts(const char* title, const RenderStats& s) {
    ImGui::Text("%s%zu triangles in, %zu culled, %zu clipped", title, s.trianglesIn,
                s.trianglesCulled, s.trianglesClipped);
    ImGui::Text("%zu rasterized, %zu fragments", s.trianglesRasterized, s.fragments);
    if (s.linesDrawn || s.pointsDrawn || s.normalsDrawn)
        ImGui::Text("%zu lines, %zu points, %zu normals", s.linesDrawn, s.pointsDrawn,
                    s.normalsDrawn);
}

void twinCounts(const GlStats& s) {
    ImGui::Text("twin: %zu triangles in, %.0f KB sent", s.trianglesIn,
                static_cast<double>(s.uploadBytes) / 1024.0);
    if (s.linesDrawn || s.pointsDrawn || s.normalsDrawn)
        ImGui::Text("twin: %zu lines, %zu points, %zu normals", s.linesDrawn, s.pointsDrawn,
                    s.normalsDrawn);
}

}  // namespace

void statsPanel(App& app) {
    // Medians over the last second or so: steadier than the last frame, still current.
    const StageTimes m = app.stats.history.recentMedian(60);
    ImGui::Text("%.1f fps, %.2f ms a frame (median of 60)", m.total > 0 ? 1000.0 / m.total : 0.0,
                m.total);
    const FramePlan plan = planFrame(app.model.rendererChoice, app.compare.settings.enabled);
    // A fixed-fit table sizes its columns to their text: wrapping (the side bar's) would let
    // them shrink to a word, so its text does not wrap.
    ImGui::PushTextWrapPos(-1.0f);
    if (ImGui::BeginTable("split", 2, ImGuiTableFlags_SizingFixedFit)) {
        auto row = [](const char* stage, double ms) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(stage);
            ImGui::TableNextColumn();
            ImGui::Text("%7.2f ms", ms);
        };
        if (plan.engine) {
            // One frame's total with its own stages (the frame of median engine time), so the
            // parts add up to the whole; what the stages leave is set-up and hand-over.
            const StageTimes e = app.stats.history.medianFrameBy(60, &StageTimes::render);
            row("CPU engine render", e.render);
            row("  clear", e.engineClear);
            row("  vertices", e.engineVertex);
            row("  raster + shade", e.engineRaster);
            row("  post passes", e.enginePost);
            row("  other", std::max(0.0, e.render - e.engineClear - e.engineVertex -
                                             e.engineRaster - e.enginePost));
        }
        if (plan.twin) {
            // Like the engine's time, the twin's ends with the picture in memory: its draw is
            // timed on the CPU clock up to glFinish, then the readback.
            const StageTimes t = app.stats.history.medianFrameBy(60, &StageTimes::twin);
            row(isLab(app.model.rendererChoice) ? "your pipeline render" : "OpenGL twin render",
                t.twin);
            row("  prepare + upload", t.twinUpload);
            row("  draw (to glFinish)", t.twinDraw);
            row("  readback + post", t.twinReadback);
        }
        if (plan.twoSides()) row("compare (diff)", m.compare);
        row("upload", m.upload);
        row("draw frame", m.draw);
        row("ui", m.ui);
        row("  drawing it", m.uiDraw);
        row("swap + events", m.present);
        if (plan.engine) row("waiting for engine", m.wait);
        ImGui::EndTable();
    }
    ImGui::PopTextWrapPos();
    ImGui::TextDisabled("a renderer's stages: its frame of median time");
    // Pipelined, the engine's time overlaps the drawing: the frame costs about the larger part.
    ImGui::Checkbox("engine on its own thread", &app.loop.pipelined);
    if (plan.twin && !app.loop.rendererLog.device.empty())
        ImGui::TextDisabled("OpenGL: %s", app.loop.rendererLog.device.c_str());
    if (plan.engine && plan.twin && app.loop.pipelined)
        ImGui::TextDisabled(
            "engine and twin run at once (llvmpipe: on the\nsame cores); untick for separate "
            "times");
    const std::vector<float>& plot = app.stats.history.plot;
    const float top = plot.empty() ? 1.0f : *std::max_element(plot.begin(), plot.end()) * 1.2f;
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "frame ms (max %.1f)", top / 1.2f);
    ImGui::PlotLines(
        "##history", plot.data(), static_cast<int>(plot.size()), 0, overlay, 0.0f, top,
        // An explicit width: -1 gave a 4-pixel strip here (ImGui 1.86).
        ImVec2(std::max(40.0f, ImGui::GetContentRegionAvail().x), 60.0f * app.work.scale));
    const Camera& c = app.model.scene.camera;
    ImGui::Text("frame %dx%d", c.width, c.height);
    if (plan.engineCompare) {
        drawCounts("left: ", app.compare.sides.leftStats);
        drawCounts("right: ", app.compare.sides.rightStats);
    } else if (plan.engine) {
        drawCounts(plan.twin ? "CPU: " : "", app.model.stats);
    }
    if (plan.twin) twinCounts(app.twin.stats);
}

}  // namespace facet::view
