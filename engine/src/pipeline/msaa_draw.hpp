#pragma once
// The multisampled triangle draw (RenderSettings::msaa > 1), compiled in a translation unit of
// its own (msaa_draw.cpp): its pixel-loop instances then leave the compiler's inlining choices
// for the one-sample loops in renderer.cpp as they were.

#include "binning/tiles.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/framebuffer.hpp"
#include "pipeline/variants.hpp"

namespace facet::detail {

/// Draws the triangles of `input` with variant `key` into `samples` (the per-sample buffer,
/// already sized and filled) at `count` samples per pixel of a width × height frame.
void drawMsaaTriangles(TileRenderer& tiles, const VariantKey& key, const DrawInput& input,
                       const RenderSettings& settings, const DrawConstants& constants,
                       Framebuffer& samples, int count, int width, int height, int subdivision,
                       int threads, int subPixelBits, RenderStats& stats);

}  // namespace facet::detail
