#pragma once
// Stability sweep "camera_paths": whole frames of a mesh along camera paths that stress the
// pipeline (issue 6): flying through the mesh, grazing the near plane, backing away until the
// mesh is sub-pixel, and turning the y hint onto the view axis (the degenerate look-at). Each
// frame is drawn by the fast path and the reference; no NaN, no coverage difference outside the
// reference's ambiguity mask, colours within 1 LSB (perspective, Gouraud).

#include <cstddef>
#include <string>
#include <vector>

#include "facet/evaluation/reference_compare.hpp"
#include "sweep_table.hpp"

namespace facet::app {

/// One frame of one path. Paths and what `param` is for each:
///   fly_<mesh>: position along the flight line, in bounding-box diagonals from the centre;
///   grazing_at / grazing_along_<mesh>: the eye's distance from the mesh's outermost vertex in
///     near distances, looking at the surface / along it;
///   far_<mesh>: the eye's distance from the mesh's centre over the scene's own distance;
///   up_hint_<mesh>: how far the y hint is off the view axis (its x over its y), 0 = on it.
/// <mesh> is spot and bunny from the shared data, or knot (a procedural torus knot) without it.
struct CameraPoint {
    std::string path;
    std::string label;  ///< the frame in a few characters ("t=-0.35", "k=1.01", "eps=1e-07")
    int step = 0;       ///< frame index along the path
    double param = 0.0;
    int width = 0, height = 0;
    double ms = 0.0;            ///< fast path's render(): median ms after a warm-up, one thread
    double msMin = 0.0;         ///< fastest timed frame
    double msMax = 0.0;         ///< slowest timed frame
    int frames = 0;             ///< timed frames
    double refMs = 0.0;         ///< the reference's render of the same frame, ms (one run)
    std::size_t triangles = 0;  ///< triangles submitted
    std::size_t clipped = 0;    ///< triangles clipped (near plane or guard band)
    std::size_t fragments = 0;  ///< fragments that passed coverage
    ReferenceDiff diff;         ///< the frame against the reference's
    bool mustDraw = false;      ///< the reference covers pixels outside its ambiguity mask
    bool degenerate = false;    ///< the camera is invalid (checkCamera fails): nothing may draw
};

/// Runs every path: 160×90 (64×36 quick), options.frames timed frames per point, fewer frames
/// per path when options.quick. Meshes from options.shared + "/data/scenes/" when present.
std::vector<CameraPoint> sweepCameraPaths(const SweepOptions& options);

/// The points as the chart's table, name "camera_paths", one row per frame.
SweepTable cameraTable(const std::vector<CameraPoint>& points);

}  // namespace facet::app
