#include "key_map.hpp"

#include <algorithm>
#include <array>

#include "framing.hpp"
#include "renderer_choice.hpp"
#include "viewer_model.hpp"

namespace facet::view {
namespace {

using enum Action;

// Rows the help shows as one.
constexpr std::string_view kDraw = "draw: solid, wireframe, vertices";
constexpr std::string_view kShader = "shader: painter, depth, texture, simple (no depth test)";

// Letters are matched in both cases: Shift or Caps Lock should not make a key dead.
constexpr std::array kKeys{
    KeyBinding{Help, "F1  ?", "this help", "?", NamedKey::F1, std::nullopt},
    KeyBinding{Back, "Esc", "close what is open, innermost first (never quits)", "",
               NamedKey::Escape, std::nullopt},
    KeyBinding{Quit, "Ctrl+Q", "quit (asks once if the scene has unsaved changes)", "",
               NamedKey::CtrlQ, std::nullopt},
    KeyBinding{TogglePanels, "Tab", "hide or show the side bar", "", NamedKey::Tab, std::nullopt},
    KeyBinding{FrameModel, "F", "frame the model (its bounding sphere)", "fF", std::nullopt,
               std::nullopt},
    KeyBinding{ResetCamera, "Home  R", "the scene's camera", "rR", NamedKey::Home, std::nullopt},
    KeyBinding{Fullscreen, "F11", "fullscreen", "", NamedKey::F11, std::nullopt},
    KeyBinding{Screenshot, "F12  P", "screenshot into the pictures folder", "pP", NamedKey::F12,
               std::nullopt},
    KeyBinding{ToggleStats, "S", "stats overlay", "sS", std::nullopt, std::nullopt},
    KeyBinding{ToggleLightMarker, "M", "light marker", "mM", std::nullopt, std::nullopt},
    KeyBinding{ModeSolid, "1", "draw solid", "1", std::nullopt, std::nullopt, kDraw},
    KeyBinding{ModeWireframe, "2", "draw wireframe", "2", std::nullopt, std::nullopt, kDraw},
    KeyBinding{ModeVertices, "3", "draw vertices", "3", std::nullopt, std::nullopt, kDraw},
    KeyBinding{ShaderPainter, "4", "painter shader", "4", std::nullopt, std::nullopt, kShader},
    KeyBinding{ShaderDepth, "5", "depth shader", "5", std::nullopt, std::nullopt, kShader},
    KeyBinding{ShaderTexture, "6", "texture shader", "6", std::nullopt, std::nullopt, kShader},
    KeyBinding{ShaderSimple, "7", "simple shader (no depth test)", "7", std::nullopt, std::nullopt,
               kShader},
    KeyBinding{NextLighting, "L", "lighting: off, Gouraud, Phong", "lL", std::nullopt,
               std::nullopt},
    KeyBinding{NextInterp, "I", "interpolation: affine, subdivided, perspective", "iI",
               std::nullopt, std::nullopt},
    KeyBinding{NextRenderer, "G", "renderer: CPU, OpenGL, side by side", "gG", std::nullopt,
               std::nullopt},
    KeyBinding{ToggleCompare, "C", "compare two interpolations", "cC", std::nullopt, std::nullopt},
    KeyBinding{ToggleDifference, "D", "compare: split or difference", "dD", std::nullopt,
               std::nullopt},
    KeyBinding{ToggleNormals, "N", "show normals", "nN", std::nullopt, std::nullopt},
    KeyBinding{ToggleCull, "B", "cull back faces", "bB", std::nullopt, std::nullopt},
};

constexpr std::array kMouse{
    MouseBinding{"left drag", "orbit around the look-at point"},
    MouseBinding{"right or middle drag", "pan"},
    MouseBinding{"wheel", "zoom"},
    MouseBinding{"drag the light marker", "move the light around the look-at point"},
    MouseBinding{"Ctrl + left drag", "turn the light around the look-at point"},
    MouseBinding{"Shift + left click", "inspect that pixel: its fragments, step by step"},
    MouseBinding{"drag the divider", "move the Compare divider"},
    MouseBinding{"drag the side bar's edge", "resize it; << collapses it"},
    MouseBinding{"Ctrl + click a slider", "type a value (beyond its range too)"},
    MouseBinding{"Alt / Shift + drag a field", "finer / coarser steps"},
};

template <typename T>
T cycled(T value, int count) {
    return static_cast<T>((static_cast<int>(value) + 1) % count);
}

}  // namespace

std::span<const KeyBinding> keyBindings() {
    return kKeys;
}

std::vector<HelpRow> helpRows() {
    std::vector<HelpRow> rows;
    for (const KeyBinding& k : kKeys) {
        if (!k.group.empty() && !rows.empty() && rows.back().what == k.group) {
            rows.back().keys += " ";
            rows.back().keys += k.keys;
            continue;
        }
        rows.push_back({std::string(k.keys), std::string(k.group.empty() ? k.what : k.group)});
    }
    return rows;
}

std::span<const MouseBinding> mouseBindings() {
    return kMouse;
}

std::optional<Action> actionForChar(unsigned codepoint) {
    if (codepoint == 0 || codepoint > 127) return std::nullopt;
    const char c = static_cast<char>(codepoint);
    for (const KeyBinding& k : kKeys)
        if (k.chars.find(c) != std::string_view::npos) return k.action;
    return std::nullopt;
}

std::optional<Action> actionForKey(NamedKey key) {
    for (const KeyBinding& k : kKeys)
        if (k.named == key || k.named2 == key) return k.action;
    return std::nullopt;
}

std::string_view keysFor(Action action) {
    for (const KeyBinding& k : kKeys)
        if (k.action == action) return k.keys;
    return {};
}

EscTarget escTarget(const OpenThings& open) {
    if (open.popup) return EscTarget::Popup;
    if (open.inspector) return EscTarget::Inspector;
    if (open.measureTable) return EscTarget::MeasureTable;
    if (open.help) return EscTarget::Help;
    if (open.fullscreen) return EscTarget::Fullscreen;
    return EscTarget::None;
}

bool applyDocumentAction(Action action, ViewerModel& model, CompareSettings& compare) {
    RenderSettings& s = model.settings;
    switch (action) {
        case FrameModel:
            frameModel(model);
            return true;
        case ResetCamera:
            model.resetCamera();
            return true;
        case ModeSolid:
            s.mode = DrawMode::Solid;
            return true;
        case ModeWireframe:
            s.mode = DrawMode::Wireframe;
            return true;
        case ModeVertices:
            s.mode = DrawMode::Vertices;
            return true;
        case ShaderPainter:
            s.shader = ShaderKind::Painter;
            return true;
        case ShaderDepth:
            s.shader = ShaderKind::Depth;
            return true;
        case ShaderTexture:
            s.shader = ShaderKind::Texture;
            return true;
        case ShaderSimple:
            s.shader = ShaderKind::Simple;
            return true;
        case NextLighting:
            s.lighting = cycled(s.lighting, 3);
            return true;
        case NextInterp:
            s.interp = cycled(s.interp, 3);
            return true;
        case NextRenderer:
            selectRenderer(model.rendererChoice, nextRenderer(model.rendererChoice), compare);
            return true;
        case ToggleCompare:
            setCompare(!compare.enabled, model.rendererChoice, compare);
            return true;
        case ToggleDifference:
            // Only where two pictures are shown: elsewhere the window says how to get them.
            if (!planFrame(model.rendererChoice, compare.enabled).twoSides()) return false;
            compare.display = compare.display == CompareDisplay::Split ? CompareDisplay::Difference
                                                                       : CompareDisplay::Split;
            return true;
        case ToggleNormals:
            s.showNormals = !s.showNormals;
            return true;
        case ToggleCull:
            s.cullBackFaces = !s.cullBackFaces;
            return true;
        default:
            return false;
    }
}

}  // namespace facet::view
