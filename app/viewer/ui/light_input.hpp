#pragma once
// The light in the picture: its marker drawn over the frame (a sun for a point light, a handle
// with an arrow to the look-at point for a directional one) and the drags that move it. The
// maths (projection, following the pointer, turning) is light_marker.hpp's.

#include <string>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "layout.hpp"

namespace facet::view {

struct App;

/// A drag that moves the light.
enum class LightDrag {
    None,
    Follow,  ///< the marker follows the pointer
    Turn,    ///< Ctrl + drag: the light turns around the look-at point
};

/// The light marker between frames.
struct LightMarkerState {
    bool shown = true;  ///< the marker in the picture, when lighting is on (M)
    LightDrag drag = LightDrag::None;
    std::string note;  ///< the words beside an off-screen light's marker, this frame
    Rect noteRect;     ///< where they are drawn (window pixels), empty when none
};

/// Starts a light drag when the left button went down over the marker (or with Ctrl); true
/// when it did, and the press is the light's.
bool startLightDrag(App& app);

/// Moves the light during a drag by this frame's pointer; ends the drag on release.
void dragLightStep(App& app);

/// Draws the light's marker over the frame.
void drawLightMarker(App& app);

/// Where the light's marker is drawn, in frame pixels (its projection, or on the frame's border
/// when the light is off-screen).
glm::dvec2 lightMarkerPlace(const App& app);

/// Whether the marker shows: turned on and lighting on.
bool lightMarkerShown(const App& app);

/// The light's homogeneous position in the scene (one place to change when Scene changes).
glm::dvec4& lightPosition(App& app);
/// The light's homogeneous position in the scene, read only.
const glm::dvec4& lightPosition(const App& app);

}  // namespace facet::view
