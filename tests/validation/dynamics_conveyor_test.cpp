// A conveyor loop under gravity with guide friction against the static contour method of
// `catena loop` (issue 21 validation (6b); docs/models/dynamics.md, docs/models/loop.md).
//
// Two equal 12B sprockets, z = 16, 60 pitches apart on a horizontal line; the driver (x = 0) turns
// counter-clockwise at constant speed (0.24 m/s) and pulls the upper run, the tail wheel is an
// idler (inertia, no load). Both runs slide on level straight guides with Coulomb friction μ under
// gravity, from 3 pitches after one wheel to 3 pitches before the other, each with a rounded
// lead-in at its entry end. In steady running the mean tension grows along each guided run by
// μ q0 per metre (q0 the chain's weight per metre) and by q0 H round the idler, where the chain
// climbs H from the lower run to the upper: `catena loop` (strength::solve) with a take-up at the
// drive's slack side set to the slack tension the simulation finds, then the two runs with w = μ,
// the lift and a turn of factor 1, and the drive, gives the tight-side tension and the tension
// along the upper guide. The simulation is compared with it, over whole tooth periods of steady
// running, within 1 % (measured: +0.44 % at the tight side, +0.63 to +0.75 % along the guide).
// That bias is the loop's losses besides the guides' friction (the rollers' impacts on the seats
// and the rails), which the loop model leaves out: the rise tight − slack is checked against the
// energy balance that includes them (below; docs/models/dynamics.md, "The conveyor's bias").
//
// The speed is low on purpose: the wheels' polygon action dissipates energy (seat impacts and
// the dampers), which shows as a further tension rise round each wheel growing as v². In a
// frictionless run of this loop at 0.49 m/s it added 0.15 N per wheel (12 % of the lift; the loop
// model would lump it into the turn factor k), at 0.24 m/s under 0.04 N.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "../dynamics/period_mean.hpp"
#include "catena/strength/loop.hpp"
#include "conveyor_loop_model.hpp"
#include "conveyor_run.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTensionTol = 0.01;  // issue 21 (6b): 1 %
constexpr double kCarriedTol = 0.02;  // the rise and the friction power (below)
constexpr double kEnergyTol = 0.002;  // the rise against the energy balance (below)

// The loop, its wheels and guides (tests/dynamics/two_wheel_loops.hpp): validation (6b)'s
// defaults, one rail a run.
using testing::Conveyor;
using testing::conveyor_probes;
using testing::ConveyorProbe;
using testing::ConveyorRun;

// The end of the whole tooth periods in (t0, t1].
double window_end(const Conveyor& d, double t0, double t1) {
  const double period = 2 * kPi / (d.teeth * d.omega);
  return t0 + std::floor((t1 - t0) / period + 1e-9) * period;
}

// The run (tests/validation/conveyor_run.hpp): the conveyor stepped, its tensions sampled at
// validation (6b)'s probes in the conveyor's frame (level here: along x, above or below y = 0).
// `lift` raises the start by that much [m] (picometres: the same run perturbed at the Newton
// tolerance's level, for the window means' scatter below). The loop's energy is taken at the ends
// of the window of whole tooth periods in (t0, duration].
ConveyorRun run(const Conveyor& d, double duration, double step, double t0, double lift = 0.0) {
  return testing::run_conveyor(d, conveyor_probes(d), duration, step, lift,
                               {t0, window_end(d, t0, duration)});
}

// The simulation over the loop model in a window (t0, t1] of a run (whole tooth periods).
struct Comparison {
  std::vector<double> mean;   // the probes' window means [N]
  std::vector<double> ratio;  // simulation / loop model, the probes 1..5 (0: the slack, input)
  double rise = 0.0;          // (tight − slack) over the loop model's
  double friction = 0.0;      // the steps' friction power over (2 μ q0 L) v
  // The energy balance of the chain from the slack probe round the tail to the tight probe: the
  // speed-weighted rise over the simulated friction force, the lift and the loop's other losses
  // (`losses`), each power over the chain's mean speed (docs/models/dynamics.md, "The conveyor's
  // bias").
  double energy_rise = 0.0;
  double losses = 0.0;     // [N] the loop's losses besides the guides' friction over the mean speed
  double loop_rise = 0.0;  // [N] the loop model's tight − slack
};

