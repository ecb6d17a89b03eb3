#pragma once
// Meshes made from formulas: the default scene's model, test geometry and benchmark loads.

#include <cstdint>

#include "facet/mesh.hpp"

namespace facet {

/// A (p,q) torus knot swept by a circular tube, coloured by a hue ramp along the knot.
/// `segments` around the knot, `sides` around the tube; closed and consistently wound.
Mesh makeTorusKnot(int p, int q, int segments, int sides, float tubeRadius = 0.18f);

/// A UV sphere of radius 1 with `rings` latitude bands and `sectors` longitude bands, uv
/// wrapping once around (u) and pole to pole (v), coloured by the normal.
Mesh makeUvSphere(int rings, int sectors);

/// A unit square grid in the XY plane (z = 0) of cols × rows cells, two triangles each, with
/// interior vertices jittered by up to `jitter` of a cell (deterministic from `seed`).
/// Below 0.25 no triangle can fold over.
Mesh makeJitteredGrid(int cols, int rows, float jitter, std::uint32_t seed);

/// `mesh` with each vertex coloured by its place in the bounding box (x, y, z as r, g, b), so
/// interpolation errors show as colour differences on a white or textured mesh.
Mesh colouredByPosition(Mesh mesh);

}  // namespace facet
