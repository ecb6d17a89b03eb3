#pragma once
// The tessellation-and-highlights sweep (issue 6, part 3): a white UV sphere lit by its
// specular term alone, at several tessellations and growing shininess s. Gouraud evaluates the
// highlight at vertices only; once the highlight is narrower than a face it falls between them
// and Gouraud loses it, while Phong keeps it.

#include <vector>

#include "sweep_table.hpp"

namespace facet::app {

/// One tessellation at one shininess, Gouraud against Phong.
struct HighlightPoint {
    int rings = 0;  ///< the sphere has `rings` rings and 2·rings sectors
    double shininess = 0.0;
    int gouraudPeak = 0;  ///< brightest channel value (0…255) of the Gouraud image
    int phongPeak = 0;    ///< the same for Phong
    /// gouraudPeak / phongPeak: 1 when Gouraud keeps the highlight, 0 when it lost it.
    double peakRatio = 0.0;
    /// Gouraud's and Phong's RMSE (8-bit steps) against the ground truth over the pixels it
    /// covers fully: how much of the picture each gets wrong, not just the peak.
    double gouraudRmse = 0.0;
    double phongRmse = 0.0;
    double gouraudMs = 0.0, phongMs = 0.0;  ///< median frame times
};

/// The shininess values swept: 1 to 1024, factors of 4.
std::vector<double> highlightShininess();

/// The tessellations swept: rings 8, 16, 32, 64 (8, 16, 32 when quick).
std::vector<int> highlightRings(bool quick);

/// Runs the sweep at 96 × 96 pixels (every tessellation × shininess).
std::vector<HighlightPoint> sweepHighlights(const SweepOptions& options);

/// The smallest shininess with Gouraud's peak below half of Phong's for `rings`, or 0 when
/// Gouraud keeps at least half the peak at every swept shininess.
double highlightLostAt(const std::vector<HighlightPoint>& points, int rings);

/// The table "highlights": rings, shininess, gouraud_peak, phong_peak, ratio, gouraud_rmse,
/// phong_rmse, gouraud_ms, phong_ms.
SweepTable highlightsTable(const std::vector<HighlightPoint>& points);

}  // namespace facet::app
