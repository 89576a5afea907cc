// Rolling kinematics of the hinge: contact point, roller centre, feature points, pitch change
// (seed 000 eqs. (8)–(9), (11), (14)–(19), corrected; see docs/models/hinge.md).
#pragma once

#include <vector>

#include "catena/hinge/hinge.hpp"

namespace catena::hinge {

struct Point {
  double x = 0.0;  ///< [m]
  double y = 0.0;  ///< [m]
};

/// The hinge at one mutual link angle φ, in the plate frame (see hinge.hpp).
struct Pose {
  double phi = 0.0;    ///< [rad] mutual turn of the links
  double gamma = 0.0;  ///< [rad] turn of the roller relative to the plate, φ/2 (eq. 3); the
                       ///< roller is rotated by −γ in the plate frame
  double psi1 = 0.0;   ///< [rad] contact angle on the plate's arc (eqs. 1–2)
  double psi2 = 0.0;   ///< [rad] contact angle on the roller's face (0 for flat faces)
  Point contact;       ///< M1, eqs. (8)–(9)
  Point centre;        ///< O2, eqs. (18)–(19)
  double v1 = 0.0;     ///< [m] V1 of eqs. (18)–(19), derived (docs)
  double v2 = 0.0;     ///< [m] V2 of eqs. (18)–(19), derived (docs)
};

/// Pose at φ for a hinge whose roller face radius is `r2` (+∞ or ignored for flat faces).
Pose pose(const Hinge& hinge, double r2, double phi);

/// A point fixed in the roller (body coordinates about its centre) seen in the plate frame, eq.
/// (11).
Point roller_point(const Pose& pose, Point body);

/// [m] Δt(φ) = t(φ) − t(0) with both hinges of the link turned by φ: twice the shift of one
/// roller centre along the plate axis (the thesis' convention of eq. 14). Negative = shorter.
double pitch_change(const Hinge& hinge, double r2, double phi);

/// The roller's feature points (body coordinates): the four corners where the working faces meet
/// the cylindrical part, in the order (+x,+y), (+x,−y), (−x,+y), (−x,−y).
std::vector<Point> feature_points(const Hinge& hinge, double r2);

}  // namespace catena::hinge
