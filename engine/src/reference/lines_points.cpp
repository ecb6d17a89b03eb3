// Rules 6 and 7 of the reference path (the rules are listed in raster.cpp): lines as a closed
// Bresenham formula, points as squares, with the ambiguity flags of rule 8(c).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "reference/geometry.hpp"

namespace facet::reference::detail {
namespace {

// Line endpoints farther out than this are beyond any image and would overflow the int64
// Bresenham arithmetic (2·k·dminor); such segments are not drawn. No sane scene gets near it.
constexpr double kMaxLineCoord = 536870912.0;  // 2^29

// floor(a / b) for b > 0, rounding towards -inf unlike C++'s truncating division.
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// The pixels floor(v) may become when v moves by up to 1/256 px: one, or two next to each other.
std::array<std::int64_t, 2> floorCandidates(double v) {
    return {static_cast<std::int64_t>(std::floor(v - kSnap)),
            static_cast<std::int64_t>(std::floor(v + kSnap))};
}

struct LinePixel {
    std::int64_t x, y, k;
};

// Pixels of the integer line (x0, y0)-(x1, y1) that lie in the image, with their step index k
// of n = max(|dx|, |dy|), endpoints included.
std::vector<LinePixel> linePixels(const Image& img, std::int64_t x0, std::int64_t y0,
                                  std::int64_t x1, std::int64_t y1, std::int64_t& n) {
    const std::int64_t dx = x1 - x0;
    const std::int64_t dy = y1 - y0;
    n = std::max(std::abs(dx), std::abs(dy));
    std::vector<LinePixel> pixels;
    if (n == 0) {
        if (inImage(img, x0, y0)) pixels.push_back({x0, y0, 0});
        return pixels;
    }
    const bool xMajor = std::abs(dx) >= std::abs(dy);
    const std::int64_t major0 = xMajor ? x0 : y0;
    const std::int64_t minor0 = xMajor ? y0 : x0;
    const std::int64_t dMinor = xMajor ? dy : dx;
    const std::int64_t step = (xMajor ? dx : dy) > 0 ? 1 : -1;
    const std::int64_t majorSize = xMajor ? img.width : img.height;
    // Only the k whose major coordinate major0 + k·step is inside the image: a clipped line may
    // be millions of pixels long.
    std::int64_t kFirst = step > 0 ? -major0 : major0 - (majorSize - 1);
    std::int64_t kLast = step > 0 ? majorSize - 1 - major0 : major0;
    kFirst = std::max<std::int64_t>(kFirst, 0);
    kLast = std::min(kLast, n);
    for (std::int64_t k = kFirst; k <= kLast; ++k) {
        const std::int64_t major = major0 + k * step;
        // Round k·dMinor/n to nearest, ties towards +inf: integer Bresenham in closed form.
        const std::int64_t minor = minor0 + floorDiv(2 * k * dMinor + n, 2 * n);
        const LinePixel p = xMajor ? LinePixel{major, minor, k} : LinePixel{minor, major, k};
        if (inImage(img, p.x, p.y)) pixels.push_back(p);
    }
    return pixels;
}

}  // namespace

void drawSegment(Image& img, const Pass& pass, Vertex a, Vertex b, double nearPlane) {
    const double da = a.clip.w - nearPlane;
    const double db = b.clip.w - nearPlane;
    if (!(da >= 0.0) && !(db >= 0.0)) return;
    if (!(da >= 0.0)) a = intersectNear(b, db, a, da);
    if (!(db >= 0.0)) b = intersectNear(a, da, b, db);

    const glm::dvec2 s0 = glm::dvec2(a.clip) / a.clip.w;
    const glm::dvec2 s1 = glm::dvec2(b.clip) / b.clip.w;
    for (const double c : {s0.x, s0.y, s1.x, s1.y}) {
        if (!(std::abs(c) < kMaxLineCoord)) return;
    }

    std::int64_t n = 0;
    const std::vector<LinePixel> pixels = linePixels(
        img, static_cast<std::int64_t>(std::floor(s0.x)),
        static_cast<std::int64_t>(std::floor(s0.y)), static_cast<std::int64_t>(std::floor(s1.x)),
        static_cast<std::int64_t>(std::floor(s1.y)), n);
    const std::array<Vertex, 2> ends{a, b};
    for (const LinePixel& p : pixels) {
        // Attributes at t = k/n along the line, the same for steep and shallow lines.
        const double t = n == 0 ? 0.0 : static_cast<double>(p.k) / static_cast<double>(n);
        const double q = (1.0 - t) / a.clip.w + t / b.clip.w;
        const std::array<double, 2> weights =
            detail::lineWeights(t, a.clip.w, b.clip.w, pass.settings.interp);
        fragment(img, pass, p.x, p.y, 1.0 / q, ends, weights, 0.0);
    }

    // Rule 8(c): an endpoint within 1/256 px of a pixel border may land in either pixel, which
    // moves (and re-steps) the whole line: flag every pixel of every line the endpoints could
    // give. For most lines all candidates are the same and nothing is flagged.
    const auto cx0 = floorCandidates(s0.x), cy0 = floorCandidates(s0.y);
    const auto cx1 = floorCandidates(s1.x), cy1 = floorCandidates(s1.y);
    if (cx0[0] == cx0[1] && cy0[0] == cy0[1] && cx1[0] == cx1[1] && cy1[0] == cy1[1]) return;
    for (const std::int64_t x0 : cx0) {
        for (const std::int64_t y0 : cy0) {
            for (const std::int64_t x1 : cx1) {
                for (const std::int64_t y1 : cy1) {
                    std::int64_t unused = 0;
                    for (const LinePixel& p : linePixels(img, x0, y0, x1, y1, unused)) {
                        img.ambiguous[pixelIndex(img, p.x, p.y)] = 1;
                    }
                }
            }
        }
    }
}

void drawPoint(Image& img, const Pass& pass, const Vertex& v, double nearPlane) {
    if (!(v.clip.w >= nearPlane)) return;
    const glm::dvec2 s = glm::dvec2(v.clip) / v.clip.w;
    if (!(std::abs(s.x) < kMaxLineCoord && std::abs(s.y) < kMaxLineCoord)) return;
    const auto px = static_cast<std::int64_t>(std::floor(s.x));
    const auto py = static_cast<std::int64_t>(std::floor(s.y));
    // Odd sizes are centred; even sizes put the extra pixel on the +x/+y side.
    const std::int64_t lo = -(static_cast<std::int64_t>(pass.settings.pointSize) - 1) / 2;
    const std::int64_t hi = lo + pass.settings.pointSize - 1;
    const std::array<double, 1> own{1.0};
    for (std::int64_t y = py + lo; y <= py + hi; ++y) {
        for (std::int64_t x = px + lo; x <= px + hi; ++x) {
            if (inImage(img, x, y)) fragment(img, pass, x, y, v.clip.w, {&v, 1}, own, 0.0);
        }
    }
    // Rule 8(c): near a pixel border the square may sit one pixel over; flag both positions.
    const auto cx = floorCandidates(s.x), cy = floorCandidates(s.y);
    if (cx[0] == cx[1] && cy[0] == cy[1]) return;
    for (std::int64_t y = cy[0] + lo; y <= cy[1] + hi; ++y) {
        for (std::int64_t x = cx[0] + lo; x <= cx[1] + hi; ++x) {
            if (inImage(img, x, y)) img.ambiguous[pixelIndex(img, x, y)] = 1;
        }
    }
}
}  // namespace facet::reference::detail
