#pragma once
// The --state file: the view, light and material at exit as "key values..." lines, so a test
// that drives the window with real input events can check what its drags and wheel turns did.

#include <map>
#include <string>

#include "facet/error.hpp"
#include "viewer_model.hpp"

namespace facet::view {

/// The model's state as text, one "key value..." per line (numbers to full precision).
std::string stateText(const ViewerModel& model, long long frames);

/// Splits state text into key → rest of the line; comments (#) and blank lines are skipped.
std::map<std::string, std::string> parseState(const std::string& text);

/// Writes text to a file; the error names the path.
Status writeTextFile(const std::string& path, const std::string& text);

}  // namespace facet::view
