#pragma once
// What `facet accuracy` measures: per scene, each of the fast path's approximations as one
// method (one RenderSettings), all judged against one ground truth of the scene.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "facet/evaluation/frame_times.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::app {

/// One way of drawing a scene: its axis ("interp", "filter", "lighting"), its name and settings.
struct AccuracyMethod {
    std::string axis;
    std::string name;
    RenderSettings settings;
};

/// The scene's base settings: textured scenes (a texture and uvs) use the texture shader,
/// combined with Phong lighting; the others painter with Phong. Perspective, trilinear.
RenderSettings baseSettings(const Scene& scene);

/// The methods for a scene, each the base with one axis changed: interpolation affine,
/// subdivided 8/16/32, perspective; texture nearest/bilinear/trilinear (textured scenes only);
/// lighting Gouraud/Phong; samples per pixel 1x1, 2x2, 4x4 (supersampling), msaa2, msaa4, msaa8
/// (multisampling). All share the base's
/// ground truth (groundTruthSettings()).
std::vector<AccuracyMethod> accuracyMethods(const Scene& scene);

/// The methods around given settings (the viewer's: shader, combine, lighting as the user set
/// them), made Solid without the normals or the legend, like the ground truth: interpolation
/// always; texture filters with the Texture shader on a textured scene; Gouraud/Phong when the
/// settings light and the shader shows it; samples 1x1, 2x2, 4x4, msaa2/4/8 always.
/// accuracyMethods(scene)
/// is this with baseSettings().
std::vector<AccuracyMethod> accuracyMethods(const Scene& scene, const RenderSettings& base);

/// The methods a ground truth of samples×samples per pixel can judge: those with fewer samples
/// per pixel than it (N×N supersampled: N², multisampled: its count), coarser than the truth. A
/// method as fine as the truth or finer would be measured against itself or against something
/// coarser, and rank "better" than methods that are. The names of the others, comma separated,
/// go to `leftOut`. `facet accuracy` and the viewer's Compare panel both measure only these.
std::vector<AccuracyMethod> methodsBelowTruth(const std::vector<AccuracyMethod>& methods,
                                              int samples, std::string* leftOut = nullptr);

/// RMSEs within this share of each other count as equal on the Pareto front.
inline constexpr double kParetoRmseTie = 1e-3;

/// A measured point: median time and error.
struct ParetoPoint {
    double ms = 0.0;    ///< median frame time
    double rmse = 0.0;  ///< error against the ground truth
};

/// Which points lie on the Pareto front of (time, RMSE): those no other point beats, at least as
/// good on both and better on one (RMSEs within kParetoRmseTie being equal). The chart of
/// `facet accuracy`, its CSV and the viewer's table mark the same ones.
std::vector<bool> onParetoFront(const std::vector<ParetoPoint>& points);

/// One method measured: the engine's median frame time and its error.
struct AccuracyResult {
    std::string scene;  ///< the scene file's stem
    std::string axis;
    std::string method;
    int width = 0, height = 0;
    FrameTimes times;  ///< the engine's frame times (ms)
    ImageError error;
};

/// Times every method round-robin: `warmup` untimed frames each, then per round one timed frame
/// each, so a stretch when another process holds the cores slows every method alike instead of
/// the one that happened to be measured then. Each timed frame right follows an untimed one of
/// the same method, so no method is timed with the previous method's data in the caches.
/// `beforeRender`, when set, is called with the method's index before each round's frames of it
/// (progress; it may throw to stop). Returns the frame times (ms) per method.
std::vector<std::vector<double>> timeMethods(
    Renderer& renderer, const Scene& scene, const std::vector<AccuracyMethod>& methods, int frames,
    int warmup, Framebuffer& frame, const std::function<void(std::size_t)>& beforeRender = {});

}  // namespace facet::app
