#include "panels_accuracy.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "viewer_model.hpp"
#include "workspace_ui.hpp"

namespace facet::view {
namespace {

const ImVec4 kGreen(0.45f, 0.85f, 0.45f, 1.0f);
const ImVec4 kYellow(0.95f, 0.8f, 0.3f, 1.0f);

void cell(const char* format, double value) {
    ImGui::TableNextColumn();
    if (std::isinf(value))
        ImGui::TextUnformatted("inf");
    else
        ImGui::Text(format, value);
}

/// The measured methods, one row each; returns the row clicked, or -1.
int methodTable(const AccuracyReport& report, const RenderSettings& current) {
    int clicked = -1;
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("accuracy", 8, flags)) return clicked;
    for (const char* name : {"", "axis", "method", "ms", "RMSE", "PSNR", "max", ">2 LSB"})
        ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        const AccuracyRow& r = report.rows[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushID(static_cast<int>(i));
        // The row the viewer draws now is highlighted; the Pareto front is starred.
        if (r.pareto) ImGui::PushStyleColor(ImGuiCol_Text, kGreen);
        if (ImGui::Selectable(r.pareto ? "*" : " ", sameMethod(r.settings, current),
                              ImGuiSelectableFlags_SpanAllColumns))
            clicked = static_cast<int>(i);
        if (r.pareto) ImGui::PopStyleColor();
        ImGui::PopID();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.axis.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.method.c_str());
        cell("%.2f", r.times.median);
        cell("%.3f", r.error.rmse);
        cell("%.1f", r.error.psnr);
        cell("%.0f", r.error.maxError);
        cell("%.2f %%", 100.0 * r.error.over2Lsb);
    }
    ImGui::EndTable();
    return clicked;
}

}  // namespace

void accuracySection(AccuracyState& accuracy, const ViewerModel& model) {
    accuracy.open = ImGui::TreeNodeEx("Against the ground truth", ImGuiTreeNodeFlags_DefaultOpen);
    if (!accuracy.open) return;
    AccuracyJob& job = accuracy.job;
    // Sub-samples per pixel, n×n: the reference path's time and memory grow with n².
    char current[32];
    std::snprintf(current, sizeof current, "%d x %d per pixel", accuracy.samples, accuracy.samples);
    // A narrow side bar leaves out "per pixel" rather than cut it off.
    if (ImGui::CalcTextSize(current).x + ImGui::GetFrameHeight() +
            2.0f * ImGui::GetStyle().FramePadding.x >
        ImGui::CalcItemWidth())
        std::snprintf(current, sizeof current, "%d x %d", accuracy.samples, accuracy.samples);
    if (ImGui::BeginCombo("samples", current)) {
        for (int n = 1; n <= kMaxAccuracySamples; ++n) {
            char item[32];
            std::snprintf(item, sizeof item, "%d x %d", n, n);
            if (ImGui::Selectable(item, n == accuracy.samples)) accuracy.samples = n;
        }
        ImGui::EndCombo();
    }
    const AccuracyStatus status = job.status();
    if (job.running()) {
        ImGui::ProgressBar(static_cast<float>(status.fraction), ImVec2(-80.0f, 0.0f),
                           status.label.c_str());
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) job.cancel();
    } else {
        if (ImGui::Button("Measure"))
            job.start(model.scene, model.sceneVersion, model.settings, accuracy.samples);
        ImGui::SameLine();
        ImGui::TextDisabled("time and error per method");
        if (!status.message.empty()) {
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(kYellow, "%s", status.message.c_str());
            ImGui::PopTextWrapPos();
        }
    }

    const std::shared_ptr<const AccuracyReport> report = job.report();
    if (report) {
        // A new report opens its table (a window of its own: eight columns).
        if (job.reportCount() != accuracy.tableSeen) {
            accuracy.tableSeen = job.reportCount();
            accuracy.table = true;
        }
        ImGui::Text("%zu methods, truth %dx%d samples (%.1f s)", report->rows.size(),
                    report->samples, report->samples, report->groundTruthSeconds);
        ImGui::Checkbox("show the table", &accuracy.table);
    }
    ImGui::TreePop();
}

void accuracyWindow(AccuracyState& accuracy, ViewerModel& model, WorkspaceUi& work) {
    const std::shared_ptr<const AccuracyReport> report = accuracy.job.report();
    if (!report || !accuracy.table) return;
    const Rect& image = work.layout.image;
    const float margin = 10.0f * work.scale;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(image.x) + margin,
                                   static_cast<float>(image.y + image.h) - margin),
                            ImGuiCond_Appearing, ImVec2(0.0f, 1.0f));
    // Never larger than the image area (it scrolls instead).
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                        ImVec2(static_cast<float>(image.w) - 2.0f * margin,
                                               static_cast<float>(image.h) - 2.0f * margin));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;
    if (ImGui::Begin("Against the ground truth", &accuracy.table, flags)) {
        noteWindow(work, "table");
        ImGui::Text("%dx%d, ground truth %dx%d samples per pixel (%.1f s), median of %d frames",
                    report->width, report->height, report->samples, report->samples,
                    report->groundTruthSeconds, report->frames);
        const AccuracyView now = accuracyView(model.scene, model.sceneVersion, model.settings);
        if (!reportFresh(*report, now))
            ImGui::TextColored(kYellow, "stale: the view or settings changed since");
        if (now.settings.mode != DrawMode::Solid)
            ImGui::TextDisabled("(drawn solid for this, like the ground truth)");
        const int clicked = methodTable(*report, now.settings);
        if (clicked >= 0)
            applyMethod(report->rows[static_cast<std::size_t>(clicked)], model.settings);
        if (!report->leftOut.empty())
            ImGui::TextColored(kYellow, "left out, not coarser than the truth: %s",
                               report->leftOut.c_str());
        ImGui::TextDisabled(
            "RMSE, max: 8-bit steps. The truth is finer than every method listed.\n"
            "* Pareto front: no other method both faster and more accurate.\n"
            "Times: each timed frame follows one of the same method, rounds interleaved,\n"
            "medians. Click a row: use that method.");
    }
    ImGui::End();
}

void announceAccuracy(AccuracyState& accuracy) {
    const std::uint64_t count = accuracy.job.reportCount();
    if (count == accuracy.announced) return;
    accuracy.announced = count;
    const std::shared_ptr<const AccuracyReport> r = accuracy.job.report();
    if (!r) return;
    std::printf(
        "facet-view: accuracy measured, %zu methods at %dx%d, ground truth %dx%d samples "
        "(%.1f s)\n",
        r->rows.size(), r->width, r->height, r->samples, r->samples, r->groundTruthSeconds);
    std::fflush(stdout);
}

}  // namespace facet::view
