// Test helper: the pieces of validation (6b)'s loop model — the contour method of `catena loop`
// (strength::solve) the level and the inclined conveyor are compared with
// (tests/validation/dynamics_conveyor_*_test.cpp): a straight run of the chain's weight, the
// take-up at the drive's slack side, the tail idler and the drive.
#pragma once

#include "catena/strength/loop.hpp"

namespace catena::dynamics::testing {

// A straight run `length` [m] long at `incline` [rad] (its travel's rise), of chain weight
// `chain_weight` [N/m] and resistance factor `resistance` (μ on a guide, 0 unsupported).
inline strength::Segment loop_straight(const char* name, double length, double incline,
                                       double chain_weight, double resistance) {
  strength::Segment g;
  g.kind = strength::SegmentKind::kStraight;
  g.name = name;
  g.length = length;
  g.incline = incline;
  g.chain_weight = chain_weight;
  g.resistance = resistance;
  return g;
}

// The take-up at the drive's slack side, set to `pretension` [N] (the simulated slack tension).
inline strength::Segment loop_takeup(double pretension) {
  strength::Segment t;
  t.kind = strength::SegmentKind::kTakeup;
  t.pretension = pretension;
  return t;
}

// The tail idler: a turn of factor 1 (the wheels' polygon losses left out).
inline strength::Segment loop_idler() {
  strength::Segment i;
  i.kind = strength::SegmentKind::kTurn;
  i.factor = 1.0;
  return i;
}

inline strength::Segment loop_drive() {
  strength::Segment dr;
  dr.kind = strength::SegmentKind::kDrive;
  return dr;
}

}  // namespace catena::dynamics::testing
