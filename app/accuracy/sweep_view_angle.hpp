#pragma once
// The view-angle sweep (issue 6, part 3): a textured surface seen from face-on (0°) to almost
// edge-on (89°), drawn with each interpolation and measured against the ground truth. Where
// affine fails (the texture slides as depth varies across a triangle) and how far subdivision
// pushes that failure.

#include <string>
#include <vector>

#include "sweep_table.hpp"

namespace facet::app {

/// One surface at one angle drawn with one interpolation.
struct ViewAnglePoint {
    std::string surface;  ///< "facet" (the course's textured unit square) or "floor" (1 × 16)
    double degrees = 0.0;
    std::string method;  ///< "affine", "subdivided:N" or "perspective"
    /// Against the ground truth over the pixels it covers fully (no silhouette aliasing):
    double rmse = 0.0;      ///< RMS channel error, 8-bit steps
    double maxError = 0.0;  ///< largest channel error
    double over2Lsb = 0.0;  ///< share of those pixels more than 2 LSB off
    std::size_t pixels = 0;
    /// Against the one-sample perspective reference over its covered, unambiguous pixels: the
    /// interpolation's own error, without the filtering and sampling the ground truth adds.
    double rmseReference = 0.0;
    int maxReference = 0;
    double ms = 0.0;  ///< median frame time (options.frames after one warm-up)
};

/// The angles swept: 0° to 89°, denser near face-on where affine starts to fail.
std::vector<double> viewAngles(bool quick);

/// Runs the sweep: the facet and the floor, every angle, affine / subdivided 8, 16, 32 /
/// perspective. The texture is the course's brick.jpg from options.shared when it is there,
/// else a generated brick pattern. Trilinear filtering, 160 × 160 (96 × 96 quick).
std::vector<ViewAnglePoint> sweepViewAngle(const SweepOptions& options);

/// The table "view_angle": surface, degrees, method, rmse, max, over2, pixels, rmse_reference,
/// max_reference, ms.
SweepTable viewAngleTable(const std::vector<ViewAnglePoint>& points);

}  // namespace facet::app
