#pragma once
// The Compare view: the same scene and camera rendered twice with two interpolations (affine
// on the left and perspective-correct on the right by default), shown side by side across a
// movable divider, or as a heat map of their per-pixel difference, with the numbers.

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// What the Compare view shows.
enum class CompareDisplay {
    Split,       ///< left interpolation left of the divider, right one right of it
    Difference,  ///< heat map of the per-pixel error (black: equal)
};

/// The Compare panel's choices: plain data the panels edit and a frame compares with ==.
struct CompareSettings {
    bool enabled = false;                       ///< the viewer shows this instead of one frame
    InterpSpec left{Interp::Affine, 16};        ///< interpolation of the left side
    InterpSpec right{Interp::Perspective, 16};  ///< interpolation of the right side
    double divider = 0.5;                       ///< divider position, fraction of the width
    CompareDisplay display = CompareDisplay::Split;
    int heatScale = 0;  ///< error shown brightest; 0: the largest error of the frame

    /// Every field equal.
    bool operator==(const CompareSettings&) const = default;
};

/// Two renders of one view and what differs between them: the renderers and buffers.
struct CompareView {
    Renderer leftRenderer;  ///< separate instances: each keeps its own scratch buffers
    Renderer rightRenderer;
    Framebuffer leftFrame;
    Framebuffer rightFrame;
    Framebuffer shown;  ///< the composed picture (split or heat map)
    RenderStats leftStats;
    RenderStats rightStats;
    ImageDiff diff;  ///< left against right, over the pixels either covers (DiffPixels::covered)
    std::string refused;  ///< why a side drew nothing (checkFrame's message), or empty

    /// Renders both sides with `settings`, each with the interpolation `compare` gives it.
    void renderSides(const Scene& scene, const RenderSettings& settings,
                     const CompareSettings& compare);

    /// Compares the two sides and composes `shown` (split or heat map, as `compare` says).
    const Framebuffer& compose(const CompareSettings& compare);

    /// renderSides() then compose().
    const Framebuffer& render(const Scene& scene, const RenderSettings& settings,
                              const CompareSettings& compare);
};

/// Compares `left` with `right` (the numbers over the pixels either side covers) and composes
/// `shown`: the
/// split at `divider` (a fraction of the width) or the heat map up to `heatScale` (0: the
/// largest error). The Compare view's two interpolations and the CPU | OpenGL view both use it.
ImageDiff composeSides(const Framebuffer& left, const Framebuffer& right, CompareDisplay display,
                       double divider, int heatScale, Framebuffer& shown);

/// Divider column for a frame width: round(fraction · width), clamped to [0, width].
int dividerColumn(double fraction, int width);

/// Left columns [0, column) from `a`, the rest from `b`, and a 1-pixel white line at `column`
/// when it lies inside the frame; a and b must have the same size.
void composeSplit(const Framebuffer& a, const Framebuffer& b, int column, Framebuffer& out);

}  // namespace facet::view
