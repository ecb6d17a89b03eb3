#pragma once
// What `facet accuracy` measures: per scene, each of the fast path's approximations as one
// method (one RenderSettings), all judged against one ground truth of the scene.

#include <string>
#include <vector>

#include "facet/ground_truth.hpp"
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
/// lighting Gouraud/Phong. All share the base's ground truth (groundTruthSettings()).
std::vector<AccuracyMethod> accuracyMethods(const Scene& scene);

/// One method measured: the engine's median frame time and its error.
struct AccuracyResult {
    std::string scene;  ///< the scene file's stem
    std::string axis;
    std::string method;
    int width = 0, height = 0;
    double medianMs = 0.0, minMs = 0.0, maxMs = 0.0;
    int frames = 0;
    ImageError error;
};

}  // namespace facet::app
