#pragma once
// The depth-precision sweep (issue 6, part 3): two parallel planes δ apart at a growing distance
// d from the camera, the far one drawn first; wherever the far one still shows, depth failed to
// tell them apart (z-fighting). The depth format is the engine's only one: float camera-space
// z, 1 / (interpolated 1/w).

#include <vector>

#include "sweep_table.hpp"

namespace facet::app {

/// One distance and relative gap: how much of the far plane shows through the near one.
struct DepthPoint {
    double distance = 0.0;     ///< d, camera to the planes along the view axis
    double relativeGap = 0.0;  ///< δ / d
    double fighting = 0.0;     ///< share (0…1) of the covered pixels where the far plane shows
};

/// The share of the far plane showing through for planes δ apart at distance d: two 60°-tilted
/// quads covering a 64 × 64 view, far (green) then near (red), depth test LESS.
double zFightingShare(double distance, double delta);

/// The distances swept: 1 to 1e4 (1, 100, 1e4 when quick).
std::vector<double> depthDistances(bool quick);

/// Runs the sweep: per distance, δ/d from 1e-3 down a quarter-octave ladder to 1e-9.
std::vector<DepthPoint> sweepDepth(const SweepOptions& options);

/// The smallest δ/d at `distance` that resolves (no fighting) together with every larger step
/// of the ladder; 0 when even the largest fights.
double smallestResolvedGap(const std::vector<DepthPoint>& points, double distance);

/// The table "depth": distance, relative_gap, fighting, smallest_resolved (δ/d, per distance).
SweepTable depthTable(const std::vector<DepthPoint>& points);

}  // namespace facet::app
