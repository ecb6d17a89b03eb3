#pragma once
// The sub-pixel precision sweep (issue 6, part 3): the fast path snapped to 1/2^b px for several
// b, against the exact (unsnapped, double) coverage of the reference path and against the
// supersampled ground truth, with its frame time and a crack check at every b.

#include <cstddef>
#include <string>
#include <vector>

#include "facet/evaluation/frame_times.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/scene.hpp"
#include "sweep_table.hpp"

namespace facet::app {

/// One scene at one grid.
struct SubPixelPoint {
    std::string scene;  ///< "sphere", "fan", or a shared scene's stem ("bunny", "spot")
    int bits = 8;       ///< fractional bits of the snapping grid
    int width = 0, height = 0;
    std::size_t triangles = 0;
    std::size_t covered = 0;  ///< pixels the exact coverage covers (reference depth finite)
    /// Pixels whose visible triangle (or none) differs from the exact coverage's.
    std::size_t differ = 0;
    /// Of those, the ones the reference flags ambiguous (a centre within 1/256 px of an edge, or
    /// a depth tie): all of them at 8 bits, fewer and fewer as the grid gets coarser.
    std::size_t differAmbiguous = 0;
    /// Pixels where the front-minus-back coverage differs from the winding number of the mesh's
    /// snapped open edges: a crack or a doubly drawn pixel on a shared edge. 0 at every grid.
    std::size_t cracks = 0;
    /// Pixels drawn more (or fewer) times than at 8 bits: the snapped mesh folding over (a thin
    /// triangle flipped) or a silhouette moving, never a crack (cracks would show above).
    std::size_t layersChanged = 0;
    ImageError error;  ///< the scene's picture (baseSettings()) against its ground truth
    FrameTimes times;  ///< Renderer::render, whole frame, one thread (ms)
};

/// The grids swept: 2…8 bits, or 4, 6, 8 in quick mode.
std::vector<int> subPixelSweepBits(bool quick);

/// The procedural scenes of the sweep, at the given size: "sphere" (a 16×32 UV sphere, slivers
/// at the poles) and "fan" (720 triangles of half a degree around one vertex, tilted).
Scene subPixelScene(const std::string& name, int width, int height);

/// Measures every grid on the sphere, the fan and, when `options.shared` holds them, the bunny
/// and Spot: 320×240 (shared scenes 320×180), quick mode 160×120 (160×90) with a 4×4 ground
/// truth instead of 8×8. Times options.frames frames per point on one thread after one warm-up,
/// round-robin.
std::vector<SubPixelPoint> sweepSubPixel(const SweepOptions& options);

/// The sweep as the "subpixel" table: one row per scene and grid.
SweepTable subPixelTable(const std::vector<SubPixelPoint>& points);

}  // namespace facet::app
