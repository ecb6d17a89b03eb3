#pragma once
// Ground truth: what a pixel should be when it is the average of the scene over its square, not
// a single sample at its centre. Built on the reference path (reference.hpp), which stays the
// oracle for the fast path's rules; this is the yardstick for how far from the ideal each of the
// fast path's approximations (affine, subdivided, nearest, Gouraud...) lands, measured by
// image_metrics.hpp.

#include <cstddef>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/error.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

/// Supersampling per axis when none is asked for: 8×8 = 64 samples per pixel.
inline constexpr int kDefaultGroundTruthSamples = 8;
/// Largest accepted samples per axis (the supersampled image is samples² times the frame).
inline constexpr int kMaxGroundTruthSamples = 16;

/// A ground-truth image in linear float, before any 8-bit rounding.
struct GroundTruth {
    int width = 0;
    int height = 0;
    int samples = 0;               ///< per axis: each pixel averages samples² sub-samples
    std::vector<glm::vec3> color;  ///< RGB in [0,1] (each sub-sample clamped), row 0 at the top
    std::vector<float> coverage;   ///< share of the pixel's sub-samples some triangle drew, k/N²
    bool cancelled = false;        ///< the progress callback stopped it: empty, width 0
};

/// Told how far a ground truth got (0…1), from the thread rendering it, every half percent or
/// so; returning false cancels it. The same type as reference::Progress.
using GroundTruthProgress = std::function<bool(double fraction)>;

/// The settings the ground truth is rendered with: Solid, perspective-correct interpolation,
/// Phong in place of Gouraud, bilinear on level 0 in place of any texture filter, no
/// multisampling; the rest
/// (shader, combine, culling, background, near plane) as given.
RenderSettings groundTruthSettings(const RenderSettings& settings);

/// Renders the scene with groundTruthSettings() at samples×samples sub-samples per pixel, box
/// filtered. `samples` is clamped to 1…kMaxGroundTruthSamples. With `progress`, a render it
/// cancels returns an empty GroundTruth with `cancelled` set. An error (checkFrame's for the
/// frame's camera and size, or the supersampled image beyond kMaxReferenceBytes) instead.
Result<GroundTruth> renderGroundTruth(const Scene& scene, const RenderSettings& settings,
                                      int samples = kDefaultGroundTruthSamples,
                                      const GroundTruthProgress& progress = {});

/// The ground truth of pixel (x, y) alone, a 1×1 GroundTruth: the reference renders only that
/// pixel's samples×samples sub-samples (reference::renderWindow), so it costs the triangles'
/// setup, not a whole frame. Equal to renderGroundTruth()'s pixel (x, y), except with the Depth
/// shader, whose colours then map the pixel's own depth range. Empty (width 0) outside the image
/// or for a camera checkFrame() refuses.
GroundTruth renderGroundTruthPixel(const Scene& scene, const RenderSettings& settings, int x, int y,
                                   int samples = kDefaultGroundTruthSamples);

}  // namespace facet
