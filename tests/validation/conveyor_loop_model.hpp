// Test helper: the pieces of validation (6b)'s loop model — the contour method of `catena loop`
// (strength::solve) the level and the inclined conveyor are compared with
// (tests/validation/dynamics_conveyor_*_test.cpp): a straight run of the chain's weight, the
// take-up at the drive's slack side, the tail idler and the drive.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>

#include "../dynamics/two_wheel_loops.hpp"
#include "catena/strength/loop.hpp"
#include "conveyor_run.hpp"

namespace catena::dynamics::testing {

// A straight run `length` [m] long at `incline` [rad] (its travel's rise), of chain weight
// `chain_weight` [N/m] and resistance factor `resistance` (μ on a guide, 0 unsupported).
// `load_weight` [N/m]: the conveyed load's weight on it (0: none).
inline strength::Segment loop_straight(const char* name, double length, double incline,
                                       double chain_weight, double resistance,
                                       double load_weight = 0.0) {
  strength::Segment g;
  g.load_weight = load_weight;
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

// The wheels' pitch radius R, and the runs' mean height off the line of centres on a wheel of z
// teeth, R sin(π/z)/(π/z) (the chain climbs twice that round the tail).
inline double wheel_radius(const Conveyor& d) {
  return 0.5 * d.pitch / std::sin(std::numbers::pi / d.teeth);
}
inline double run_level(const Conveyor& d) {
  const double half_angle = std::numbers::pi / d.teeth;
  return wheel_radius(d) * std::sin(half_angle) / half_angle;
}

// `catena loop` for validation (6b)'s conveyor `d`, level or inclined at β = d.incline, its
// take-up at `slack` (the simulated slack tension), from the drive's slack side:
//   the lower run, travelling down (β > 0) from the drive: its carried length (the guide and half
//     of each unsupported stretch to the wheels; w = μ, incline −β) and the 1.5 pitches on to the
//     tail's tangent point (w = 0, incline −β);
//   the lift round the tail from the lower run to the upper, whose tangent points are 2 h apart
//     across the line of centres (h the runs' level): 2 h cos β upward, q0 2 h cos β;
//   the tail idler (a turn of factor 1);
//   the upper run, travelling up: 1.5 pitches (w = 0, incline β), then its carried length
//     (w = μ, incline β) to the tight side — half a stretch, the guide and half a stretch, the
//     guide carrying the conveyed load q_L g (d.load_per_metre; 0: none) besides the chain;
//   the drive.
struct ConveyorLoopModel {
  strength::LoopResult result;
  double speed = 0.0;        // [m/s] the pitch line's
  double upper_entry = 0.0;  // [N] where the upper run's carried length begins
  double carried = 0.0;      // [m] a run's carried length
  double x_start = 0.0;   // [m] where (along the line of centres) the upper carried length begins
  double guide_in = 0.0;  // [N] where the upper guide begins (in the travel)
  double guide_gradient = 0.0;  // [N/m] the tension's rise along the upper guide
  double half_stretch = 0.0;    // [m] half an unsupported stretch, guide_gap/2 pitches
  // [N] the loop model's tension on the upper run at x (along the line of centres) on its guide
  double upper_at(double x) const {
    return guide_in + (x_start - half_stretch - x) * guide_gradient;
  }
};

inline ConveyorLoopModel conveyor_loop_model(const Conveyor& d, double slack) {
  constexpr double kPi = std::numbers::pi;
  const double p = d.pitch, beta = d.incline;
  const double q0 = d.mass_per_metre * d.gravity, load = d.load_per_metre * d.gravity;
  const double radius = wheel_radius(d), level = run_level(d);
  ConveyorLoopModel out;
  out.carried = (d.span_links - d.guide_gap) * p;  // the guide and 2 × half a stretch
  out.half_stretch = 0.5 * d.guide_gap * p;
  out.x_start = (d.span_links - 0.5 * d.guide_gap) * p;
  const double guide = out.carried - 2 * out.half_stretch;
  const double stretch = d.span_links * p - out.x_start;  // to the tail's tangent point
  strength::Loop loop;
  loop.speed = d.omega * radius;
  out.speed = loop.speed;
  auto straight = [&](const char* name, double length, double incline, double w,
                      double load_weight = 0.0) {
    return loop_straight(name, length, incline, q0, w, load_weight);
  };
  loop.segments = {loop_takeup(slack),
                   straight("lower run, guided", out.carried, -beta, d.friction),
                   straight("lower run to the tail", stretch, -beta, 0.0),
                   straight("lift round the tail", 2 * level * std::cos(beta), kPi / 2, 0.0),
                   loop_idler(),
                   straight("upper run from the tail", stretch, beta, 0.0),
                   straight("upper run onto its guide", out.half_stretch, beta, d.friction),
                   straight("upper guide", guide, beta, d.friction, load),
                   straight("upper run off its guide", out.half_stretch, beta, d.friction),
                   loop_drive()};
  out.result = strength::solve(loop);
  out.upper_entry = out.result.segments[6].tension_in;
  out.guide_in = out.result.segments[7].tension_in;
  out.guide_gradient = (out.result.segments[8].tension_in - out.guide_in) / guide;
  return out;
}

// The simulation's window means `m` against the loop model `lm`, each within `tol` of it: the
// tight side, the three points along the upper guide and the guide's entry (validation 6b's
// tensions, level, inclined and loaded).
inline void expect_tensions_match(const ConveyorMeans& m, const ConveyorLoopModel& lm, double tol) {
  const strength::LoopResult& lr = lm.result;
  EXPECT_NEAR(m.tight / lr.tight_tension, 1.0, tol)
      << "tight " << m.tight << " loop " << lr.tight_tension << " slack " << m.slack;
  for (std::size_t k = 0; k < 3; ++k) {
    const double loop_t = lm.upper_at(m.along_x[k]);
    EXPECT_NEAR(m.along[k] / loop_t, 1.0, tol)
        << "x " << m.along_x[k] << ": " << m.along[k] << " loop " << loop_t;
  }
  EXPECT_NEAR(m.upper_entry / lm.upper_entry, 1.0, tol)
      << m.upper_entry << " loop " << lm.upper_entry;
}

// A conveyor's steady means (conveyor_means) and the loop model taken at their slack tension:
// the inclined and the loaded conveyor's comparisons start so. The slack side must be in tension
// (fatal: ASSERT_NO_FATAL_FAILURE at the call).
struct ConveyorAgainstLoop {
  ConveyorMeans m;
  ConveyorLoopModel lm;
};
inline void run_against_loop_model(const Conveyor& d, ConveyorAgainstLoop& out) {
  out.m = conveyor_means(d);
  ASSERT_GT(out.m.slack, 0.0);
  out.lm = conveyor_loop_model(d, out.m.slack);
}

// The tensions' line of those comparisons' printout: the slack and tight sides, the tight side and
// the guide's entry against the loop model, and the three points along the upper guide, in %.
inline void print_tensions(const ConveyorMeans& m, const ConveyorLoopModel& lm) {
  const strength::LoopResult& lr = lm.result;
  std::printf("slack %.4f tight %.4f (loop %.4f, %+.3f %%) entry %+.3f %% along", m.slack, m.tight,
              lr.tight_tension, 100 * (m.tight / lr.tight_tension - 1),
              100 * (m.upper_entry / lm.upper_entry - 1));
  for (std::size_t k = 0; k < 3; ++k)
    std::printf(" %+.3f", 100 * (m.along[k] / lm.upper_at(m.along_x[k]) - 1));
}

}  // namespace catena::dynamics::testing
