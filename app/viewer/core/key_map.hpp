#pragma once
// Every key of the viewer in one table: what the key callbacks dispatch and what the help
// overlay (F1 or ?) lists, so the two cannot drift apart. Printable keys are matched by the
// character typed (so "?" works on any keyboard layout), the others by name. The actions that
// only edit the document (draw mode, shader, framing...) are applied here, without a window.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facet::view {

struct ViewerModel;
struct CompareSettings;

/// What a key (or a button doing the same) asks for.
enum class Action {
    Help,               ///< show or hide the key and mouse overlay
    Back,               ///< close the innermost open thing (escTarget); never quits
    Quit,               ///< quit, after one question when the scene has unsaved changes
    TogglePanels,       ///< hide or show the side bar
    FrameModel,         ///< turn-around point and distance so the model's bounding sphere fits
    ResetCamera,        ///< back to the scene file's camera
    Fullscreen,         ///< fullscreen on the window's monitor, or back
    Screenshot,         ///< save the frame into the screenshot folder
    NextRenderer,       ///< CPU engine, OpenGL twin, side by side
    ToggleStats,        ///< the stats overlay in the image's corner
    ToggleLightMarker,  ///< the light's marker in the picture
    ModeSolid,
    ModeWireframe,
    ModeVertices,
    ShaderPainter,
    ShaderDepth,
    ShaderTexture,
    ShaderSimple,
    NextLighting,  ///< off, Gouraud, Phong
    NextInterp,    ///< affine, subdivided, perspective
    ToggleCompare,
    ToggleDifference,  ///< Compare (or side by side): split or heat map
    ToggleNormals,
    ToggleCull,
};

/// Keys without a character.
enum class NamedKey { Escape, Tab, Home, F1, F11, F12, CtrlQ };

/// One line of the help: the keys, what they do, and what triggers them.
struct KeyBinding {
    Action action;
    std::string_view keys;   ///< as the help shows them, e.g. "F1  ?"
    std::string_view what;   ///< what it does
    std::string_view chars;  ///< printable characters that trigger it (ASCII)
    std::optional<NamedKey> named;
    std::optional<NamedKey> named2;
    std::string_view group = {};  ///< the help's one row for a run of bindings (1 2 3: draw...)
};

/// One row of the help: keys and what they do (a group's bindings share a row).
struct HelpRow {
    std::string keys;
    std::string what;
};

/// The help's key rows, in the table's order, groups merged ("1 2 3", "draw: solid, ...").
std::vector<HelpRow> helpRows();

/// The key table, in the order the help lists it.
std::span<const KeyBinding> keyBindings();

/// A mouse gesture and what it does (the help's second column).
struct MouseBinding {
    std::string_view gesture;
    std::string_view what;
};

/// The mouse gestures, in the order the help lists them.
std::span<const MouseBinding> mouseBindings();

/// The action of a typed character (a Unicode code point), if any.
std::optional<Action> actionForChar(unsigned codepoint);

/// The action of a named key, if any.
std::optional<Action> actionForKey(NamedKey key);

/// The keys of an action as the help shows them ("" when it has none): for button labels.
std::string_view keysFor(Action action);

/// What is open in the window, for Esc.
struct OpenThings {
    bool popup = false;      ///< an ImGui pop-up: a combo's drop-down, the error or quit question
    bool inspector = false;  ///< the pixel inspector's window
    bool measureTable = false;  ///< the ground-truth table's window (Measure)
    bool help = false;          ///< the keys and mouse overlay
    bool fullscreen = false;
};

/// What Esc closes: the innermost open thing, or nothing.
enum class EscTarget { Popup, Inspector, MeasureTable, Help, Fullscreen, None };

/// The innermost open thing, in the order pop-up, inspector, table, help, fullscreen.
EscTarget escTarget(const OpenThings& open);

/// Applies the actions that edit only the document (framing, camera, draw mode, shader,
/// lighting, interpolation, Compare, normals, culling, renderer); returns false for the others
/// (help, quit, panels, fullscreen, screenshot, overlays), which the window handles.
bool applyDocumentAction(Action action, ViewerModel& model, CompareSettings& compare);

}  // namespace facet::view
