#include "layout.hpp"

#include <algorithm>
#include <cmath>

namespace facet::view {

Rect letterbox(int frameWidth, int frameHeight, int areaWidth, int areaHeight) {
    if (areaWidth <= 0 || areaHeight <= 0) return {};
    if (frameWidth <= 0 || frameHeight <= 0) return {0, 0, areaWidth, areaHeight};
    // Compare aspects with integers: w/h > W/H ⇔ w·H > W·h, exact, so a frame of the area's
    // size (or aspect) is never off by a pixel.
    const long long fw = frameWidth, fh = frameHeight, aw = areaWidth, ah = areaHeight;
    Rect r;
    if (fw * ah >= aw * fh) {  // wider than the area: full width, bars above and below
        r.w = areaWidth;
        r.h = static_cast<int>(std::max(1LL, (aw * fh + fw / 2) / fw));
    } else {  // taller: full height, bars left and right
        r.h = areaHeight;
        r.w = static_cast<int>(std::max(1LL, (ah * fw + fh / 2) / fh));
    }
    r.x = (areaWidth - r.w) / 2;
    r.y = (areaHeight - r.h) / 2;
    return r;
}

glm::dvec2 windowToFrame(const Rect& view, int frameWidth, int frameHeight, glm::dvec2 point) {
    if (view.w <= 0 || view.h <= 0) return point;
    return {(point.x - view.x) * frameWidth / view.w, (point.y - view.y) * frameHeight / view.h};
}

double frameScale(const Rect& view, int frameWidth) {
    return view.w > 0 ? static_cast<double>(frameWidth) / view.w : 1.0;
}

}  // namespace facet::view
