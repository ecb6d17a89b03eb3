#pragma once
// Which renderer draws the viewer's frame: the CPU engine, the OpenGL twin (app/gl, drawn with
// the window's own context), or both side by side across the Compare divider. Here is the
// choice without any OpenGL: its names, what one frame runs for it, how it and the
// interpolation Compare exclude each other, and the run's record for the --state file, so the
// unit tests cover all of it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare.hpp"

namespace facet::view {

/// The Render panel's renderer choice.
enum class RendererChoice {
    Cpu,       ///< the CPU engine alone (the interpolation Compare may be on)
    OpenGl,    ///< the OpenGL twin alone
    Split,     ///< CPU engine left of the divider, OpenGL twin right (or their difference)
    Lab,       ///< your pipeline alone: the lab's steps (lab/), drawn in the twin's place
    LabSplit,  ///< your pipeline left of the divider, the CPU engine right (or the difference)
};

/// True for the two choices that run the lab's pipeline instead of the OpenGL twin.
bool isLab(RendererChoice choice);

/// "cpu", "gl", "split", "lab", "lab-split": the --renderer values and the state file's spelling.
std::vector<std::string_view> rendererNames();

/// The choice a name spells; nullopt when unknown.
std::optional<RendererChoice> parseRenderer(std::string_view name);

/// The name parseRenderer() reads back.
std::string_view toString(RendererChoice choice);

/// "CPU engine", "OpenGL twin", "CPU | OpenGL side by side": the Render panel's entries.
std::string_view rendererLabel(RendererChoice choice);

/// The next choice in that order, wrapping (the G key).
RendererChoice nextRenderer(RendererChoice choice);

/// What one frame runs and shows.
struct FramePlan {
    bool engine = false;         ///< the CPU engine renders (on its thread)
    bool engineCompare = false;  ///< ...twice, for the interpolation Compare
    bool twin = false;           ///< the OpenGL twin renders (on the window's thread)
    bool sideBySide = false;     ///< engine and twin composed across the divider

    /// Two pictures on screen (a divider to drag, or a difference).
    bool twoSides() const { return engineCompare || sideBySide; }
};

/// The plan for a choice and the Compare checkbox (which only counts with the CPU engine).
FramePlan planFrame(RendererChoice choice, bool compareEnabled);

/// Sets `current` to `wanted`. The twin and the interpolation Compare share the divider, so
/// any choice but the CPU engine turns Compare off.
void selectRenderer(RendererChoice& current, RendererChoice wanted, CompareSettings& compare);

/// Turns the interpolation Compare on or off; on, it goes back to the CPU engine.
void setCompare(bool on, RendererChoice& current, CompareSettings& compare);

/// What the renderers did over a run, written to the --state file for tests.
struct RendererLog {
    long long engineFrames = 0;  ///< frames the CPU engine rendered
    long long twinFrames = 0;    ///< frames the OpenGL twin rendered
    int switches = 0;            ///< times the choice changed between frames
    std::string device;          ///< GL_RENDERER of the twin's context, once it ran
    std::string error;           ///< the twin's last error; empty when none
};

/// The log as state lines: engine_frames, twin_frames, renderer_switches, twin_device and
/// twin_error (its newlines as " | ", so it stays one line).
std::string rendererLogText(const RendererLog& log);

}  // namespace facet::view
