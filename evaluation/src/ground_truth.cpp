// Ground truth by supersampling the reference path (ground_truth.hpp).
//
// The reference renders the scene at N times the size: width·N, height·N and focal·N. The
// principal point is half the image size (spec §4), so it scales with it, and the big
// image's pixel centre (I + ½, J + ½) lands at ((I + ½)/N, (J + ½)/N) in the frame's pixels:
// the sub-sample centres sit at (k + ½)/N inside each pixel, an N×N grid that covers the pixel
// evenly. Averaging each N×N block (a box filter) approximates the integral of the image over
// the pixel's square.
//
// Textures: each sub-sample reads level 0 bilinearly, so the N² samples together average the
// texture over the pixel's footprint on the surface, which is what a mip level only guesses at.
// Lighting is Phong (per sub-sample) and interpolation perspective-correct, the exact forms.
//
// Colours stay in double until the average, and are clamped per sub-sample first, as the
// display would clamp each of them; nothing is rounded to 8 bits.

#include "facet/evaluation/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "facet/camera.hpp"
#include "facet/limits.hpp"
#include "facet/reference.hpp"

namespace facet {

RenderSettings groundTruthSettings(const RenderSettings& settings) {
    RenderSettings s = settings;
    s.mode = DrawMode::Solid;
    s.interp = Interp::Perspective;
    if (s.lighting == Lighting::Gouraud) s.lighting = Lighting::Phong;
    s.filter = TextureFilter::Bilinear;
    s.showNormals = false;
    s.depthLegend = false;
    s.msaa = 1;  // its own N×N samples per pixel already
    return s;
}

namespace {

/// Each n×n block of `image` averaged into one pixel of a width × height truth: colours
/// clamped per sub-sample, the share of sub-samples some triangle drew.
GroundTruth averageBlocks(const reference::Image& image, int n, int width, int height) {
    GroundTruth truth;
    truth.width = width;
    truth.height = height;
    truth.samples = n;
    const std::size_t pixels = static_cast<std::size_t>(truth.width) * truth.height;
    truth.color.assign(pixels, glm::vec3(0.0f));
    truth.coverage.assign(pixels, 0.0f);
    const double perSample = 1.0 / (static_cast<double>(n) * n);
    for (int y = 0; y < truth.height; ++y) {
        for (int x = 0; x < truth.width; ++x) {
            glm::dvec3 sum(0.0);
            int covered = 0;
            for (int sy = 0; sy < n; ++sy) {
                const std::size_t row = static_cast<std::size_t>(y * n + sy) * image.width;
                for (int sx = 0; sx < n; ++sx) {
                    const std::size_t i = row + static_cast<std::size_t>(x * n + sx);
                    sum += glm::clamp(image.color[i], 0.0, 1.0);
                    // Depth-writing shaders leave a finite depth wherever a triangle drew (the
                    // Simple shader writes none, so its coverage stays 0).
                    covered += std::isfinite(image.depth[i]) ? 1 : 0;
                }
            }
            const std::size_t p = static_cast<std::size_t>(y) * truth.width + x;
            truth.color[p] = glm::vec3(sum * perSample);
            truth.coverage[p] = static_cast<float>(covered * perSample);
        }
    }
    return truth;
}

}  // namespace

Result<GroundTruth> renderGroundTruth(const Scene& scene, const RenderSettings& settings,
                                      int samples, const GroundTruthProgress& progress) {
    const int n = std::clamp(samples, 1, kMaxGroundTruthSamples);
    const RenderSettings truthSettings = groundTruthSettings(settings);
    // The frame's own camera and size as the renderers check them; then the n² image's memory,
    // since its camera may be past kMaxImageSide (1280 px at 16 samples is 20480).
    RenderSettings frameSettings = truthSettings;
    frameSettings.supersample = 1;
    if (Status st = checkFrame(scene.camera, frameSettings); !st) return st.error();
    if (!scene.mesh) return Error{{}, "the scene has no mesh"};
    if (Status st = checkReferenceImage(scene.camera.width * n, scene.camera.height * n); !st)
        return Error{{},
                     "ground truth at " + std::to_string(n) + "x" + std::to_string(n) +
                         " samples: " + st.error().message};
    // The reference render is nearly all of the time; the average after it is the last 1 %.
    reference::Progress renderProgress;
    if (progress) renderProgress = [&progress](double f) { return progress(0.99 * f); };
    // Sub-sample centres at (k + ½)/n in each pixel: the scene seen n times larger.
    Result<reference::Image> rendered = reference::renderScaledWindow(
        scene, truthSettings, n, {0, 0, scene.camera.width * n, scene.camera.height * n},
        renderProgress);
    if (!rendered) return rendered.error();
    const reference::Image& image = rendered.value();
    if (image.cancelled) {
        GroundTruth truth;
        truth.cancelled = true;
        return truth;
    }
    GroundTruth truth = averageBlocks(image, n, scene.camera.width, scene.camera.height);
    if (progress) progress(1.0);  // too late to cancel: the truth is whole
    return truth;
}

GroundTruth renderGroundTruthPixel(const Scene& scene, const RenderSettings& settings, int x, int y,
                                   int samples) {
    if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height) return {};
    // Checked before x·n, which a refused camera's size could overflow.
    if (!checkFrame(scene.camera, RenderSettings{}) || !scene.mesh) return {};
    const int n = std::clamp(samples, 1, kMaxGroundTruthSamples);
    const Result<reference::Image> image = reference::renderScaledWindow(
        scene, groundTruthSettings(settings), n, {x * n, y * n, n, n});
    if (!image) return {};
    return averageBlocks(image.value(), n, 1, 1);
}

}  // namespace facet
