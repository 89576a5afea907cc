// Pocket wheel (chain wheel) for round-link chain: the bi-regular polygon of joint centres.
//
// Source: 003 (Dolipiński, Reich, Adamowicz, Ziegler), eqs. (6)–(9). A round-link chain on a
// pocket wheel alternates horizontal and vertical links, so the centres of the working joints
// lie on the pitch circle at alternating distances t + d and t − d.
#pragma once

#include <vector>

#include "catena/core/error.hpp"

namespace catena::pocketwheel {

/// The chain and the wheel (constant model).
struct PocketWheel {
  double pitch = 0.0;  ///< [m] chain pitch t (inner length of a link)
  double wire = 0.0;   ///< [m] wire diameter d of the links
  int teeth = 0;       ///< [-] number of teeth z (pockets for horizontal links)
};

/// All problems with a wheel at once: t > 0, d > 0, t > d, z ≥ 3.
std::vector<Issue> validate(const PocketWheel& wheel);

/// Derived geometry of the wheel.
struct WheelGeometry {
  double pitch_radius = 0.0;             ///< [m] R, eq. (6)
  double delta1 = 0.0;                   ///< [rad] central angle of the t + d side, eq. (7)
  double delta2 = 0.0;                   ///< [rad] central angle of the t − d side, eq. (8)
  double tooth_angle = 0.0;              ///< [rad] 2π/z = δ1 + δ2, eq. (9)
  double transverse_displacement = 0.0;  ///< [m] Δy = R(1 − cos(δ1/2)), free run-on
  double chordal_height = 0.0;           ///< [m] H of the chordal guide, R cos(δ1/2)
};

/// Computes R, δ1, δ2 from eqs. (6)–(8). Throws InputError if validate() fails.
WheelGeometry wheel_geometry(const PocketWheel& wheel);

}  // namespace catena::pocketwheel
