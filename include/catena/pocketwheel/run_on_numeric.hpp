// Independent numerical solution of the pocket-wheel run-on, for validating the closed forms.
//
// Nothing here uses eqs. (6)–(43) of 003: the pitch radius is the root of the polygon's closure
// condition, joint positions are rotated vectors, the guided point is found by Newton's method on
// the bar-length constraint, seating events are roots of "the next joint's distance from the
// axis equals R" found by scanning and bracketing, and velocities and accelerations are
// fourth-order central differences of the solved positions.
#pragma once

#include <cstddef>
#include <vector>

#include "catena/pocketwheel/run_on.hpp"

namespace catena::pocketwheel::numeric {

/// Pitch radius as the root of asin((t+d)/2R) + asin((t−d)/2R) = π/z (Brent–TOMS 748).
double pitch_radius(const PocketWheel& wheel);

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

struct NumericPhase {
  double begin = 0.0;   ///< [rad]
  double end = 0.0;     ///< [rad]
  Vec2 crank_begin;     ///< [m] crank joint position at φ = begin
  double link = 0.0;    ///< [m] link that seats at the phase's end
  double span = 0.0;    ///< [m] slider: bar length from crank to guided point
  double offset = 0.0;  ///< [m] x offset (see evaluate)
};

struct NumericPlan {
  double radius = 0.0;  ///< [m]
  double period = 0.0;  ///< [rad] 2π/z
  Guide guide;
  double height = 0.0;  ///< [m] H
  std::vector<NumericPhase> phases;
  std::vector<double> seating_angles;  ///< [rad] in [0, 2π/z)
};

/// Finds the phases and seating events numerically. Throws InputError on invalid input or when
/// no consistent period exists.
NumericPlan plan(const PocketWheel& wheel, const Guide& guide);

/// Position x (and y for free run-on) at φ in phase `index`, solved from the constraints.
Vec2 position(const NumericPlan& plan, std::size_t index, double phi);

/// Kinematics by differentiating position() numerically with step `step` [rad].
PointKinematics evaluate_phase(const NumericPlan& plan, std::size_t index, double phi,
                               double step = 1e-3);
PointKinematics evaluate(const NumericPlan& plan, double phi, double step = 1e-3);

/// The numerical analysis with the same outputs as run_on(): the series and the seating angles
/// come from the numerical solver; the reported plan (phases, first_link) and the extremes are
/// the closed forms' (the tests hold the two plans equal to 1e-10 rad).
RunOnResult run_on(const PocketWheel& wheel, const Guide& guide, const Sampling& sampling);

}  // namespace catena::pocketwheel::numeric
