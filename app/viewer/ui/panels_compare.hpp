#pragma once
// Compare panel and the labels over the frame: which interpolation each side uses (or, with
// the CPU | OpenGL renderer, which renderer), split or difference, and the error numbers of the
// two pictures.

#include "compare.hpp"
#include "layout.hpp"
#include "renderer_choice.hpp"

namespace facet::view {

struct AccuracyState;
struct ViewerModel;

/// What Compare shows and what its last two-sided frame measured.
struct CompareState {
    CompareSettings settings;  ///< the Compare panel's choices
    CompareView sides;         ///< two-sided frames' numbers and the CPU | OpenGL picture
};

/// Compare: the two interpolations, split or difference, divider, error numbers, then the
/// ground-truth section (panels_accuracy.hpp).
void comparePanel(CompareState& compare, ViewerModel& model, AccuracyState& accuracy);

/// Labels over the frame shown in `view` naming each side (and the difference's colour bar);
/// `scale` is the UI scale.
void compareOverlay(const CompareState& compare, RendererChoice renderer, const Rect& view,
                    float scale);

}  // namespace facet::view
