#pragma once
// Stability sweep "extreme": single triangles at the limits the rasterizer must survive (issue 6),
// drawn by the fast path (the advanced draw(), clip-space input) and by the double-precision
// reference from the same floats. Per case: the time per draw, what each covered, where they
// disagree outside the reference's ambiguity mask (must be nowhere) and NaN depth (never).

#include <cstddef>
#include <string>
#include <vector>

#include "facet/evaluation/reference_compare.hpp"
#include "sweep_table.hpp"

namespace facet::app {

/// One triangle case measured. Families and what `param` is for each:
///   size, size_pixel_centre: edge length in px of a near-equilateral triangle (1e-4 … 1e6),
///     centred on a generic point or on a pixel centre;
///   sliver, sliver_long: aspect ratio long edge / height (1 … 1e6), long edge 1e3 / 1e6 px;
///   far_wedge, far_vertex: the far vertices' coordinate magnitude in px (1e2 … 1e7);
///   near_vertex: clip w of one vertex at a fixed pixel, through the near plane (0.01) to < 0;
///   near_fixed_clip: clip w of one vertex with fixed clip x, y (its pixel runs off to infinity);
///   nonfinite: a triangle with one NaN / ±inf clip coordinate, alone (param: case index);
///   nonfinite_mixed: the same followed by a good triangle, which must draw as if alone.
struct ExtremePoint {
    std::string family;
    std::string label;  ///< the case in a few characters ("L=1e-4", "w=-0.01", "x=nan")
    int step = 0;       ///< index within the family
    double param = 0.0;
    int width = 0, height = 0;
    double fastUs = 0.0;        ///< fast path, one thread: median µs per draw after a warm-up
    double fastUsMin = 0.0;     ///< fastest timed draw, µs
    double fastUsMax = 0.0;     ///< slowest timed draw, µs
    int frames = 0;             ///< timed draws
    double refMs = 0.0;         ///< the reference's draw of the same input, ms (one run)
    std::size_t fragments = 0;  ///< fast path's fragments (RenderStats)
    std::size_t clipped = 0;    ///< triangles the fast path clipped (near plane or guard band)
    /// Fast frame against the reference of the expected input (the input itself, or for the
    /// non-finite families what must remain of it: nothing, or the good triangle alone).
    ReferenceDiff diff;
    bool mustDraw = false;    ///< the reference covers pixels outside its ambiguity mask
    bool exactColor = false;  ///< the engine claims colours within 1 LSB here (perspective)
};

/// Runs every case: options.quick takes fewer points and a 64×48 image instead of 256×192.
std::vector<ExtremePoint> sweepExtreme(const SweepOptions& options);

/// The points as the chart's table, name "extreme", one row per point.
SweepTable extremeTable(const std::vector<ExtremePoint>& points);

}  // namespace facet::app
