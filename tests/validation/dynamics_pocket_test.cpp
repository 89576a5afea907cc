// Round-link chain on a pocket wheel, free run-on (issue 21 validation (1), second half;
// docs/models/dynamics.md, "Pocket wheel"): the strand's speed simulated by the chain dynamics
// against the free run-on kinematics of seed 003 (catena::pocketwheel::run_on, the library behind
// `catena pocketwheel`). The forced run-on, a slow test, is in dynamics_pocket_forced_test.cpp.
//
// The paper's example chain Ø18×64 on a pocket wheel of z = 8 turning at ω = 5 rad/s clockwise
// (the strand comes in from −x over the top, the paper's frame). The strand is a straight run of
// links alternating t − d and t + d, its far end held by a constant force (a tension source); the
// chain is wrapped over a few pockets past the top. At t = 0 the state is the paper's φ = 0: the
// crank joint at θ = δ1/2 (its t + d link just seated), the strand level through it and moving
// with it. The strand's speed along x is synchronously averaged over the tooth phase φ mod 2π/z
// after the first period and compared with ω dx/dφ of the closed form at the bin's φ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/pocketwheel/run_on.hpp"
#include "pocket_run.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
using testing::PocketRun;

struct Measured {
  std::vector<double> phi;     // bin centres [rad]
  std::vector<double> strand;  // mean vx over the measured strand nodes
  std::vector<double> node;    // vx of one strand node a few links from the wheel
  double max_penetration = 0.0;
  double max_tilt = 0.0;       // [rad] the largest slope of a measured strand link
  double friction_work = 0.0;  // [J] the pockets' friction's over the run (State)
  bool converged = true;
};

Measured simulate(const PocketRun& d, int bins) {
  Sprocket w = pocket_wheel(d.pitch, d.wire, d.teeth, 0.0, 0.0, d.clearance, d.contact_stiffness,
                            d.contact_damping);
  w.driver = true;
  w.speed = -d.omega;  // clockwise: the top moves along +x
  w.friction = d.friction;
  const double r = w.pitch_radius, d1 = w.pocket_angle;
  const double tau = 2 * kPi / d.teeth, d2 = tau - d1;
  // node order: the strand's far end 0 … the crank c … the wrapped joints c + 1 … c + wrapped
  const int c = d.strand_links + (d.strand_links % 2);  // even: link c (crank → next) is t + d
  const auto n = static_cast<std::size_t>(c + 1 + d.wrapped);
  Model model = uniform_chain(n, false, d.pitch, d.node_mass, d.stiffness, d.damping, false);
  model.alternation = d.wire;
  model.links_carry_compression = !d.tension_only;
  model.sprockets = {w};
  model.loads = {{.node = 0, .fx = -d.force, .fy = 0.0}};
  State s(n, 1);
  // the wheel's angle: vertex k even at ψ + (k/2)τ; the crank at polar π/2 + δ1/2 is an odd one
  s.angle = {kPi / 2 - 0.5 * d1};
  s.speed = {-d.omega};
  const double th0 = 0.5 * d1;  // the crank's θ (from the upward vertical, + upstream)
  const double cx = -r * std::sin(th0), cy = r * std::cos(th0);
  const double vcx = d.omega * r * std::cos(th0), vcy = d.omega * r * std::sin(th0);
  double x = cx;
  for (int i = c; i >= 0; --i) {
    s.x[i] = x;
    s.y[i] = cy;
    s.vx[i] = vcx;
    s.vy[i] = vcy;
    // the link from node i − 1 to i, stretched by F/k
    if (i > 0) x -= model.rest_length(static_cast<std::size_t>(i - 1)) + d.force / d.stiffness;
  }
  double polar = kPi / 2 + th0;
  for (int k = 1; k <= d.wrapped; ++k) {
    polar -= (k % 2 == 1) ? d1 : d2;
    const auto i = static_cast<std::size_t>(c + k);
    s.x[i] = r * std::cos(polar);
    s.y[i] = r * std::sin(polar);
    s.vx[i] = d.omega * r * std::sin(polar);
    s.vy[i] = -d.omega * r * std::cos(polar);
  }
  Integrator integ(model, {.step = d.step, .theta = d.theta});
  Measured out;
  std::vector<double> strand(bins, 0.0), node(bins, 0.0);
  std::vector<int> count(bins, 0);
  const double period = tau / d.omega;
  const int steps = static_cast<int>(std::lround(d.periods * period / d.step));
  // the nodes that stay in the strand over the whole run: 2 links wind on per period
  const int last = c - 2 * d.periods - 2;
  for (int k = 0; k < steps; ++k) {
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) {
      out.converged = false;
      break;
    }
    out.max_penetration = std::max(out.max_penetration, rep.max_penetration);
    if (s.time < d.skip_periods * period) continue;
    double sum = 0.0;
    for (int i = 2; i <= last; ++i) {
      sum += s.vx[i];
      out.max_tilt =
          std::max(out.max_tilt, std::abs(std::atan2(s.y[i] - s.y[i - 1], s.x[i] - s.x[i - 1])));
    }
    const double phase = std::fmod(d.omega * s.time, tau) / tau;
    const int b = std::min(bins - 1, static_cast<int>(phase * bins));
    strand[b] += sum / (last - 1);
    node[b] += s.vx[last];
    ++count[b];
  }
  out.friction_work = s.seat_friction_work;
  for (int b = 0; b < bins; ++b) {
    out.phi.push_back((b + 0.5) / bins * tau);
    out.strand.push_back(count[b] ? strand[b] / count[b] : NAN);
    out.node.push_back(count[b] ? node[b] / count[b] : NAN);
  }
  return out;
}

