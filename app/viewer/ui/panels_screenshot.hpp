#pragma once
// Screenshot panel and the screenshot it takes: the shown frame (and the whole window when
// asked) to the next free numbered files in the screenshot folder.

#include <string>

namespace facet::view {

struct App;

/// The Screenshot panel between frames.
struct ScreenshotState {
    std::string folder;      ///< set at start: the pictures folder (screenshot_folder.hpp)
    bool windowToo = false;  ///< the screenshot key also saves the whole window
    std::string last;        ///< what the last screenshot wrote (or its error)
    bool requested = false;  ///< from the key or the button; taken this frame
};

/// Screenshot: folder, whole window too, save button.
void screenshotPanel(ScreenshotState& screenshot);

/// Saves the shown frame (and the window when the panel asks for it) to the next free numbered
/// files in the screenshot folder; the frame loop calls it before the swap.
void takeScreenshot(App& app);

}  // namespace facet::view
