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
// compared within 1 % (measured: docs/models/dynamics.md, validation (6b)). With the load's
// inertia (Guide::load_inertia), run fast: the catch at the rail's entry against q_L v² and the
// catch's and discharge's powers against ½ q_L v³.
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
constexpr double kLoopTol = 0.04;     // the catch's rise of the tight side and the drive's power

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

// The load's inertia, loading and discharge (Guide::load_inertia; docs/models/dynamics.md, "A
// conveyed load: its inertia, loading and discharge") on the loaded conveyor (q_L = 3 q), run fast
// — ω = 30 rad/s, the chain's mean speed v = z p ω/2π = 1.455 m/s — so that the catch's force
// q_L v² (7.9 N) stands well above the window means' scatter. Against the same run with the load
// as weight only: the tension step across the loading point (the upper run from before the
// guide's entry to three quarters along the guide, in its travel a quarter along) and the tight
// side over the slack side both rise by q_L v² (the material arriving at rest is brought to the
// chain's speed there; leaving, it takes its momentum along without a force), the drive's power by
// q_L v³, and the work balance's catch and discharge each take ½ q_L v³. The step, the catch and
// the discharge are held within 2 %, the tight side's and the drive's rise within 4 % (below), and
// the drive's rise against what the work balance books to the load's inertia and to the loop's
// losses within 2 %.
TEST(DynamicsConveyorLoad, LoadInertiaCatchesTheLoadAtTheRailsEntry) {
  Conveyor d;
  d.load_per_metre = 3.0 * d.mass_per_metre;
  d.omega = 30.0;
  const double duration = 1.2;
  const testing::ConveyorMeans off = testing::conveyor_means(d, duration);
  d.load_inertia = true;
  const testing::ConveyorMeans on = testing::conveyor_means(d, duration);
  const double v = d.teeth * d.pitch * d.omega / (2 * kPi), q = d.load_per_metre;
  const double force = q * v * v, power = q * v * v * v;
  const double step_off = off.along[2] - off.upper_entry, step_on = on.along[2] - on.upper_entry;
  const double rise_off = off.tight - off.slack, rise_on = on.tight - on.slack;
  std::printf("v %.4f m/s, q_L v^2 %.4f N, q_L v^3 %.4f W\n", v, force, power);
  std::printf(
      "entry step %.4f N -> %.4f N (%+.3f %% of q_L v^2); tight - slack %.4f -> %.4f N "
      "(%+.3f %%)\n",
      step_off, step_on, 100 * ((step_on - step_off) / force - 1), rise_off, rise_on,
      100 * ((rise_on - rise_off) / force - 1));
  std::printf(
      "drive power %.4f -> %.4f W (%+.3f %% of q_L v^3); catch %.4f W (%+.3f %% of half), "
      "discharge %.4f W (%+.3f %%); weight only: catch %.3g W discharge %.3g W\n",
      off.drive_power, on.drive_power, 100 * ((on.drive_power - off.drive_power) / power - 1),
      on.catch_power, 100 * (on.catch_power / (0.5 * power) - 1), on.discharge_power,
      100 * (on.discharge_power / (0.5 * power) - 1), off.catch_power, off.discharge_power);
  std::printf("friction power %.4f -> %.4f W\n", off.friction_power, on.friction_power);
  // The work balance of each run over the window (ConveyorMeans::Balance): the drive's rise
  // against the catch and discharge plus the change of the losses — the rails' friction, the
  // links' and the contacts' dampers and the θ-method's rest. What is left is the change of the
  // loop's stored energy over the window and of the loads' work (the numerical rest being the
  // balance's remainder, adding those two would close it identically): measured −1.45 %, the
  // stored energy falling by 0.128 W with the load's inertia (+0.032 W as weight only).
  const testing::ConveyorMeans::Balance &b0 = off.balance, &b1 = on.balance;
  const double drive_rise = b1.drive - b0.drive;
  const double catches = b1.load_catch + b1.discharge - (b0.load_catch + b0.discharge);
  const double losses = (b1.friction - b0.friction) + (b1.damper - b0.damper) +
                        (b1.contact_damping - b0.contact_damping) + (b1.numerical - b0.numerical);
  std::printf(
      "balance (W, off -> on): drive %.4f -> %.4f, catch + discharge %.4f -> %.4f, friction "
      "%.4f -> %.4f, link dampers %.4f -> %.4f, contact dampers %.4f -> %.4f, numerical %.4f -> "
      "%.4f, others %.4f -> %.4f, loads %.4f -> %.4f, energy rate %.4f -> %.4f\n",
      b0.drive, b1.drive, b0.load_catch + b0.discharge, b1.load_catch + b1.discharge, b0.friction,
      b1.friction, b0.damper, b1.damper, b0.contact_damping, b1.contact_damping, b0.numerical,
      b1.numerical, b0.other, b1.other, b0.load, b1.load, b0.energy_rate, b1.energy_rate);
  std::printf(
      "drive rise %.4f W against catch + discharge %.4f W + the losses' change %+.4f W "
      "(%+.4f %%)\n",
      drive_rise, catches, losses, 100 * (drive_rise / (catches + losses) - 1));
  EXPECT_NEAR(drive_rise / (catches + losses), 1.0, kCarriedTol);
  EXPECT_NEAR((step_on - step_off) / force, 1.0, kCarriedTol);
  EXPECT_NEAR(on.catch_power / (0.5 * power), 1.0, kCarriedTol);
  EXPECT_NEAR(on.discharge_power / (0.5 * power), 1.0, kCarriedTol);
  // The tight side and the drive's power see the rest of the loop as well (the balance above:
  // the drive's rise 0.357 W short of the catch's and discharge's 11.611 W — the loop's stored
  // energy 0.160 W, the rails' friction 0.069 W, the θ-method's rest 0.068 W, the contacts'
  // dampers 0.046 W, the links' 0.008 W; q_L = 3 q at 15 and 45 rad/s and q_L = 10 q at 30 rad/s
  // gave the drive's rise −0.43, −1.37 and +1.82 % off q_L v³), so these two are held to 4 %
  // (measured −2.50 and −2.67 %).
  EXPECT_NEAR((rise_on - rise_off) / force, 1.0, kLoopTol);
  EXPECT_NEAR((on.drive_power - off.drive_power) / power, 1.0, kLoopTol);
}

}  // namespace
}  // namespace catena::dynamics