struct Comparison {
  double worst = 0.0;               // max over the bins of |v_sim − v_theory| / ωR
  double variation = 0.0;           // (max − min)/ωR of the simulated bins
  double expected_variation = 0.0;  // the same of the theory at the bins' centres
  double tilt = 0.0;                // [rad] the largest slope of a measured strand link
  double friction_work = 0.0;       // [J] the pockets' friction's
};

Comparison compare(const PocketRun& d) {
  constexpr int kBins = 40;
  const Measured m = simulate(d, kBins);
  EXPECT_TRUE(m.converged);
  // every joint stays within twice the clearance of its vertex (measured: penetration ≤ 55 µm
  // at 5 kN, F/k_c = 50 µm)
  EXPECT_LT(m.max_penetration, d.clearance);
  // catena pocketwheel's free run-on, the library function
  const pocketwheel::RunOnPlan plan =
      pocketwheel::plan_run_on({.pitch = d.pitch, .wire = d.wire, .teeth = d.teeth},
                               {.kind = pocketwheel::GuideKind::kNone});
  const double v0 = d.omega * plan.geometry.pitch_radius;
  Comparison c;
  double lo = INFINITY, hi = -INFINITY, elo = INFINITY, ehi = -INFINITY;
  for (int b = 0; b < kBins; ++b) {
    const double expect = d.omega * pocketwheel::evaluate(plan, m.phi[b]).dx;
    c.worst = std::max(c.worst, std::abs(m.strand[b] - expect) / v0);
    lo = std::min(lo, m.strand[b]);
    hi = std::max(hi, m.strand[b]);
    elo = std::min(elo, expect);
    ehi = std::max(ehi, expect);
  }
  c.variation = (hi - lo) / v0;
  c.tilt = m.max_tilt;
  c.friction_work = m.friction_work;
  c.expected_variation = (ehi - elo) / v0;
  std::printf(
      "k %.2g F %.0f mu %.2g: worst %.4f variation %.4f (theory %.4f) tilt %.4f rad, "
      "friction work %.4g J\n",
      d.stiffness, d.force, d.friction, c.worst, c.variation, c.expected_variation, c.tilt,
      c.friction_work);
  return c;
}

