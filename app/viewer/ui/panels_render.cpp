// Named by the engine's own lists (drawModeNames() and so on), so a new mode shows up here
// without touching the viewer. Both renderers read the same settings; where the twin's picture
// departs from the engine's, the panel says so.

#include "panels_render.hpp"

#include <algorithm>

#include <imgui.h>

#include "facet/limits.hpp"
#include "facet/mesh.hpp"
#include "gl_renderer.hpp"
#include "lab/renderer.hpp"
#include "panel_widgets.hpp"
#include "popups.hpp"
#include "scene_defaults.hpp"
#include "settings_map.hpp"
#include "twin_view.hpp"
#include "viewer_model.hpp"

namespace facet::view {
namespace {

/// What the debug view counts, in one or two lines under its combo.
const char* debugViewHelp(DebugView view) {
    switch (view) {
        case DebugView::Overdraw:
            return "fragments per pixel: every fragment that reached the depth test";
        case DebugView::TriangleSize:
            return "pixels of the triangle that wrote each pixel (log scale)";
        case DebugView::BinLoad:
            return "triangles binned in each 64x64 tile (darker lines: tile borders)";
        case DebugView::DepthTest:
            return "green: every fragment passed; red: some fragment failed (hidden by an "
                   "earlier, nearer one); black: no fragment";
        case DebugView::TextureLod:
            return "mip level of the fragment that wrote each pixel, under the texture shader "
                   "with trilinear filtering";
        case DebugView::InterpError:
            return "largest channel difference, in 8-bit steps, between affine and perspective "
                   "interpolation of these settings";
        case DebugView::None:
            break;
    }
    return "";
}

/// The renderer combo, and the twin's departures from the engine for these settings.
void rendererPicker(ViewerModel& model, CompareSettings& compare, const TwinView& twin) {
    static const auto names = rendererNames();
    RendererChoice& choice = model.rendererChoice;
    if (ImGui::BeginCombo("renderer", std::string(rendererLabel(choice)).c_str())) {
        for (const std::string_view name : names) {
            const RendererChoice c = parseRenderer(name).value_or(RendererChoice::Cpu);
            if (ImGui::Selectable(std::string(rendererLabel(c)).c_str(), c == choice))
                selectRenderer(choice, c, compare);
        }
        ImGui::EndCombo();
    }
    // Always one line (the details on hover), so the rows below stay put when the choice changes.
    const std::string differences = choice == RendererChoice::Cpu ? ""
                                    : isLab(choice)               ? lab::differences(model.settings)
                                                    : GlRenderer::differences(model.settings);
    if (isLab(choice)) {
        // Your pipeline: which steps are still stubs, and where it draws these settings
        // differently (both on hover).
        const std::vector<lab::Step>& todo = twin.labReport.notStarted;
        std::string steps;
        for (const lab::Step st : todo) steps += "\n  " + std::string(lab::stepName(st));
        if (todo.empty() && differences.empty())
            ImGui::TextDisabled("your pipeline: every step it ran is written");
        else
            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f),
                               "your pipeline: %zu step%s not "
                               "started (hover)",
                               todo.size(), todo.size() == 1 ? "" : "s");
        if (ImGui::IsItemHovered()) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
            const std::string text = (todo.empty() ? std::string("Every step it ran is written.")
                                                   : "Still the stubs:" + steps) +
                                     (differences.empty() ? "" : "\n\n" + differences);
            ImGui::TextUnformatted(text.c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
    } else if (choice == RendererChoice::Cpu) {
        ImGui::TextDisabled("G cycles: CPU, OpenGL twin, side by side");
    } else if (differences.empty()) {
        ImGui::TextDisabled("the OpenGL twin draws these settings as the engine");
    } else {
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "OpenGL twin departs here (hover)");
        if (ImGui::IsItemHovered()) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
            ImGui::TextUnformatted(differences.c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
    }
}

}  // namespace