Comparison compare(const Conveyor& d, const ConveyorRun& r, double t0, double t1) {
  const double p = d.pitch;
  const double x_hi = (d.span_links - d.guide_gap) * p;
  const double guide = x_hi - d.guide_gap * p;
  // the window's whole tooth periods in (t0, t1]
  const double t_end = window_end(d, t0, t1);
  Comparison c;
  for (const ConveyorProbe& pr : r.probes)
    c.mean.push_back(mean_between(r.time, pr.tension, t0, t_end));
  const std::vector<double>& mean = c.mean;

  // catena loop: take-up at the drive's slack side (the simulated slack tension), the lower
  // run, the lift round the tail idler, the idler, the upper run, the drive. A run's friction acts
  // on the weight its guide carries: the guide's own length and half of each unsupported stretch
  // between its ends and the wheels (each stretch hangs between a wheel and the guide's end, which
  // carries half its weight). Round the idler the chain climbs from the lower run's level to the
  // upper's, H = 2 R sin(π/z)/(π/z): in the contour method a vertical run of height H, q0 H.
  const double q0 = d.mass_per_metre * d.gravity;
  const double radius = testing::wheel_radius(d), level = testing::run_level(d);
  const double carried = guide + d.guide_gap * p;  // 2 × half a stretch of guide_gap pitches
  strength::Loop loop;
  loop.speed = d.omega * radius;
  // a straight run of the chain's weight (tests/validation/conveyor_loop_model.hpp)
  auto straight = [&](const char* name, double length, double incline, double w) {
    return testing::loop_straight(name, length, incline, q0, w);
  };
  loop.segments = {testing::loop_takeup(mean[0]),
                   straight("lower run", carried, 0.0, d.friction),
                   straight("lift round the idler", 2 * level, kPi / 2, 0.0),
                   testing::loop_idler(),
                   straight("upper run", carried, 0.0, d.friction),
                   testing::loop_drive()};
  const strength::LoopResult lr = strength::solve(loop);
  const double upper_in = lr.segments[4].tension_in;
  // along the upper run (travel −x from x_hi + half a stretch), the loop model's tension is linear
  // in the path
  auto loop_tension_at = [&](double x) {
    const double along = x_hi + 0.5 * d.guide_gap * p - x;
    return upper_in + along / carried * (lr.tight_tension - upper_in);
  };
  c.ratio = {0.0, mean[1] / lr.tight_tension};
  for (std::size_t k = 2; k < 5; ++k) c.ratio.push_back(mean[k] / loop_tension_at(r.probes[k].x));
  c.ratio.push_back(mean[5] / upper_in);
  c.loop_rise = lr.tight_tension - lr.slack_tension;
  c.rise = (mean[1] - mean[0]) / c.loop_rise;
  // the steps' friction work over the same whole periods
  double w0 = 0.0, w1 = 0.0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    if (r.time[k] <= t0) w0 = r.friction_work[k];
    if (r.time[k] <= t_end) w1 = r.friction_work[k];
  }
  const double friction_force = 2.0 * d.friction * q0 * carried;
  c.friction = -(w1 - w0) / ((t_end - t0) * loop.speed) / friction_force;

  // The energy balance. What the driver puts in over the window and the loop does not store
  // (drive − ΔE) is lost: in the guides' friction (the steps' friction work) and elsewhere (the
  // seats' and rails' impacts through the contacts' and links' dampers and the steps' numerical
  // damping). The chain between the slack probe and the tight one, round the tail, carries the
  // power T v across each probe; over whole tooth periods its flux in plus what the lift and the
  // losses take balance, so mean(T v) at the tight probe − at the slack probe = (friction + other
  // losses) + q0 H v̄: the rise of the speed-weighted means mean(T v)/v̄ is the friction force,
  // the lift and the other losses over v̄ (v̄ the chain's mean speed). The loop model has the
  // friction and the lift only.
  // The driver's work, the friction work and the loop's energy all at one sample at each end: the
  // one nearest t0 and t_end, where run_conveyor took the energy (the friction power above takes
  // the last sample at or before each end, which may be the step before).
  EXPECT_EQ(r.energy.size(), 2u);
  const double e0 = r.energy.at(0), e1 = r.energy.at(1);  // at t0 and t_end (run)
  const std::size_t k0 = r.energy_sample.at(0), k1 = r.energy_sample.at(1);
  const double h = r.time.at(1) - r.time.at(0);
  EXPECT_NEAR(r.time.at(k0), t0, 0.5 * h) << "the balance's first sample";
  EXPECT_NEAR(r.time.at(k1), t_end, 0.5 * h) << "the balance's last sample";
  const double d0 = r.drive_work.at(k0), d1 = r.drive_work.at(k1);
  auto weighted = [&](const ConveyorProbe& pr) {  // mean(T v) / mean(v) over the window
    std::vector<double> flux(pr.tension.size());
    for (std::size_t k = 0; k < flux.size(); ++k) flux[k] = pr.tension[k] * pr.speed[k];
    return mean_between(r.time, flux, t0, t_end) / mean_between(r.time, pr.speed, t0, t_end);
  };
  const double v_mean = mean_between(r.time, r.probes[0].speed, t0, t_end);
  const double dt = r.time[k1] - r.time[k0];
  const double friction_power = -(r.friction_work.at(k1) - r.friction_work.at(k0)) / dt;
  const double other = (d1 - d0 - (e1 - e0)) / dt - friction_power;
  c.losses = other / v_mean;
  c.energy_rise = (weighted(r.probes[1]) - weighted(r.probes[0])) /
                  (friction_power / v_mean + q0 * 2 * level + c.losses);
  return c;
}

