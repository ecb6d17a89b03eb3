#include "accuracy_methods.hpp"

#include <algorithm>
#include <chrono>

#include "facet/multisample.hpp"

namespace facet::app {

RenderSettings baseSettings(const Scene& scene) {
    RenderSettings s;
    s.mode = DrawMode::Solid;
    s.interp = Interp::Perspective;
    s.filter = TextureFilter::Trilinear;
    s.lighting = Lighting::Phong;  // the exact lighting, so other axes show their own error
    if (scene.texture && !scene.mesh->uvs.empty()) {
        s.shader = ShaderKind::Texture;
        s.combine = true;  // so the lighting axis changes the picture
    } else {
        s.shader = ShaderKind::Painter;
    }
    return s;
}

std::vector<AccuracyMethod> accuracyMethods(const Scene& scene) {
    return accuracyMethods(scene, baseSettings(scene));
}

std::vector<AccuracyMethod> accuracyMethods(const Scene& scene, const RenderSettings& settings) {
    RenderSettings base = settings;
    base.mode = DrawMode::Solid;  // what the ground truth draws
    base.showNormals = false;
    base.depthLegend = false;
    base.msaa = 1;  // the samples axis sets it; the other axes are one sample per pixel
    std::vector<AccuracyMethod> methods;
    auto add = [&](const char* axis, std::string name, auto change) {
        RenderSettings s = base;
        change(s);
        methods.push_back({axis, std::move(name), s});
    };
    add("interp", "affine", [](RenderSettings& s) { s.interp = Interp::Affine; });
    for (const int n : {8, 16, 32}) {
        add("interp", "subdivided:" + std::to_string(n), [n](RenderSettings& s) {
            s.interp = Interp::Subdivided;
            s.subdivision = n;
        });
    }
    add("interp", "perspective", [](RenderSettings& s) { s.interp = Interp::Perspective; });
    const bool textured =
        base.shader == ShaderKind::Texture && scene.texture && !scene.mesh->uvs.empty();
    if (textured) {
        add("filter", "nearest", [](RenderSettings& s) { s.filter = TextureFilter::Nearest; });
        add("filter", "bilinear", [](RenderSettings& s) { s.filter = TextureFilter::Bilinear; });
        add("filter", "trilinear", [](RenderSettings& s) { s.filter = TextureFilter::Trilinear; });
    }
    // The lit colour shows unless the shader ignores it: Depth, or Texture without combine.
    const bool litShown = base.lighting != Lighting::Off && base.shader != ShaderKind::Depth &&
                          (base.shader != ShaderKind::Texture || base.combine);
    if (litShown) {
        add("lighting", "gouraud", [](RenderSettings& s) { s.lighting = Lighting::Gouraud; });
        add("lighting", "phong", [](RenderSettings& s) { s.lighting = Lighting::Phong; });
    }
    // Coverage: one sample per pixel, the frame supersampled 2×2 and 4×4 (every sample shaded,
    // so it costs about N² frames), or multisampled with 2, 4, 8 samples (coverage and depth
    // per sample, shaded once per pixel: edges only).
    for (const int n : {1, 2, 4}) {
        add("samples", std::to_string(n) + "x" + std::to_string(n),
            [n](RenderSettings& s) { s.supersample = n; });
    }
    for (const int n : kMsaaCounts)
        add("samples", "msaa" + std::to_string(n), [n](RenderSettings& s) { s.msaa = n; });
    return methods;
}

std::vector<AccuracyMethod> methodsBelowTruth(const std::vector<AccuracyMethod>& methods,
                                              int samples, std::string* leftOut) {
    std::vector<AccuracyMethod> kept;
    std::string out;
    for (const AccuracyMethod& m : methods) {
        const int perPixel = std::max(1, m.settings.supersample) *
                             std::max(1, m.settings.supersample) * std::max(1, m.settings.msaa);
        if (perPixel < samples * samples) {
            kept.push_back(m);
        } else {
            if (!out.empty()) out += ", ";
            out += m.name;
        }
    }
    if (leftOut) *leftOut = out;
    return kept;
}

std::vector<bool> onParetoFront(const std::vector<ParetoPoint>& points) {
    std::vector<bool> front(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        const ParetoPoint& r = points[k];
        front[k] = std::none_of(points.begin(), points.end(), [&r](const ParetoPoint& o) {
            // RMSEs this close are equally accurate: a last-digit difference between two
            // renders is no accuracy anyone sees, and should not keep a slower method on.
            const double tie = kParetoRmseTie * std::max(o.rmse, r.rmse);
            const bool noWorse = o.ms <= r.ms && o.rmse <= r.rmse + tie;
            const bool better = o.ms < r.ms || o.rmse < r.rmse - tie;
            return noWorse && better;
        });
    }
    return front;
}

std::vector<std::vector<double>> timeMethods(Renderer& renderer, const Scene& scene,
                                             const std::vector<AccuracyMethod>& methods, int frames,
                                             int warmup, Framebuffer& frame,
                                             const std::function<void(std::size_t)>& beforeRender) {
    for (int i = 0; i < warmup; ++i) {
        for (std::size_t k = 0; k < methods.size(); ++k) {
            if (beforeRender) beforeRender(k);
            renderer.render(scene, methods[k].settings, frame);
        }
    }
    std::vector<std::vector<double>> ms(methods.size());
    for (int f = 0; f < frames; ++f) {
        for (std::size_t k = 0; k < methods.size(); ++k) {
            if (beforeRender) beforeRender(k);
            // An untimed frame of the same method first: the timed one then finds the caches
            // holding this method's buffers, as every frame does in the viewer, not those of
            // the method before it (affine, first in each round, always followed the 4x4
            // supersampled frame of the round before).
            renderer.render(scene, methods[k].settings, frame);
            const auto start = std::chrono::steady_clock::now();
            renderer.render(scene, methods[k].settings, frame);
            ms[k].push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        }
    }
    return ms;
}

}  // namespace facet::app
