#pragma once
// The workspace's lines of the --state file, so the window tests can check the layout the
// viewer really used against the pixels of --window-shot.

#include <string>

namespace facet::view {

struct App;

/// The workspace lines of the --state file: window, side bar, view, overlays, UI scale,
/// notice, screenshot folder, light marker.
std::string workspaceStateText(const App& app);

}  // namespace facet::view
