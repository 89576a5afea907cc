// The conveyor of validation (6b) carrying a load on its upper run, against the contour method of
// `catena loop` with `load_weight` on that run (issue 21 validation (6b); docs/models/dynamics.md,
// "A conveyed load"; docs/models/loop.md).
//
// The loop is the level test's (tests/validation/dynamics_conveyor_test.cpp: two 12B wheels,
// z = 16, 60 pitches apart, the driver at 0.24 m/s, a free tail idler, rails with μ = 0.3 and
// lead-ins 3 pitches from the wheels), its upper rail carrying conveyed material of q_L per metre
// (Guide::load_per_metre): each node over the rail bears q_L p g, ramped over a pitch at the
// rail's ends. The load's weight presses the chain onto the rail — the rail's friction grows by
// μ q_L g cos β per metre of rail — and on an incline its part along the rail pulls on the chain,
// q_L g sin β per metre. The loop model (testing::conveyor_loop_model) is the inclined test's
// with the upper run's carried length cut into half a stretch, the guide and half a stretch, the
// guide's segment with `load_weight` q_L g: along the guide the tension rises by
// (q0 + q_L g)(μ cos β + sin β) per metre, and the tight side by q_L g L (μ cos β + sin β) more
// than unloaded. The tight side, the guide's entry and three points along the loaded guide are
// compared within 1 % (measured: docs/models/dynamics.md, validation (6b)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "conveyor_loop_model.hpp"
#include "conveyor_run.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTensionTol = 0.01;  // issue 21 (6b): 1 %
constexpr double kCarriedTol = 0.02;  // the rise and the powers, as unloaded

using testing::Conveyor;

void compare(const Conveyor& d) {
  testing::ConveyorAgainstLoop run;
  ASSERT_NO_FATAL_FAILURE(testing::run_against_loop_model(d, run));
  const testing::ConveyorMeans& m = run.m;
  const testing::ConveyorLoopModel& lm = run.lm;
  const strength::LoopResult& lr = lm.result;
  const double q0 = d.mass_per_metre * d.gravity, load = d.load_per_metre * d.gravity;
  const double beta = d.incline, guide = lm.carried - 2 * lm.half_stretch;
  // the loop model's own closed form along the loaded guide
  EXPECT_NEAR(lm.guide_gradient, (q0 + load) * (d.friction * std::cos(beta) + std::sin(beta)),
              1e-9);

  testing::expect_tensions_match(m, lm, kTensionTol);
  const double rise = lr.tight_tension - lr.slack_tension;
  EXPECT_NEAR((m.tight - m.slack) / rise, 1.0, kCarriedTol)
      << "rise " << m.tight - m.slack << " loop " << rise;
  // The guides' friction: both runs' chain weight on their carried lengths and the load on the
  // upper guide, times μ cos β, times v, within 2 % as unloaded.
  const double friction_force =
      d.friction * std::cos(beta) * (2.0 * q0 * lm.carried + load * guide);
  EXPECT_NEAR(m.friction_power / (lm.speed * friction_force), 1.0, kCarriedTol)
      << "friction power " << m.friction_power << " W, loop " << lm.speed * friction_force;
  // The load's work on the chain: it rides up (β > 0) the upper rail at the chain's speed,
  // −q_L g L sin β v; level, nothing (the weight is across the travel): there the check is
  // scaled by the power the rails' friction takes, the load's power within 1e-3 of it.
  const double lift_power = -load * guide * std::sin(beta) * lm.speed;
  EXPECT_NEAR(m.load_power, lift_power,
              kCarriedTol * std::abs(lift_power) + 1e-3 * std::abs(m.friction_power))
      << "load power " << m.load_power << " W, friction power " << m.friction_power << " W";
  std::printf("q_L %.3f kg/m beta %.0f deg: ", d.load_per_metre, beta * 180 / kPi);
  testing::print_tensions(m, lm);
  std::printf(" %% rise %+.3f %% friction power %+.3f %% load power %.4g W (loop %.4g W)\n",
              100 * ((m.tight - m.slack) / rise - 1),
              100 * (m.friction_power / (lm.speed * friction_force) - 1), m.load_power, lift_power);
}

// q_L = q, the chain's own mass per metre: the upper rail's friction doubled.
TEST(DynamicsConveyorLoad, LoadEqualToTheChainsMatchesTheLoopModel) {
  Conveyor d;
  d.load_per_metre = d.mass_per_metre;
  compare(d);
}

// q_L = 3 q: the tight side ~ 1.6 × the unloaded one.
TEST(DynamicsConveyorLoad, LoadThreeTimesTheChainsMatchesTheLoopModel) {
  Conveyor d;
  d.load_per_metre = 3.0 * d.mass_per_metre;
  compare(d);
}

// Inclined +15° (the runs rising towards the driver): the load's weight along the rail pulls
// against the carrying run as well.
TEST(DynamicsConveyorLoad, RisingLoadedRunMatchesTheLoopModel) {
  Conveyor d;
  d.load_per_metre = d.mass_per_metre;
  d.incline = 15.0 * kPi / 180.0;
  compare(d);
}

}  // namespace
}  // namespace catena::dynamics
