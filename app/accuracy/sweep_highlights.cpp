// The highlights sweep (sweep_highlights.hpp).

#include "sweep_highlights.hpp"

#include "facet/evaluation/frame_times.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/render.hpp"

namespace facet::app {
namespace {

/// A white sphere with eye and light together on a generic direction, so the highlight's centre
/// (the point facing both) falls inside a face rather than on a vertex; specular only.
Scene highlightScene(int rings, double shininess) {
    Scene scene;
    Mesh sphere = makeUvSphere(rings, 2 * rings);
    sphere.colors.assign(sphere.positions.size(), glm::vec3(1.0f));
    scene.mesh = std::make_shared<const Mesh>(std::move(sphere));
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.31, -0.23, -1.0));
    scene.camera.eye = 4.0 * dir;
    scene.camera.look = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.width = scene.camera.height = 96;
    scene.camera.focal = 150.0;
    scene.lighting.ambient = 0.0;
    scene.lighting.light.position = glm::dvec4(4.0 * dir, 1.0);
    scene.lighting.light.intensity = 1.0;
    scene.lighting.material = {.ka = 0.0, .kd = 0.0, .ks = 1.0, .s = shininess};
    return scene;
}

int peak(const Framebuffer& fb) {
    int p = 0;
    for (std::uint32_t c : fb.color) p = std::max(p, static_cast<int>(c & 0xFF));
    return p;
}

}  // namespace

std::vector<double> highlightShininess() {
    return {1.0, 4.0, 16.0, 64.0, 256.0, 1024.0};
}

std::vector<int> highlightRings(bool quick) {
    if (quick) return {8, 16, 32};
    return {8, 16, 32, 64};
}

std::vector<HighlightPoint> sweepHighlights(const SweepOptions& options) {
    std::vector<HighlightPoint> points;
    Renderer renderer;
    Framebuffer fb;
    for (const int rings : highlightRings(options.quick)) {
        for (const double s : highlightShininess()) {
            options.report("highlights: rings " + std::to_string(rings) + ", s " + cell(s));
            const Scene scene = highlightScene(rings, s);
            RenderSettings settings;
            settings.background = 0x000000;
            settings.threads = 1;
            settings.lighting = Lighting::Phong;  // the ground truth lights per sample anyway
            const GroundTruth truth = renderGroundTruth(scene, settings, options.samples).value();
            HighlightPoint p{rings, s};
            settings.lighting = Lighting::Gouraud;
            p.gouraudMs =
                timeRepeated(options.frames, [&] { renderer.render(scene, settings, fb); }).median;
            p.gouraudPeak = peak(fb);
            p.gouraudRmse = measureError(fb, truth).interiorRmse;
            settings.lighting = Lighting::Phong;
            p.phongMs =
                timeRepeated(options.frames, [&] { renderer.render(scene, settings, fb); }).median;
            p.phongPeak = peak(fb);
            p.phongRmse = measureError(fb, truth).interiorRmse;
            p.peakRatio = p.phongPeak > 0 ? static_cast<double>(p.gouraudPeak) / p.phongPeak : 0.0;
            points.push_back(p);
        }
    }
    return points;
}

double highlightLostAt(const std::vector<HighlightPoint>& points, int rings) {
    for (const HighlightPoint& p : points)
        if (p.rings == rings && p.peakRatio < 0.5) return p.shininess;
    return 0.0;
}

SweepTable highlightsTable(const std::vector<HighlightPoint>& points) {
    SweepTable t{"highlights",
                 "Highlights: Gouraud's specular peak against Phong's on a UV sphere, by "
                 "tessellation and shininess",
                 {"rings", "shininess", "gouraud_peak", "phong_peak", "ratio", "gouraud_rmse",
                  "phong_rmse", "gouraud_ms", "phong_ms"},
                 {}};
    for (const HighlightPoint& p : points)
        t.add({cell(p.rings), cell(p.shininess), cell(p.gouraudPeak), cell(p.phongPeak),
               cell(p.peakRatio), cell(p.gouraudRmse), cell(p.phongRmse), cell(p.gouraudMs),
               cell(p.phongMs)});
    return t;
}

}  // namespace facet::app