// Validation (6b). The window (0.4 s, 3.2 s]: the trajectory is sensitive to picometre changes
// (the rollers' rattle on the rails and the seats), so a window's mean scatters about the steady
// mean. Measured over picometre lifts of the start (a probe out of the suite, checked by
// WindowMeansHoldUnderPicometreLifts below; docs/models/dynamics.md, validation (6b)) at the probe
// three quarters along the upper guide: the old (0.4 s, 0.8 s] scattered by ±0.25 % (σ; 4 of 20
// lifted runs had a probe beyond 1 %), (0.4 s, 3.2 s] by ±0.04 % (σ; the largest deviation over 10
// runs 0.07 %), with the predictor and the error-estimate stop on as without them.
TEST(DynamicsConveyor, GuideFrictionTensionsMatchTheLoopModel) {
  const Conveyor d;
  const double duration = 3.2, step = 1e-4, t0 = 0.4;
  const ConveyorRun r = run(d, duration, step, t0);
  ASSERT_EQ(r.time.size(), static_cast<std::size_t>(std::lround(duration / step)));
  const Comparison c = compare(d, r, t0, duration);

  EXPECT_NEAR(c.ratio[1], 1.0, kTensionTol) << "tight " << c.mean[1] << " slack " << c.mean[0];
  for (std::size_t k = 2; k < 5; ++k)
    EXPECT_NEAR(c.ratio[k], 1.0, kTensionTol) << "x " << r.probes[k].x << ": " << c.mean[k];
  EXPECT_NEAR(c.ratio[5], 1.0, kTensionTol) << "guide's entry " << c.mean[5];
  // The rise alone (tight − slack = 2 μ q0 L + q0 H), within 2 %: it also carries the wheels'
  // polygon losses, which the loop model's factor-1 turn leaves out (measured: +0.61 %).
  EXPECT_NEAR(c.rise, 1.0, kCarriedTol) << "rise " << c.mean[1] - c.mean[0];
  // The friction work the steps report, over the same whole periods: the guides' friction force
  // is the loop model's friction resistance 2 μ q0 L (the rise without the lift), times v. Within
  // 2 %, not 1: "half of each unsupported stretch" is the weight a level guide's end carries when
  // the wheel's end of the stretch is at the same height; here the wheel's end swings with the
  // polygon and the guide's end is a rounded nose (measured: −0.94 %, of which −0.64 % is the
  // chain's mean speed z p ω/2π = ωR sin(π/z)/(π/z) against the loop model's ωR: the friction
  // force itself is about 0.3 % short of 2 μ q0 L: −0.027 N, −0.34 %, over the balance's window).
  EXPECT_NEAR(c.friction, 1.0, kCarriedTol) << "friction power over the loop model's";
  // The tensions' bias over the loop model, traced: the rise of the speed-weighted means is the
  // energy balance's — the simulated friction force, the lift q0 H and the loop's other losses,
  // each over the chain's mean speed — within 0.2 % (measured +0.04 %). The other losses (0.071 N,
  // 0.77 % of the rise) are what the loop model leaves out; with them the excess of the rise over
  // the loop model (+0.61 %) is accounted for, less the friction force 0.3 % short of 2 μ q0 L.
  // The balance would miss by more than twice its tolerance without them:
  std::printf("energy balance %+.4f %%, other losses %.4f N\n", 100 * (c.energy_rise - 1.0),
              c.losses);
  EXPECT_NEAR(c.energy_rise, 1.0, kEnergyTol) << "losses " << c.losses << " N";
  EXPECT_GT(c.losses, 2 * kEnergyTol * c.loop_rise) << "losses " << c.losses << " N";
}

// The window's scatter, checked: the start lifted by 1 pm and by 2 pm (a change of the size of the
// Newton tolerance's; the trajectory is sensitive to it) gives each probe's ratio within the 1 %
// in both runs and the two runs' ratios within 0.2 % of each other (about 3.5 standard deviations
// of the difference at the measured ±0.04 %). The table of docs/models/dynamics.md ("The
// predictor and the estimate with guides") was measured over 10-20 such lifts with a probe kept
// out of the suite.
TEST(DynamicsConveyor, WindowMeansHoldUnderPicometreLifts) {
  const Conveyor d;
  const double duration = 3.2, step = 1e-4, t0 = 0.4;
  std::vector<Comparison> c;
  for (double lift : {1e-12, 2e-12})
    c.push_back(compare(d, run(d, duration, step, t0, lift), t0, duration));
  for (std::size_t k = 1; k < 6; ++k) {
    std::printf("probe %zu: %.5f %.5f\n", k, c[0].ratio[k], c[1].ratio[k]);
    EXPECT_NEAR(c[0].ratio[k], 1.0, kTensionTol) << k;
    EXPECT_NEAR(c[1].ratio[k], 1.0, kTensionTol) << k;
    EXPECT_NEAR(c[0].ratio[k], c[1].ratio[k], 2e-3) << k;
  }
}

}  // namespace
}  // namespace catena::dynamics