// The strand of a stiff chain (k = 1.6e9 N/m: the strand's first longitudinal mode, free at the
// tension source, ≈ 390 Hz, 60 times the tooth frequency zω/2π = 6.4 Hz) at 1, 2 and 5 kN: its
// speed over the tooth period within 1 % of ωR of the kinematics (measured with the tension-only
// links 0.56 %, 0.64 %, 0.94 %). The speed variation itself (theory at the bins' centres
// 0.0292 ωR: the bins blunt the cusp 1 − cos(δ1/2) = 0.0316) is reproduced only to about ±15 %
// (measured 0.0284, 0.0335, 0.0284): the elastic strand's ringing and transverse motion ride on it
// (below).
TEST(DynamicsPocketWheel, FreeRunOnStrandSpeedAgainstPocketwheel) {
  for (double force : {1000.0, 2000.0, 5000.0}) {
    PocketRun d;
    d.stiffness = 1.6e9;
    d.force = force;
    const Comparison c = compare(d);
    EXPECT_LT(c.worst, 0.01) << "F " << force;
    EXPECT_NEAR(c.variation / c.expected_variation, 1.0, 0.2) << "F " << force;
    EXPECT_NEAR(c.expected_variation, 0.0292, 5e-4);
  }
}

// Friction in the pockets (docs/models/dynamics.md, "Pocket wheel: friction"): the stiff strand of
// the first test at 1, 2 and 5 kN with μ = 0.1 in the pockets. The kinematics has no friction,
// but the joints it follows sit at the pockets' vertices, and the friction acts only on a joint's
// slip within its clearance: the strand's speed stays within the same 1 % of ωR and its
// variation within the same 20 % (measured 0.64 %, 0.83 %, 0.61 % against 0.56 %, 0.64 %,
// 0.94 % without; variation 0.0292, 0.0346, 0.0278 ωR against 0.0284, 0.0335, 0.0284), while the
// friction does work (< 0).
TEST(DynamicsPocketWheel, FreeRunOnWithFrictionInThePocketsKeepsTheOnePercent) {
  for (double force : {1000.0, 2000.0, 5000.0}) {
    PocketRun d;
    d.stiffness = 1.6e9;
    d.force = force;
    d.friction = 0.1;
    const Comparison c = compare(d);
    EXPECT_LT(c.worst, 0.01) << "F " << force;
    EXPECT_NEAR(c.variation / c.expected_variation, 1.0, 0.2) << "F " << force;
    EXPECT_LT(c.friction_work, 0.0) << "F " << force;
  }
}

// Where the 1 % is not reached, pinned as measured (docs/models/dynamics.md, "Pocket wheel"):
// the kinematics is that of a rigid strand that translates keeping its direction. (a) A softer
// strand (k = 1e8 N/m, first longitudinal mode ≈ 97 Hz, 15× the tooth frequency) rings after
// every seating and every jump of a_x: 1.37 % at 1 kN, 0.70 % at 4e8 (tension-only links). (b) At a
// low tension (200 N) the strand does not translate as a rigid bar: the seatings' transverse kicks
// travel along it as waves (c = √(T/q) = 5.5 m/s), the strand's links tilt (up to 0.074 rad,
// against 0.048 rad at 1 kN) and the x-speed picks up the swing: 1.43 % even on the stiff chain.
TEST(DynamicsPocketWheel, SoftOrSlackStrandsMissTheOnePercentForAReason) {
  PocketRun soft;
  soft.stiffness = 1e8;
  const double w_soft = compare(soft).worst;
  PocketRun stiffer = soft;
  stiffer.stiffness = 4e8;
  const double w_stiffer = compare(stiffer).worst;
  EXPECT_GT(w_soft, 0.01);
  EXPECT_LT(w_soft, 0.02);
  EXPECT_LT(w_stiffer, 0.75 * w_soft);  // the deviation falls as the strand stiffens
  PocketRun slack;
  slack.stiffness = 1.6e9;
  slack.force = 200.0;
  const Comparison c_slack = compare(slack);
  EXPECT_GT(c_slack.worst, 0.01);
  EXPECT_LT(c_slack.worst, 0.02);
  // the strand does not keep its direction: its links tilt by up to 0.074 rad at 200 N against
  // 0.048 rad at 1 kN on the same chain (measured)
  PocketRun taut = slack;
  taut.force = 1000.0;
  EXPECT_GT(c_slack.tilt, 1.3 * compare(taut).tilt);
}

}  // namespace
}  // namespace catena::dynamics
