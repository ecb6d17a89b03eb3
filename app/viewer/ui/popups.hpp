#pragma once
// The modal pop-ups: the error message any part of the viewer can queue (showError), and the
// question Ctrl+Q or the window's close button asks when the scene has unsaved changes.

#include <string>

namespace facet::view {

struct App;

/// The pop-ups between frames: what the error says, and where the quit question is.
struct PopupState {
    std::string title;  ///< the error popup's; it opens on the next frame when `pending`
    std::string message;
    bool pending = false;
    bool quitAsked = false;    ///< the quit question is open: the next Ctrl+Q or close quits
    bool quitPending = false;  ///< the quit question opens in the next frame
};

/// Opens the modal pop-up `id` when `pending` (and clears it), centred on the window, and
/// begins it: true while it shows, then end it with ImGui::EndPopup().
bool beginCentredModal(const char* id, bool& pending);

/// Queues the error popup.
void showError(PopupState& popups, const std::string& title, const std::string& message);

/// The modal error popup, when one is pending or open.
void errorPopup(PopupState& popups);

/// Ctrl+Q or the window's close button: quits, or first asks once when the scene has unsaved
/// changes (ViewerModel::unsaved).
void askToQuit(App& app);

/// The question askToQuit opens: save and quit, quit without saving, or cancel (Esc).
void quitPopup(App& app);

}  // namespace facet::view
