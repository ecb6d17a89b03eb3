#include "workspace.hpp"

#include <algorithm>
#include <cmath>

namespace facet::view {
namespace {

int scaled(int pixels, double scale) {
    return static_cast<int>(std::lround(pixels * (scale > 0.0 ? scale : 1.0)));
}

}  // namespace

int clampSidebarWidth(int width, int windowWidth, double scale) {
    const int least = scaled(kSidebarMinWidth, scale);
    const int most = static_cast<int>(windowWidth * (1.0 - kMinImageShare));
    return std::max(0, std::min(most, std::max(least, width)));
}

int autoSidebarWidth(int windowWidth, double scale) {
    const int full = scaled(kSidebarWidth, scale);
    const int least = scaled(kSidebarMinWidth, scale);
    const int share = static_cast<int>(kSidebarShare * std::max(0, windowWidth));
    return std::min(full, std::max(least, share));
}

bool autoCollapsed(int windowWidth, double scale) {
    return windowWidth < scaled(kCollapseBelow, scale);
}

Workspace workspaceLayout(int windowWidth, int windowHeight, int sidebarWidth, SidebarState state,
                          double scale) {
    Workspace w;
    if (windowWidth <= 0 || windowHeight <= 0) return w;
    int bar = 0;
    if (state == SidebarState::Open) bar = clampSidebarWidth(sidebarWidth, windowWidth, scale);
    if (state == SidebarState::Collapsed) bar = scaled(kSidebarCollapsedWidth, scale);
    bar = std::min(bar, windowWidth);
    if (bar > 0) w.sidebar = {0, 0, bar, windowHeight};
    w.image = {bar, 0, windowWidth - bar, windowHeight};
    return w;
}

Rect frameRect(const Workspace& workspace, int frameWidth, int frameHeight) {
    const Rect& a = workspace.image;
    Rect r = letterbox(frameWidth, frameHeight, a.w, a.h);
    r.x += a.x;
    r.y += a.y;
    return r;
}

OpeningSize openingSize(int sceneWidth, int sceneHeight, int sidebarWidth, int workWidth,
                        int workHeight) {
    OpeningSize o;
    const int w = std::max(1, sceneWidth);
    const int h = std::max(1, sceneHeight);
    double k = 1.0;
    if (workWidth > 0) k = std::min(k, static_cast<double>(workWidth - sidebarWidth) / w);
    if (workHeight > 0) k = std::min(k, static_cast<double>(workHeight) / h);
    // Shrinking by k keeps the scene's aspect in the image area, so the frame that follows the
    // window shows the scene's framing, only smaller.
    o.scaled = k < 1.0;
    k = std::max(k, 1e-3);
    o.imageWidth = o.scaled ? std::max(1, static_cast<int>(std::floor(w * k))) : w;
    o.imageHeight = o.scaled ? std::max(1, static_cast<int>(std::floor(h * k))) : h;
    o.width = o.imageWidth + sidebarWidth;
    o.height = o.imageHeight;
    return o;
}

bool overlaps(const Rect& a, const Rect& b) {
    if (a.w <= 0 || a.h <= 0 || b.w <= 0 || b.h <= 0) return false;
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

Rect cornerRect(const Rect& area, int w, int h, Corner corner, int margin) {
    const bool right = corner == Corner::TopRight || corner == Corner::BottomRight;
    const bool bottom = corner == Corner::BottomLeft || corner == Corner::BottomRight;
    return {right ? area.x + area.w - margin - w : area.x + margin,
            bottom ? area.y + area.h - margin - h : area.y + margin, w, h};
}

}  // namespace facet::view
