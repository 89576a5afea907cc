// The plate's figured aperture (seed 000 §1.3.2, figs. 2, 7): the hole that guides the roller
// in every position between φ = 0 and φmax.
//
// Construction: the roller's true outline (d circle cut by its two working faces) is placed at
// `poses` turns from 0 to φmax by the closed-form kinematics; the aperture is the region swept
// by it, dilated by the clearance, and bounded by the plate's convex working arc R1 (plate
// material, on which the roller rolls without clearance). The contour is traced along rays from
// the roller's centre at φ = 0: at each ray the farthest point of the swept, dilated region,
// or the plate's arc where that is nearer. The thesis builds the same hole from the feature
// points' trajectories (eq. 11); the swept outline contains those trajectories.
#pragma once

#include <vector>

#include "catena/hinge/kinematics.hpp"

namespace catena::hinge {

/// The roller's outline in its body frame, counter-clockwise, `per_arc` points per arc (four
/// arcs: two of the d circle, two faces), not repeating the first point.
std::vector<Point> roller_outline(const Hinge& hinge, double r2, int per_arc = 180);

struct ApertureOptions {
  double clearance = 0.5e-3;  ///< [m] between the roller and the aperture off the working arc
  int rays = 1440;            ///< contour points (angular resolution)
  int poses = 91;             ///< roller positions from 0 to φmax
};

struct Aperture {
  std::vector<Point>
      contour;             ///< closed (last point joins the first), plate frame, counter-clockwise
  double clearance = 0.0;  ///< [m]
  int working_points = 0;  ///< contour points lying on the plate's working arc R1
};

/// Builds the aperture. `r2` as for pose() (+∞ or ignored for flat faces).
Aperture aperture(const Hinge& hinge, double r2, const ApertureOptions& options = {});

}  // namespace catena::hinge
