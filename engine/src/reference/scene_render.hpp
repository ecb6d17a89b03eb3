#pragma once
// What the evaluation library calls in the reference renderer without its checks: the ground
// truth renders a camera n times the frame's size, past kMaxImageSide, after checking the frame's
// own camera and its n² image's memory itself (ground_truth.cpp).

#include "facet/reference.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::reference::detail {

/// renderWindow() without its checks: the caller has checked the camera and the memory.
Image renderWindowUnchecked(const Scene& scene, const RenderSettings& settings,
                            const Window& window, const Progress& progress = {});

}  // namespace facet::reference::detail
