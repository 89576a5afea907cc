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
// catch's and discharge's powers against ½ q_L v³; and with the material arriving at a speed u of
// its own (Guide::load_speed) the step against q_L v (v − u) and the catch's loss against
// ½ q_L v (v − u)².
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
constexpr double kCarriedTol = 0.02;  // the rise and the powers, as unloaded; the load's inertia

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
// q_L v³, and the work balance's catch and discharge each take ½ q_L v³. All held within 2 %, and
// the drive's rise against what the work balance books to the load's inertia and to the loop's
// losses within 2 %. The window is (0.6 s, 2.0 s]: the loop's stored energy swings slowly (its
// rate over the window −0.13 W at (0.4 s, 1.2 s], +0.04 W at (0.8 s, 1.6 s], −0.15 W at
// (1.2 s, 2.0 s] with the inertia), and 0.8 s windows left the tight side's and the drive's rise
// −2.5 % to +0.3 % off; windows of 1.2 s to 2.4 s, from 0.4 s, 0.6 s or 0.8 s, held both within
// −1.05 % to +0.31 % (docs/models/dynamics.md, validation (6b) with the load's inertia).
TEST(DynamicsConveyorLoad, LoadInertiaCatchesTheLoadAtTheRailsEntry) {
  Conveyor d;
  d.load_per_metre = 3.0 * d.mass_per_metre;
  d.omega = 30.0;
  const double duration = 2.0, t0 = 0.6;
  const testing::ConveyorMeans off = testing::conveyor_means(d, duration, t0);
  d.load_inertia = true;
  const testing::ConveyorMeans on = testing::conveyor_means(d, duration, t0);
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
  // balance's remainder, adding those two would close it identically): measured +0.69 %.
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
  // The tight side and the drive's power see the rest of the loop as well, its stored energy's
  // slow swing the largest share (above): over the 1.4 s window they are held to 2 % (they were
  // held to 4 % over (0.4 s, 1.2 s], where they were −2.50 and −2.67 % off).
  EXPECT_NEAR((rise_on - rise_off) / force, 1.0, kCarriedTol);
  EXPECT_NEAR((on.drive_power - off.drive_power) / power, 1.0, kCarriedTol);
}

// Material arriving with a speed of its own (Guide::load_speed; docs/models/dynamics.md, "A
// conveyed load: its inertia, loading and discharge") on the fast loaded conveyor above: u along
// the chain's travel (the upper run travels −x, the rail's direction +x: load_speed = −u). The
// catch's reaction Δm_L (u − v) gives a tension step q_L v (v − u) across the loading point, the
// catch's loss is ½ q_L v (v − u)² (the material's relative kinetic energy, lost in the inelastic
// catch) and the material brings ½ q_L v u² of kinetic energy (the input part of the catch's
// work): at u = v no step and no loss, at u = v/2 half the step and a quarter of the loss of the
// material arriving at rest. The discharge is ½ q_L v³ as before. Against the weight-only run; the
// step within 2 % of q_L v² (the scale of the catch's force: at u = v the expected step is 0), the
// loss within 2 % of ½ q_L v³, the arrival's input within 2 % of ½ q_L v u². The run is 1.2 s with
// means after 0.4 s, the window LoadInertiaCatchesTheLoadAtTheRailsEntry (above) found unsettled
// for the loop's global quantities (the tight side's and the drive's rise −2.5 % off there, from
// the stored energy's slow swing); it is kept here (a longer run costs CPU) because it asserts
// only local quantities at the loading and discharge points — the step, the loss, the arrival,
// the discharge — which came within 1 % in it (at most +0.84 %; docs/models/dynamics.md).
TEST(DynamicsConveyorLoad, LoadArrivingWithASpeedOfItsOwn) {
  Conveyor d;
  d.load_per_metre = 3.0 * d.mass_per_metre;
  d.omega = 30.0;
  const double duration = 1.2;
  const testing::ConveyorMeans off = testing::conveyor_means(d, duration);
  const double v = d.teeth * d.pitch * d.omega / (2 * kPi), q = d.load_per_metre;
  const double force = q * v * v, power = q * v * v * v;
  const double step_off = off.along[2] - off.upper_entry;
  d.load_inertia = true;
  for (const double u : {v, 0.5 * v}) {
    d.load_speed = -u;
    const testing::ConveyorMeans on = testing::conveyor_means(d, duration);
    const double step = on.along[2] - on.upper_entry - step_off,
                 loss = on.catch_power + on.arrival_power;
    const double step_expected = q * v * (v - u), loss_expected = 0.5 * q * v * (v - u) * (v - u);
    const double arrival_expected = 0.5 * q * v * u * u;
    std::printf(
        "u = %.4f m/s: step %.4f N (q_L v (v - u) %.4f N, %+.3f %% of q_L v^2); catch's loss %.4f "
        "W "
        "(1/2 q_L v (v - u)^2 %.4f W, %+.3f %% of 1/2 q_L v^3); arrival %.4f W (1/2 q_L v u^2 "
        "%.4f W, %+.3f %%); discharge %.4f W (%+.3f %% of 1/2 q_L v^3)\n",
        u, step, step_expected, 100 * (step - step_expected) / force, loss, loss_expected,
        100 * (loss - loss_expected) / (0.5 * power), on.arrival_power, arrival_expected,
        100 * (on.arrival_power / arrival_expected - 1), on.discharge_power,
        100 * (on.discharge_power / (0.5 * power) - 1));
    EXPECT_NEAR(step, step_expected, kCarriedTol * force) << "u " << u;
    EXPECT_NEAR(loss, loss_expected, kCarriedTol * 0.5 * power) << "u " << u;
    EXPECT_NEAR(on.arrival_power, arrival_expected, kCarriedTol * arrival_expected) << "u " << u;
    EXPECT_NEAR(on.discharge_power / (0.5 * power), 1.0, kCarriedTol) << "u " << u;
  }
}

}  // namespace
}  // namespace catena::dynamics
