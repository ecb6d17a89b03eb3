#pragma once
// The debug views' numbers (facet/debug_view.hpp) from what the instrumented draws counted
// (probe.hpp) or from two frames.

#include <cstdint>
#include <vector>

#include "debug/probe.hpp"
#include "facet/debug_view.hpp"

namespace facet::detail {

/// The settings of the frame a debug view is drawn over: the view off, solid, one sample, no
/// overlays; the texture shader with trilinear filtering for TextureLod.
RenderSettings debugViewBase(const RenderSettings& settings);

/// Overdraw, TriangleSize, DepthTest or TextureLod from an instrumented draw of the frame.
void fillFromProbe(DebugView view, const DrawProbe& probe, int mipLevels, DebugMap& map);

/// BinLoad: each pixel gets the count of its tile (countBinLoad()).
void fillBinLoad(const std::vector<std::uint32_t>& perTile, int width, int height, DebugMap& map);

/// InterpError: per pixel the largest channel difference between two renders of the same
/// frame; NaN where neither drew (both depths empty).
void fillInterpError(const Framebuffer& perspective, const Framebuffer& affine, DebugMap& map);

}  // namespace facet::detail
