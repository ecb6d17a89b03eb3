#pragma once
// Supersampling (RenderSettings::supersample): the frame rendered at N×N the size and averaged
// down, so coverage, texture and lighting are sampled N² times per pixel. Costs about N² times a
// frame; it is the engine's answer to silhouette aliasing, and a point on `facet accuracy`'s chart.
//
// The big image's camera is resizedCamera() to n times the size: width, height and focal times n.
// The principal point is half the image (conventions §4), so big pixel (I + ½, J + ½) lands at
// ((I + ½)/n, (J + ½)/n) in the frame's pixels: an even n×n grid of sample centres in each pixel.

#include "facet/framebuffer.hpp"

namespace facet::detail {

/// Largest accepted samples per axis (16 per pixel).
inline constexpr int kMaxSupersample = 4;

/// Averages each bx×by block of `big` into one pixel of `out` (resized to big / block): each
/// channel the rounded mean of the 8-bit values (alpha too), depth the nearest of the block
/// (empty only if all are). The box filter of supersampling (n×n blocks) and of multisampling's
/// resolve (SampleBlock, facet/multisample.hpp).
void resolveSupersampled(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads);

/// Multisampling's start: `samples` resized to `frame` times the block and every sample set to
/// its pixel's colour and depth, so a draw continues what is in the frame.
void expandToSamples(const Framebuffer& frame, int bx, int by, Framebuffer& samples, int threads);

}  // namespace facet::detail
