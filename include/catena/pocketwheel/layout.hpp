// Where the chain is at the start of a period (φ = 0): the joint centres seated on the wheel and
// the free strand, in the run-on frame (docs/models/pocketwheel.md: wheel axis at the origin,
// strand along +x on the upper side, θ from the upward vertical, positive upstream). For
// drawings; pure geometry from the plan.
#pragma once

#include <numbers>
#include <utility>
#include <vector>

#include "catena/pocketwheel/run_on.hpp"

namespace catena::pocketwheel {

struct ChainLayout {
  /// [m] seated joint centres on the pitch circle, the crank (last seated) first, then
  /// downstream; consecutive ones alternate t + d and t − d apart
  std::vector<std::pair<double, double>> seated;
  /// [m] the free strand from the crank upstream: to the guide end (−l, H) and along the guide
  /// for a guided run-on; a horizontal line for a free run-on
  std::vector<std::pair<double, double>> strand;
};

/// The layout at φ = 0 with the chain wrapped over `wrap` radians downstream of the crank.
ChainLayout chain_layout(const PocketWheel& wheel, const RunOnPlan& plan,
                         double wrap = std::numbers::pi);

}  // namespace catena::pocketwheel
