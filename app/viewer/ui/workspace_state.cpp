#include "workspace_state.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "light_input.hpp"
#include "light_marker.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

std::string rect(const Rect& r) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "%d %d %d %d", r.x, r.y, r.w, r.h);
    return buf;
}

}  // namespace

std::string workspaceStateText(const App& app) {
    const WorkspaceUi& w = app.work;
    std::ostringstream s;
    s << "window " << app.fbWidth << " " << app.fbHeight << "\n";
    s << "view " << rect(app.view) << "\n";
    s << "image_area " << rect(w.layout.image) << "\n";
    s << "sidebar "
      << (w.sidebarState == SidebarState::Hidden      ? "hidden"
          : w.sidebarState == SidebarState::Collapsed ? "collapsed"
                                                      : "open")
      << "\n";
    for (const auto& [name, r] : w.drawn) s << "window_" << name << " " << rect(r) << "\n";
    char loading[32];  // a load in flight (1) and its fraction, or 0 0
    std::snprintf(loading, sizeof loading, "%d %.3f", app.files.loading.running() ? 1 : 0,
                  app.files.loading.progress());
    s << "loading " << loading << "\n";
    s << "help " << (w.help ? 1 : 0) << "\n";
    s << "help_scrolls " << (w.helpScrolls ? 1 : 0) << "\n";
    s << "stats_overlay " << (w.statsOverlay ? 1 : 0) << "\n";
    s << "fullscreen " << (w.fullscreen ? 1 : 0) << "\n";
    char scale[32];
    std::snprintf(scale, sizeof scale, "%.3f", w.scale);
    s << "ui_scale " << scale << "\n";
    s << "screenshot_folder " << app.screenshot.folder << "\n";
    const bool noticeShown =
        !w.notice.text.empty() && std::chrono::steady_clock::now() < w.notice.until;
    s << "notice " << (noticeShown ? w.notice.text : "") << "\n";
    s << "refused " << app.model.refused << "\n";
    const LightMarker m = lightMarker(app.model.scene.camera, lightPosition(app),
                                      app.model.orbit.target, app.model.orbit.distance);
    const Camera& c = app.model.scene.camera;
    // Shown or not, where it is drawn (window pixels), and whether that is its projection (1)
    // or a place on the frame's border (0).
    const glm::dvec2 at = lightMarkerPlace(app);
    char marker[160];
    std::snprintf(marker, sizeof marker, "%d %.3f %.3f %d", lightMarkerShown(app) ? 1 : 0,
                  app.view.x + at.x * app.view.w / std::max(1, c.width),
                  app.view.y + at.y * app.view.h / std::max(1, c.height),
                  markerInFrame(m, c.width, c.height) ? 1 : 0);
    s << "light_marker " << marker << "\n";
    s << "light_marker_note " << app.light.note << "\n";
    s << "light_marker_note_rect " << rect(app.light.noteRect) << "\n";
    return s.str();
}

}  // namespace facet::view
