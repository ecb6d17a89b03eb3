// The depth-precision sweep (sweep_depth.hpp).

#include "sweep_depth.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "facet/advanced/draw.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"

namespace facet::app {

double zFightingShare(double d, double delta) {
    const int w = 64, h = 64;
    Camera cam;
    cam.eye = {0, 0, 0};
    cam.look = {0, 0, 1};
    cam.up = {0, -1, 0};
    cam.width = w;
    cam.height = h;
    cam.focal = 64.0;
    // Tilted 60° off the view axis so depth varies across the planes, as on any real surface.
    const double tilt = 60.0 * std::numbers::pi / 180.0;
    const glm::dvec3 normal(0.0, std::sin(tilt), -std::cos(tilt));  // towards the camera
    const glm::dvec3 along(0.0, std::cos(tilt), std::sin(tilt));
    const glm::dvec3 side(1.0, 0.0, 0.0);
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> colors;
    // A quad 1.2·d on a side covers the 64×64 view at this focal length, with room to spare.
    for (int plane = 0; plane < 2; ++plane) {
        const glm::dvec3 c = glm::dvec3(0, 0, d) + (plane == 0 ? -0.5 : 0.5) * delta * normal;
        for (const glm::dvec2 q :
             {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
            const glm::dvec3 p = c + 0.6 * d * (q.x * side + q.y * along);
            clip.push_back(glm::vec4(reference::projectPoint(cam, p)));
            colors.emplace_back(plane == 0 ? 0.0f : 1.0f, plane == 0 ? 1.0f : 0.0f, 0.0f);
        }
    }
    const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    Renderer renderer;
    RenderSettings s;
    s.threads = 1;
    Framebuffer fb;
    fb.resize(w, h);
    fb.clear(rgbaFromHex(s.background));
    facet::draw(renderer, {.clip = clip, .colors = colors, .indices = idx, .nearPlane = 1e-3f}, s,
                fb);
    const std::uint32_t green = packRgba(0, 255, 0), red = packRgba(255, 0, 0);
    std::size_t covered = 0, fighting = 0;
    for (std::uint32_t c : fb.color) {
        covered += c == green || c == red;
        fighting += c == green;
    }
    return covered ? static_cast<double>(fighting) / static_cast<double>(covered) : 1.0;
}

std::vector<double> depthDistances(bool quick) {
    if (quick) return {1.0, 100.0, 1e4};
    return {1.0, 10.0, 100.0, 1e3, 1e4};
}

std::vector<DepthPoint> sweepDepth(const SweepOptions& options) {
    std::vector<DepthPoint> points;
    const double step = std::pow(2.0, 0.25);
    for (const double d : depthDistances(options.quick)) {
        options.report("depth: d = " + cell(d));
        for (double rel = 1e-3; rel > 1e-9; rel /= step)
            points.push_back({d, rel, zFightingShare(d, rel * d)});
    }
    return points;
}

double smallestResolvedGap(const std::vector<DepthPoint>& points, double distance) {
    double smallest = 0.0;
    for (const DepthPoint& p : points) {  // in the sweep's order: largest gap first
        if (p.distance != distance) continue;
        if (p.fighting > 0.0) break;
        smallest = p.relativeGap;
    }
    return smallest;
}

SweepTable depthTable(const std::vector<DepthPoint>& points) {
    SweepTable t{"depth",
                 "Depth precision: share of a far plane showing through a near one delta away, "
                 "float camera-space z",
                 {"distance", "relative_gap", "fighting", "smallest_resolved"},
                 {}};
    for (const DepthPoint& p : points)
        t.add({cell(p.distance), cell(p.relativeGap), cell(p.fighting),
               cell(smallestResolvedGap(points, p.distance))});
    return t;
}

}  // namespace facet::app