void renderPanel(ViewerModel& model, CompareSettings& compare, const TwinView& twin,
                 PopupState& popups) {
    rendererPicker(model, compare, twin);
    RenderSettings& s = model.settings;
    static const auto modes = drawModeNames();
    static const auto shaders = shaderNames();
    static const auto interps = interpNames();
    static const auto filters = filterNames();
    static const auto lightings = lightingNames();

    int mode = nameIndex(modes, toString(s.mode));
    if (comboNames("draw mode", modes, mode))
        s.mode = parseDrawMode(modes[static_cast<std::size_t>(mode)]).value_or(s.mode);
    int shader = nameIndex(shaders, toString(s.shader));
    if (comboNames("shader", shaders, shader))
        s.shader = parseShader(shaders[static_cast<std::size_t>(shader)]).value_or(s.shader);
    int interp = nameIndex(interps, toString(s.interp));
    if (comboNames("interpolation", interps, interp))
        s.interp = parseInterp(interps[static_cast<std::size_t>(interp)]).value_or(s.interp);
    // Rows that apply to one mode only are greyed out in the others, never removed: the panel
    // keeps its shape as modes change.
    ImGui::BeginDisabled(s.interp != Interp::Subdivided);
    int n = s.subdivision;
    if (ImGui::SliderInt("every N pixels", &n, kMinSubdivision, kMaxSubdivision, "%d",
                         ImGuiSliderFlags_Logarithmic))
        applyInterp(s, {Interp::Subdivided, n});
    ImGui::EndDisabled();
    int lighting = nameIndex(lightings, toString(s.lighting));
    if (comboNames("lighting", lightings, lighting)) {
        s.lighting =
            parseLighting(lightings[static_cast<std::size_t>(lighting)]).value_or(s.lighting);
        lightingChosen(s);
    }
    // Filter and combine only mean something to the texture shader: greyed out under the others.
    ImGui::BeginDisabled(s.shader != ShaderKind::Texture);
    int filter = nameIndex(filters, toString(s.filter));
    if (comboNames("texture filter", filters, filter))
        s.filter = parseFilter(filters[static_cast<std::size_t>(filter)]).value_or(s.filter);
    ImGui::Checkbox("combine (texel x colour)", &s.combine);
    ImGui::EndDisabled();
    if (const std::string note = noEffectNote(model.scene, s); !note.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", note.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Checkbox("cull back faces", &s.cullBackFaces);
    ImGui::Checkbox("show normals", &s.showNormals);
    {
        ImGui::BeginDisabled(!s.showNormals);
        // 0 means the engine's default, a hundredth of the bounding-box diagonal (walked over
        // the mesh only when the normals show).
        const double diagonal = s.showNormals ? computeBounds(*model.scene.mesh).diagonal() : 1.0;
        sliderDouble("normal length", s.normalLength, 0.0, std::max(1e-6, 0.2 * diagonal),
                     s.normalLength > 0.0 ? "%.4f" : "auto");
        ImGui::EndDisabled();
    }
    ImGui::BeginDisabled(s.mode != DrawMode::Vertices);
    ImGui::SliderInt("point size", &s.pointSize, 1, 15);
    ImGui::EndDisabled();
    {
        ImGui::BeginDisabled(s.mode != DrawMode::Solid);
        // Coverage only: interpolation always uses the unsnapped vertices.
        int bits = s.subPixelBits;
        if (ImGui::SliderInt("sub-pixel bits", &bits, kMinSubPixelBits, kMaxSubPixelBits))
            s.subPixelBits = std::clamp(bits, kMinSubPixelBits, kMaxSubPixelBits);  // Ctrl+click
        // Supersampling: N×N samples per pixel, about N² times the work. (Where the OpenGL twin
        // departs from these two, the twin's note above says so.)
        static const char* const kSamples[] = {"1 per pixel", "2 x 2", "3 x 3", "4 x 4"};
        int ss = std::clamp(s.supersample, 1, 4) - 1;
        if (ImGui::Combo("samples", &ss, kSamples, 4)) {
            // A frame over the memory limit is refused before the renderer allocates it.
            const Camera& c = model.scene.camera;
            if (auto problem = frameMemoryProblem(c.width, c.height, ss + 1, s.msaa))
                showError(popups, "Supersampling", *problem);
            else
                s.supersample = ss + 1;
        }
        // Multisampling: coverage and depth per sample, one shading per pixel.
        static const char* const kMsaa[] = {"off", "2 samples", "4 samples", "8 samples"};
        int ms = s.msaa >= 8 ? 3 : s.msaa >= 4 ? 2 : s.msaa >= 2 ? 1 : 0;
        if (ImGui::Combo("MSAA", &ms, kMsaa, 4)) {
            const int samples = ms == 0 ? 1 : 1 << ms;
            const Camera& c = model.scene.camera;
            if (auto problem = frameMemoryProblem(c.width, c.height, s.supersample, samples))
                showError(popups, "Multisampling", *problem);
            else
                s.msaa = samples;
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "samples (supersampling) shades every sample: N x N the work, and it smooths\n"
                "edges, textures and highlights alike. MSAA tests coverage and depth at 2, 4 or\n"
                "8 points per pixel but shades each pixel once: edges only, for much less work.");
        ImGui::TextDisabled("samples: each sample shaded, N x N work");
        ImGui::TextDisabled("MSAA: shaded once a pixel, edges only");
        ImGui::EndDisabled();
    }
    {
        // Debug views: the frame coloured by what the pipeline did, with a legend in the frame.
        static const auto views = debugViewNames();
        int view = nameIndex(views, toString(s.view));
        if (comboNames("debug view", views, view))
            s.view = parseDebugView(views[static_cast<std::size_t>(view)]).value_or(s.view);
        if (s.view != DebugView::None) ImGui::TextWrapped("%s", debugViewHelp(s.view));
    }
    float rgb[3];
    rgbFromHex(s.background, rgb);
    if (ImGui::ColorEdit3("background", rgb)) s.background = hexFromRgb(rgb);
}

}  // namespace facet::view
