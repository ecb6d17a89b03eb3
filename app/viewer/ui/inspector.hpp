#pragma once
// The viewer's pixel inspector: Shift + left click on the image inspects that pixel of the
// engine's frame (facet/inspect.hpp) and opens a window listing its fragments, RenderDoc's
// pixel history style; the pixel stays marked on the image while the window is open. It is
// computed once per click, on the UI thread, never as part of the frame loop.

#include <string>

#include "accuracy_job.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/inspect.hpp"

namespace facet::view {

struct App;

/// What the inspector window shows.
struct InspectorState {
    bool open = false;   ///< the window is shown (its close box clears it)
    bool valid = false;  ///< `history` holds an inspection
    PixelHistory history;
    GroundTruth truth;    ///< the pixel's ground truth (1×1), or empty
    AccuracyView view;    ///< the picture and settings it was computed for
    double ms = 0.0;      ///< how long the inspection took
    int clicks = 0;       ///< inspections made since the start (the --state file reports it)
    bool placed = false;  ///< the window was put beside the pixel after the last inspection
    int openRow = -1;     ///< the entry whose details are shown
};

/// Shift + left click on the image: inspects the pixel under the pointer and returns true (the
/// click then starts no camera drag). False for any other input.
bool inspectorClick(App& app);

/// Inspects frame pixel (x, y) of the picture the viewer shows now.
void inspectPixelAt(App& app, int x, int y);

/// The inspector window and the marker on the inspected pixel, when open.
void inspectorWindow(App& app);

/// The inspector's lines of the --state file: open, pixel, fragments and colours.
std::string inspectorStateText(const App& app);

}  // namespace facet::view
