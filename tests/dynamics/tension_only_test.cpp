// Tension-only links (Model::links_carry_compression = false; docs/models/dynamics.md,
// "Tension-only links"): a round link cannot push its neighbour. The law (link_force) against
// central differences and its energy's derivative, in compression, in the ramp and in tension;
// the integrator's Newton matrix against its residual's differences; two nodes pushed together
// pass without a force; a mass bouncing on a slack link closes its work balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kStiffness = 1e8;  // the pocket example's chain: k = 1e8 N/m, c = 2000 N·s/m
constexpr double kDamping = 2000.0;
constexpr double kPitch = 0.064;

Model tension_only(std::size_t nodes, double damping = kDamping) {
  Model m = uniform_chain(nodes, false, kPitch, 0.42, kStiffness, damping, false);
  m.links_carry_compression = false;
  return m;
}

// The law over compression, the ramp and tension, at rates from fast shortening to fast
// stretching: T ≥ 0 everywhere, T = 0 and E = 0 in compression below the ramp (the bilateral law
// pushes there with k s < 0), the bilateral law exactly beyond the ramp where it pulls, ∂T/∂s and
// ∂T/∂ṡ against central differences, and T_e = dE/ds.
TEST(DynamicsTensionOnlyLinks, LawNeverPushesAndItsDerivativesAndEnergyAreExact) {
  const Model m = tension_only(2);
  Model bilateral = m;
  bilateral.links_carry_compression = true;
  const double eps = m.link_smoothing;
  ASSERT_EQ(eps, 1e-6);
  int compressed = 0, ramp = 0, taut = 0, clamped = 0;
  for (int i = -300; i <= 300; ++i) {
    const double s = i * 0.01 * eps + 0.003 * eps;  // off the ramp's ends by a little
    for (const double rate : {-0.5, -0.02, -1e-4, 0.0, 1e-4, 0.02, 0.5}) {
      const LinkForce f = link_force(m, s, rate);
      EXPECT_GE(f.tension, 0.0) << s << " " << rate;
      const double u = s + 0.5 * eps;
      if (u <= 0.0) {
        ++compressed;
        EXPECT_EQ(f.tension, 0.0);
        EXPECT_EQ(f.energy, 0.0);
        EXPECT_EQ(f.stiffness, 0.0);
        EXPECT_EQ(f.damping, 0.0);
      } else if (u < eps) {
        ++ramp;
        EXPECT_GT(f.elastic, 0.0);
        EXPECT_LT(f.elastic, kStiffness * eps / 2 * (1 + 1e-12));
      } else {
        ++taut;
        const LinkForce b = link_force(bilateral, s, rate);
        EXPECT_EQ(f.elastic, b.elastic);
        if (b.tension > 0.0) {
          EXPECT_EQ(f.tension, b.tension);
        } else {
          EXPECT_EQ(f.tension, 0.0);
        }
      }
      if (f.tension == 0.0 && f.elastic > 0.0) ++clamped;
      // the derivatives, where the differences do not straddle the clamp T = 0
      const double ds = 1e-4 * eps, dr = 1e-7;
      const LinkForce sp = link_force(m, s + ds, rate), sm = link_force(m, s - ds, rate);
      const LinkForce rp = link_force(m, s, rate + dr), rm = link_force(m, s, rate - dr);
      const double scale = kStiffness + kDamping * std::abs(rate) / eps;
      if ((sp.tension > 0.0) == (sm.tension > 0.0) && (sp.tension > 0.0) == (f.tension > 0.0)) {
        EXPECT_NEAR(f.stiffness, (sp.tension - sm.tension) / (2 * ds), 1e-6 * scale)
            << s << " " << rate;
      }
      if ((rp.tension > 0.0) == (rm.tension > 0.0) && (rp.tension > 0.0) == (f.tension > 0.0)) {
        EXPECT_NEAR(f.damping, (rp.tension - rm.tension) / (2 * dr), 1e-6 * kDamping)
            << s << " " << rate;
      }
      EXPECT_NEAR(f.elastic, (sp.energy - sm.energy) / (2 * ds), 1e-6 * kStiffness * eps) << s;
    }
  }
  // C¹ at both ends of the ramp: T_e and its slope meet
  for (const double u : {0.0, eps}) {
    const double s = u - 0.5 * eps, d = 1e-9 * eps;
    const LinkForce lo = link_force(m, s - d, 0.0), hi = link_force(m, s + d, 0.0);
    EXPECT_NEAR(lo.elastic, hi.elastic, 1e-6 * kStiffness * eps);
    EXPECT_NEAR(lo.stiffness, hi.stiffness, 1e-6 * kStiffness);
    EXPECT_NEAR(lo.energy, hi.energy, 1e-6 * kStiffness * eps * eps);
  }
  EXPECT_GT(compressed, 1000);
  EXPECT_GT(ramp, 500);
  EXPECT_GT(taut, 1000);
  EXPECT_GT(clamped, 50);  // shortening fast in tension: slack, the spring still stretched
}

// A 4-node chain at rest, node 0 at the origin, its link j len[j] long at the angle ang[j]
State three_link_chain(const double (&len)[3], const double (&ang)[3]) {
  State s(4, 0);
  for (std::size_t j = 0; j < 3; ++j) {
    s.x[j + 1] = s.x[j] + len[j] * std::cos(ang[j]);
    s.y[j + 1] = s.y[j] + len[j] * std::sin(ang[j]);
  }
  return s;
}

using NodeForce = std::array<double, 2>;
// Each node's force of that chain from its links' tensions t (+T_j e_j from the link j = i it
// starts, −T_j e_j from link i − 1) against −∂E/∂q, the central difference of energy().elastic;
// the forces, for further checks
std::vector<NodeForce> expect_node_forces_are_minus_the_energys_gradient(
    const Model& m, const State& s, const std::vector<double>& t, const double (&ang)[3]) {
  const double eps = m.link_smoothing;
  std::vector<NodeForce> forces(4, NodeForce{0.0, 0.0});
  for (std::size_t i = 0; i < 4; ++i) {
    NodeForce& f = forces[i];
    if (i < 3) f[0] += t[i] * std::cos(ang[i]), f[1] += t[i] * std::sin(ang[i]);
    if (i > 0) f[0] -= t[i - 1] * std::cos(ang[i - 1]), f[1] -= t[i - 1] * std::sin(ang[i - 1]);
    for (int axis = 0; axis < 2; ++axis) {
      const double d = 1e-4 * eps;
      State p = s, q = s;
      (axis == 0 ? p.x : p.y)[i] += d;
      (axis == 0 ? q.x : q.y)[i] -= d;
      const double grad = (energy(m, p).elastic - energy(m, q).elastic) / (2 * d);
      EXPECT_NEAR(f[axis], -grad, 1e-3 * kStiffness * eps) << i << " " << axis;
    }
  }
  return forces;
}

// That chain's residual in the integrator at rest (θ = ½, the step h): the inertia's part is 0 at
// the predictor, so −r/h is each node's force, checked against expect_node_forces_are_minus_the_
// energys_gradient's forces (and through it against −∂E/∂q)
void expect_rest_residual_is_minus_the_energys_gradient(const Model& m, const State& s,
                                                        const std::vector<double>& t,
                                                        const double (&ang)[3], double h) {
  Integrator integ(m, {.step = h, .theta = 0.5});
  std::vector<double> u(8), r;
  for (std::size_t i = 0; i < 4; ++i) u[2 * i] = s.x[i], u[2 * i + 1] = s.y[i];
  integ.newton_system(m, s, u, r, nullptr);
  const std::vector<NodeForce> at_rest =
      expect_node_forces_are_minus_the_energys_gradient(m, s, t, ang);
  for (std::size_t i = 0; i < 4; ++i)
    for (int axis = 0; axis < 2; ++axis)
      EXPECT_NEAR(-r[2 * i + axis] / h, at_rest[i][axis], 1e-9 * kStiffness * m.link_smoothing)
          << i << " " << axis;
}

// energy() and link_tensions() read the law: on a 4-node chain at rest (one link slack, one in the
// ramp, one taut), each node's force from the tensions against −∂E/∂q, the central difference of
// energy().elastic.
TEST(DynamicsTensionOnlyLinks, ForceIsMinusTheGradientOfTheChainsEnergy) {
  const Model m = tension_only(4);
  const double eps = m.link_smoothing;
  // link 0 slack (2 µm short), link 1 in the ramp (0.2 ε), link 2 taut (30 µm)
  const double len[3] = {kPitch - 2e-6, kPitch + 0.2 * eps, kPitch + 30e-6};
  const double ang[3] = {0.1, -0.3, 0.7};
  const State s = three_link_chain(len, ang);
  std::vector<double> t(3);
  link_tensions(m, s, t);
  EXPECT_EQ(t[0], 0.0);  // the bilateral law: −200 N
  EXPECT_GT(t[1], 0.0);
  EXPECT_NEAR(t[2], kStiffness * 30e-6, 1e-6);
  expect_node_forces_are_minus_the_energys_gradient(m, s, t, ang);
}

// The integrator's Newton matrix (Integrator::newton_system) against central differences of its
// residual, on a chain whose links are at the step's θ point slack, in the ramp, taut, and taut
// but shortening faster than the spring pulls (slack by the clamp); and the slack link's end node
// feels no force: its residual is the inertia's alone, 0 at the constant-velocity predictor.
TEST(DynamicsTensionOnlyLinks, NewtonMatrixMatchesTheResidualsDifferences) {
  const Model m = tension_only(5);
  const double eps = m.link_smoothing, h = 1e-4, th = 0.6;
  State s(5, 0);
  const double len[4] = {kPitch - 3e-6, kPitch + 0.1 * eps, kPitch + 20e-6, kPitch + 2e-6};
  const double ang[4] = {0.2, -0.4, 0.5, 1.1};
  // the rate of each link along itself: link 3 shortens at 0.5 m/s (c ṡ = −1000 N against
  // k s = 200 N), the others slowly
  const double rate[4] = {0.0, 1e-4, -1e-3, -0.5};
  for (std::size_t j = 0; j < 4; ++j) {
    s.x[j + 1] = s.x[j] + len[j] * std::cos(ang[j]);
    s.y[j + 1] = s.y[j] + len[j] * std::sin(ang[j]);
    s.vx[j + 1] = s.vx[j] + rate[j] * std::cos(ang[j]) - 0.3 * std::sin(ang[j]);
    s.vy[j + 1] = s.vy[j] + rate[j] * std::sin(ang[j]) + 0.3 * std::cos(ang[j]);
  }
  std::vector<double> t(4);
  link_tensions(m, s, t);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_GT(t[1], 0.0);
  EXPECT_GT(t[2], 1000.0);
  EXPECT_EQ(t[3], 0.0);
  Integrator integ(m, {.step = h, .theta = th});
  const std::size_t nu = integ.unknowns();
  ASSERT_EQ(nu, 10u);
  std::vector<double> u(nu), r, jac;
  for (std::size_t i = 0; i < 5; ++i) {
    u[2 * i] = s.x[i] + h * s.vx[i];
    u[2 * i + 1] = s.y[i] + h * s.vy[i];
  }
  integ.newton_system(m, s, u, r, &jac);
  // node 0 hangs on the slack link 0 alone
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
  const double scale = h * th * kStiffness;
  double worst = 0.0;
  for (std::size_t j = 0; j < nu; ++j) {
    const std::vector<double> fd = testing::residual_difference(integ, m, s, u, j, 1e-11);
    for (std::size_t a = 0; a < nu; ++a) {
      worst = std::max(worst, std::abs(fd[a] - jac[a * nu + j]) / scale);
      EXPECT_NEAR(jac[a * nu + j], fd[a], 1e-5 * scale) << a << " " << j;
    }
  }
  std::printf("tension-only Newton matrix: largest misfit %.2e of h theta k\n", worst);
}

// Two free nodes on one link, thrown together at 1 m/s each: the link goes slack and they pass
// on at their speeds (the undamped bilateral link, for contrast, rings with them at its
// 3.5 kHz, pushing with −9 kN); every tension 0, the energy unchanged.
TEST(DynamicsTensionOnlyLinks, NodesPushedTogetherFeelNoForce) {
  for (const bool compression : {false, true}) {
    Model m = tension_only(2, 0.0);   // undamped: the bilateral link rings, never lets them pass
    ASSERT_EQ(m.jam_length(0), 0.0);  // no jam (NodesThrownTogetherBounceOffTheJam: with one)
    m.links_carry_compression = compression;
    State s(2, 0);
    s.x[1] = kPitch - 1e-6;  // just slack (at l = p the ramp still pulls k ε/8 = 12.5 N)
    s.vx[0] = 1.0;
    s.vx[1] = -1.0;
    const double e0 = energy(m, s).total();
    Integrator integ(m, {.step = 1e-5, .theta = 0.5});
    std::vector<double> t(1);
    double lowest = 0.0;
    for (int k = 0; k < 1000; ++k) {  // 10 ms: the gap closes by 20 mm of 64
      ASSERT_TRUE(integ.step(m, s).converged) << k;
      link_tensions(m, s, t);
      lowest = std::min(lowest, t[0]);
    }
    std::printf("pushed together (%s): v %.6f %.6f m/s, lowest tension %.1f N\n",
                compression ? "bilateral" : "tension-only", s.vx[0], s.vx[1], lowest);
    if (compression) {  // the old law, for contrast: the link pushes them back
      EXPECT_LT(lowest, -1000.0);
      EXPECT_GT(std::abs(s.vx[0] - 1.0), 0.1);
      continue;
    }
    EXPECT_EQ(lowest, 0.0);
    // (to Newton's rounding: the steps' corrections stop at 1e-10 of the pitch)
    EXPECT_NEAR(s.vx[0], 1.0, 1e-9);
    EXPECT_NEAR(s.vx[1], -1.0, 1e-9);
    EXPECT_NEAR(s.x[1] - s.x[0], kPitch - 1e-6 - 0.02, 1e-12);
    EXPECT_NEAR(energy(m, s).total(), e0, 1e-9 * e0);
    EXPECT_EQ(s.damper_work, 0.0);
  }
}

// A mass on a slack-able link: node 0 pinned, node 1 (0.42 kg) thrown outward at 0.1 m/s from the
// rest length, gravity pulling it away from the pin (9.81 m/s²). The link stretches, throws the
// mass back, goes slack (the mass flies free towards the pin until gravity turns it) and catches
// it again, over and over. The tension never goes below 0 (the bilateral law keeps the mass
// oscillating about the rest length, through compression), the link goes slack, and at θ = ½ the
// work balance closes:
// ΔE = the damper's work + a numerical rest that is small against it (the ramp's steps are not a
// discrete gradient).
TEST(DynamicsTensionOnlyLinks, BouncingOnASlackLinkClosesItsWorkBalance) {
  Model m = tension_only(2);
  m.pinned = {1, 0};
  m.gravity_x = 9.81;
  State s(2, 0);
  s.x[1] = kPitch;
  s.vx[1] = 0.1;
  const double e0 = energy(m, s).total();
  Integrator integ(m, {.step = 2e-6, .theta = 0.5});
  std::vector<double> t(1);
  double lowest = INFINITY, shortest = INFINITY, highest = 0.0;
  for (int k = 0; k < 20000; ++k) {  // 40 ms
    ASSERT_TRUE(integ.step(m, s).converged) << k;
    link_tensions(m, s, t);
    lowest = std::min(lowest, t[0]);
    highest = std::max(highest, t[0]);
    shortest = std::min(shortest, s.x[1] - s.x[0]);
  }
  const double de = energy(m, s).total() - e0, rest = de - s.damper_work;
  std::printf(
      "bouncing: tension %.3g .. %.1f N, shortest l - p %.2f um, dE %.4e J, damper %.4e J, "
      "numerical %.2e J\n",
      lowest, highest, (shortest - kPitch) * 1e6, de, s.damper_work, rest);
  EXPECT_GE(lowest, 0.0);
  EXPECT_GT(highest, 300.0);
  EXPECT_LT(shortest - kPitch, -10 * m.link_smoothing);  // slack, well below the ramp
  EXPECT_LT(s.damper_work, -1e-4);
  EXPECT_LT(std::abs(rest), 1e-3 * std::abs(s.damper_work));
}

// With Model::links_discrete_gradient the same bouncing mass closes its work balance to rounding:
// the links' force over the step (link_step_force) does exactly −ΔE of its spring at θ = ½, also
// on the steps that enter, cross or leave the ramp (the θ point's force leaves +8.1e-8 J there
// with Newton to the same 1e-13; +9.9e-8 J at the default, the test above). The damper over the
// step dissipates as much as the θ point's (within 1 %).
TEST(DynamicsTensionOnlyLinks, BouncingWithTheDiscreteGradientClosesItsBalanceToRounding) {
  double rest[2] = {0.0, 0.0}, damper[2] = {0.0, 0.0};
  for (const bool gradient : {false, true}) {
    Model m = tension_only(2);
    m.pinned = {1, 0};
    m.gravity_x = 9.81;
    m.links_discrete_gradient = gradient;
    State s(2, 0);
    s.x[1] = kPitch;
    s.vx[1] = 0.1;
    const double e0 = energy(m, s).total();
    // Newton to 1e-13 of the pitch: at the default 1e-10 its stopping leaves 1.8e-8 J here
    Integrator integ(m, {.step = 2e-6, .tolerance = 1e-13, .theta = 0.5});
    std::vector<double> t(1);
    double lowest = INFINITY, shortest = INFINITY;
    for (int k = 0; k < 20000; ++k) {  // 40 ms
      ASSERT_TRUE(integ.step(m, s).converged) << k;
      link_tensions(m, s, t);
      lowest = std::min(lowest, t[0]);
      shortest = std::min(shortest, s.x[1] - s.x[0]);
    }
    const double de = energy(m, s).total() - e0;
    rest[gradient] = de - s.damper_work;
    damper[gradient] = s.damper_work;
    std::printf("bouncing (%s): dE %.6e J, damper %.6e J, numerical %.2e J\n",
                gradient ? "discrete gradient" : "theta point", de, s.damper_work, rest[gradient]);
    EXPECT_GE(lowest, 0.0);
    EXPECT_LT(shortest - kPitch, -10 * m.link_smoothing);  // it goes slack: through the ramp
  }
  EXPECT_GT(std::abs(rest[0]), 1e-8);  // the θ point's: the ramp's steps
  EXPECT_LT(std::abs(rest[1]), 1e-10);
  EXPECT_LT(std::abs(rest[1]), 1e-3 * std::abs(rest[0]));
  EXPECT_LT(damper[1], -1e-4);
  EXPECT_NEAR(damper[1], damper[0], 1e-2 * std::abs(damper[0]));
}

// One step h at θ = ½ of a link between two massless nodes through the integrator's assembly
// (Integrator::newton_system at the step's end as the iterate, the nodes moving at Δx/h: the
// residual is −h × the link's force): the link goes from l0 to l1 long [m] while it turns 0.3 rad
// (0.4 → 0.7) and its first node moves by (2e-4, −1e-4) m.
struct LinkStepWork {
  double work = 0.0;                    // Σ F·Δx over the nodes [J], F = −r/h
  double terms = 0.0;                   // Σ |F·Δx| [J]: the sum's rounding
  double length0 = 0.0, length1 = 0.0;  // the ends' lengths as newton_system takes them [m]
};
LinkStepWork one_link_step(const Model& m, double l0, double l1, double h) {
  State s(2, 0);
  const double a0 = 0.4, a1 = 0.7;
  const double x0[4] = {0.0, 0.0, l0 * std::cos(a0), l0 * std::sin(a0)};
  const double x1[4] = {2e-4, -1e-4, 2e-4 + l1 * std::cos(a1), -1e-4 + l1 * std::sin(a1)};
  std::vector<double> u(4);
  for (std::size_t i = 0; i < 2; ++i) {
    s.x[i] = x0[2 * i];
    s.y[i] = x0[2 * i + 1];
    s.vx[i] = (x1[2 * i] - x0[2 * i]) / h;
    s.vy[i] = (x1[2 * i + 1] - x0[2 * i + 1]) / h;
    u[2 * i] = x1[2 * i];
    u[2 * i + 1] = x1[2 * i + 1];
  }
  Integrator integ(m, {.step = h, .theta = 0.5});
  std::vector<double> r;
  integ.newton_system(m, s, u, r, nullptr);
  LinkStepWork out;
  for (std::size_t a = 0; a < 4; ++a) {
    out.work -= r[a] / h * (x1[a] - x0[a]);
    out.terms += std::abs(r[a] / h * (x1[a] - x0[a]));
  }
  const double d1x = x1[2] - x1[0], d1y = x1[3] - x1[1];
  out.length0 = std::hypot(x0[2], x0[3]);
  out.length1 = std::sqrt(d1x * d1x + d1y * d1y);
  return out;
}

// One step of a link at θ = ½ through the integrator's assembly (Integrator::newton_system at
// the step's end as the iterate, massless nodes moving at Δx/h: the residual is −h × the link's
// force), undamped, the link turning 0.3 rad: with Model::links_discrete_gradient its work on the
// two nodes is −(E(s₁) − E(s₀)) to rounding on a step that enters the ramp, crosses it, leaves
// it either way, stays within it, or comes down into it from beyond; the θ point's force misses.
TEST(DynamicsTensionOnlyLinks, OneStepsWorkIsMinusTheEnergysChangeWithTheDiscreteGradient) {
  const double eps = 1e-6, h = 1e-5;
  struct Case {
    const char* name;
    double s0, s1;  // [ε]
  };
  const Case cases[] = {{"entering", -0.8, -0.1}, {"crossing", -0.8, 1.4},
                        {"leaving", 0.3, -0.9},   {"leaving up", 0.1, 2.0},
                        {"inside", -0.3, 0.35},   {"from beyond", 3.0, 0.2},
                        {"beyond", 2.0, 40.0}};
  for (const Case& c : cases) {
    double misfit[2] = {0.0, 0.0};
    double de = 0.0, rounding = 0.0;
    for (const bool gradient : {false, true}) {
      Model m = uniform_chain(2, false, kPitch, 1e-12, kStiffness, 0.0, false);
      m.links_carry_compression = false;
      m.links_discrete_gradient = gradient;
      const LinkStepWork step = one_link_step(m, kPitch + c.s0 * eps, kPitch + c.s1 * eps, h);
      de = link_force(m, c.s1 * eps, 0.0).energy - link_force(m, c.s0 * eps, 0.0).energy;
      misfit[gradient] = step.work + de;
      if (gradient) rounding = 1e-14 * step.terms;
    }
    std::printf("%-12s dE %+.6e J: work + dE %+.2e J (theta point %+.2e J; rounding %.1e J)\n",
                c.name, de, misfit[1], misfit[0], rounding);
    EXPECT_LT(std::abs(misfit[1]), rounding) << c.name;
    if (std::string(c.name) != "beyond") {  // beyond the ramp the θ point's is exact too
      EXPECT_GT(std::abs(misfit[0]), 1e-4 * std::abs(de)) << c.name;
    }
  }
}

// The damper over the step (link_step_force, damped, spring off): f_d = (C(u₁) − C(u₀))/h against
// Simpson's rule for ∫ c min(1, u/ε) du over [u₀, u₁] (0 for u ≤ 0), and the whole force's
// damper share T − T_dg does the work −(T − T_dg)(s₁ − s₀) ≤ 0 on random steps, clamped or not
// (the spring on); its slope ∂T/∂s₁ against central differences where T is not clamped.
TEST(DynamicsTensionOnlyLinks, DamperOverTheStepIsTheRampsIntegralAndNeverDoesWork) {
  const double eps = 1e-6;
  Model m = tension_only(2);
  Model damper_only = m;
  damper_only.axial_stiffness = 0.0;  // (unvalidated: the law alone)
  unsigned seed = 12345u;
  auto uniform = [&seed]() {  // a small LCG: the same steps on every platform
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) * (1.0 / 16777216.0);
  };
  int clamped = 0, checked = 0;
  double worst_integral = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double s0 = (-3.0 + 8.0 * uniform()) * eps;
    const double s1 = k % 2 == 0 ? (-3.0 + 8.0 * uniform()) * eps : s0 + (uniform() - 0.5) * eps;
    const double h = std::pow(10.0, -7.0 + 3.0 * uniform());  // 0.1 µs .. 0.1 ms
    // Simpson's rule on the ramped coefficient, with the ramp's kinks as nodes
    auto coefficient = [&](double v) { return kDamping * std::clamp(v / eps, 0.0, 1.0); };
    const double u0 = s0 + 0.5 * eps, u1 = s1 + 0.5 * eps;
    std::vector<double> knots{u0, u1};
    for (const double kink : {0.0, eps})
      if ((kink - u0) * (kink - u1) < 0.0) knots.push_back(kink);
    std::sort(knots.begin(), knots.end());
    double integral = 0.0;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1];
      integral +=
          (b - a) / 6.0 * (coefficient(a) + 4.0 * coefficient(0.5 * (a + b)) + coefficient(b));
    }
    if (u1 < u0) integral = -integral;
    const LinkStep d = link_step_force(damper_only, s0, s1, h);
    EXPECT_EQ(d.elastic, 0.0);
    const double fd = integral / h;
    // (the spring off, the clamp keeps only the damper's pull)
    EXPECT_NEAR(d.tension, std::max(0.0, fd), 1e-9 * kDamping * eps / h + 1e-12 * std::abs(fd))
        << s0 << " " << s1 << " " << h;
    worst_integral =
        std::max(worst_integral, std::abs(d.tension - std::max(0.0, fd)) * h / (kDamping * eps));
    const LinkStep f = link_step_force(m, s0, s1, h);
    EXPECT_GE(f.tension, 0.0);
    EXPECT_GE(f.elastic, 0.0);
    const double work = -(f.tension - f.elastic) * (s1 - s0);
    EXPECT_LE(work, 0.0) << s0 << " " << s1 << " " << h;
    if (f.tension == 0.0 && f.elastic > 0.0) ++clamped;
    // ∂T/∂s₁, where the difference stays on one side of the clamp and of the threshold
    const double ds = 1e-6 * eps;
    const LinkStep p = link_step_force(m, s0, s1 + ds, h), q = link_step_force(m, s0, s1 - ds, h);
    if ((p.tension > 0.0) == (q.tension > 0.0) && (p.tension > 0.0) == (f.tension > 0.0) &&
        std::abs(s1 - s0) > 10 * ds) {
      ++checked;
      EXPECT_NEAR(f.slope, (p.tension - q.tension) / (2 * ds), 1e-5 * (kStiffness + kDamping / h))
          << s0 << " " << s1 << " " << h;
    }
  }
  std::printf("damper over the step: %d clamped, %d slopes checked, integral within %.2e\n",
              clamped, checked, worst_integral);
  EXPECT_GT(clamped, 100);
  EXPECT_GT(checked, 10000);
}

// The spring over a step shorter than the threshold |s₁ − s₀| ≤ 1e-6 max(ε, |s₀|, |s₁|)
// (link_step_force's fallback, undamped): T_e at the mean stretch, against the quotient of E
// written out piece by piece (0 slack, k u³/6ε in the ramp, ½ k s² + k ε²/24 beyond: each piece's
// mean force k (u_a² + u_a u_b + u_b²)/6ε, k (s_a + s_b)/2, weighted by its length, no
// cancellation) within k Δs²/24ε plus rounding, and its slope ½ ∂T_e/∂s at the mean against
// central differences. In the ramp's middle (s₀ = −s₁ = 1e-13 ε, T = k ε/8) the threshold's scale
// is ε (`floor`), not |s| ≈ 1e-13 ε: the quotient there would be E's rounding over Δs; then across
// the ramp's upper end (s = ε/2, where E''' jumps), near its lower end, and far beyond it.
TEST(DynamicsTensionOnlyLinks, ShortStepsTakeTheMeanStretchsForceWithTheScaleOfTheRamp) {
  const Model m = tension_only(2, 0.0);
  const double eps = m.link_smoothing, k = kStiffness, h = 1e-5;
  auto quotient = [&](double s0, double s1) {  // (E(s₁) − E(s₀))/(s₁ − s₀), s₀ < s₁
    double sum = 0.0;
    std::vector<double> knots{s0, s1};
    for (const double kink : {-0.5 * eps, 0.5 * eps})
      if (kink > s0 && kink < s1) knots.push_back(kink);
    std::sort(knots.begin(), knots.end());
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1], ua = a + 0.5 * eps, ub = b + 0.5 * eps;
      const double mid = 0.5 * (ua + ub);
      double mean = 0.0;
      if (mid >= eps) {
        mean = 0.5 * k * (a + b);
      } else if (mid > 0.0) {
        mean = k * (ua * ua + ua * ub + ub * ub) / (6.0 * eps);
      }
      sum += (b - a) * mean;
    }
    return sum / (s1 - s0);
  };
  struct Case {
    const char* name;
    double s0, s1, ds;  // [ε] the step's ends and the central difference's half-width
  };
  const Case cases[] = {{"ramp's middle", -1e-13, 1e-13, 1e-8},
                        {"upper end", 0.5 - 2e-8, 0.5 + 3e-8, 1e-9},
                        {"lower end", -0.5 - 1e-8, -0.5 + 5e-7, 1e-8},
                        {"far beyond", 40.0, 40.0 + 2e-5, 1e-7}};
  for (const Case& c : cases) {
    const double s0 = c.s0 * eps, s1 = c.s1 * eps, ds = c.ds * eps;
    ASSERT_LE(std::abs(s1 - s0), 1e-6 * std::max({eps, std::abs(s0), std::abs(s1)}));
    const LinkStep f = link_step_force(m, s0, s1, h);
    const double q = quotient(s0, s1), mean = 0.5 * (s0 + s1);
    const double bound = k * (s1 - s0) * (s1 - s0) / (24.0 * eps) + 1e-15 * std::abs(q);
    ASSERT_GT(f.tension, 0.0) << c.name;
    EXPECT_EQ(f.tension, f.elastic) << c.name;
    EXPECT_NEAR(f.tension, q, bound) << c.name;
    // ½ ∂T_e/∂s at the mean: ½ k u/ε in the ramp, ½ k beyond
    const double u = mean + 0.5 * eps;
    EXPECT_NEAR(f.slope, 0.5 * k * std::min(u / eps, 1.0), 1e-9 * k) << c.name;
    const LinkStep p = link_step_force(m, s0, s1 + ds, h), n = link_step_force(m, s0, s1 - ds, h);
    const double difference = (p.tension - n.tension) / (2.0 * ds);
    EXPECT_NEAR(f.slope, difference, 1e-6 * k) << c.name;
    std::printf(
        "%-14s T %.15g N, quotient %.15g N (bound %.1e N); slope %.6e N/m, differences %.6e "
        "N/m\n",
        c.name, f.tension, q, bound, f.slope, difference);
  }
}

// The integrator's Newton matrix with Model::links_discrete_gradient at θ = ½ against central
// differences of its residual: at the iterate the links go slack → slack, ramp → ramp,
// slack → ramp, taut → taut and taut → ramp shortening so fast that the damper over the step
// clamps T at 0 (h = 10 µs: c/h = 2e8 N/m > k).
// A step of a 6-node chain: its links j from kPitch + s0[j] long at the angles a0[j] (node 0 at
// the origin) to kPitch + s1[j], each turned by `turn`, node 0 moved by (1, −2) µm: the start's
// positions in `s`, the step's end in `u`
void five_link_step(const double (&s0)[5], const double (&s1)[5], const double (&a0)[5],
                    double turn, State& s, std::vector<double>& u) {
  u[0] = 1e-6;
  u[1] = -2e-6;
  for (std::size_t j = 0; j < 5; ++j) {
    s.x[j + 1] = s.x[j] + (kPitch + s0[j]) * std::cos(a0[j]);
    s.y[j + 1] = s.y[j] + (kPitch + s0[j]) * std::sin(a0[j]);
    u[2 * j + 2] = u[2 * j] + (kPitch + s1[j]) * std::cos(a0[j] + turn);
    u[2 * j + 3] = u[2 * j + 1] + (kPitch + s1[j]) * std::sin(a0[j] + turn);
  }
}

TEST(DynamicsTensionOnlyLinks, NewtonMatrixWithTheDiscreteGradientMatchesTheDifferences) {
  Model m = tension_only(6);
  m.links_discrete_gradient = true;
  const double eps = m.link_smoothing, h = 1e-5, th = 0.5;
  const double s0[5] = {-3e-6, 0.1 * eps, -0.8 * eps, 20e-6, 6e-6};
  const double s1[5] = {-2.5e-6, 0.3 * eps, 0.2 * eps, 20.5e-6, 3e-6};
  const double a0[5] = {0.2, -0.4, 0.5, 1.1, -0.9}, turn = 0.01;
  State s(6, 0);
  std::vector<double> u(12);
  five_link_step(s0, s1, a0, turn, s, u);
  for (std::size_t j = 0; j < 5; ++j) {
    const LinkStep law = link_step_force(m, s0[j], s1[j], h);
    if (j == 0) {
      EXPECT_EQ(law.elastic, 0.0);
    } else if (j < 4) {
      EXPECT_GT(law.tension, 0.0) << j;
    } else {
      EXPECT_GT(law.elastic, 100.0);
      EXPECT_EQ(law.tension, 0.0);
    }
  }
  Integrator integ(m, {.step = h, .theta = th});
  std::vector<double> r, jac, point;
  integ.newton_system(m, s, u, r, &jac);
  Model theta_point = m;
  theta_point.links_discrete_gradient = false;
  Integrator other(theta_point, {.step = h, .theta = th});
  other.newton_system(theta_point, s, u, r, &point);
  const double scale = h * th * kStiffness;
  const testing::ColumnsAgainstDifferences found = testing::expect_columns_match_differences(
      integ, m, s, u, jac, point, [](std::size_t) { return 1e-11; }, 1e-7);
  std::printf(
      "discrete-gradient links' Newton matrix: largest misfit %.2e of the column, the theta "
      "point's matrix %.2e of h theta k away\n",
      found.worst, found.differs / scale);
  EXPECT_GT(found.differs, 0.1 * scale);  // a law of its own
}

// The jam (Model::link_jam_length; docs/models/dynamics.md, "Tension-only links: the jam"): links
// that jam at l_jam = 50 mm, s_j = l_jam − p = −14 mm (both parities).
constexpr double kJam = 0.05;

Model jamming(std::size_t nodes, double damping = kDamping) {
  Model m = tension_only(nodes, damping);
  m.link_jam_length = {kJam, kJam};
  return m;
}

// The law over the jam, at rates from fast shortening to fast lengthening: T ≤ 0 everywhere,
// T = E = 0 above the jam's ramp (slack), the bilateral law about l_jam, k (s − s_j) + c ṡ, beyond
// it where it pushes (0 where it would pull: a jammed link lengthening fast comes free), E =
// ½ k (s − s_j)² + k ε²/24 there, ∂T/∂s and ∂T/∂ṡ against central differences, T_e = dE/ds, and
// C¹ at the ramp's ends. Without the jam the same stretches are slack: T = E = 0.
TEST(DynamicsTensionOnlyLinks, JamPushesBelowItsLengthWithExactDerivativesAndEnergy) {
  const Model m = jamming(2);
  const double eps = m.link_smoothing, k = kStiffness, sj = kJam - kPitch;
  int jammed = 0, ramp = 0, slack = 0, clamped = 0;
  for (int i = -300; i <= 300; ++i) {
    const double s = sj + i * 0.01 * eps + 0.003 * eps;  // off the ramp's ends by a little
    for (const double rate : {-0.5, -0.02, -1e-4, 0.0, 1e-4, 0.02, 0.5}) {
      const LinkForce f = link_force(m, s, rate);
      EXPECT_LE(f.tension, 0.0) << s << " " << rate;
      const double v = sj - s + 0.5 * eps;  // the ramp's depth
      if (v <= 0.0) {
        ++slack;
        EXPECT_EQ(f.tension, 0.0);
        EXPECT_EQ(f.energy, 0.0);
        EXPECT_EQ(f.stiffness, 0.0);
        EXPECT_EQ(f.damping, 0.0);
      } else if (v < eps) {
        ++ramp;
        EXPECT_LT(f.elastic, 0.0);
        EXPECT_GT(f.elastic, -k * eps / 2 * (1 + 1e-9));
      } else {
        ++jammed;
        EXPECT_NEAR(f.elastic, k * (s - sj), 1e-9 * k * eps);
        EXPECT_NEAR(f.tension, std::min(0.0, k * (s - sj) + kDamping * rate), 1e-9 * k * eps);
        EXPECT_NEAR(f.energy, 0.5 * k * (s - sj) * (s - sj) + k * eps * eps / 24, 1e-9 * f.energy);
      }
      if (f.tension == 0.0 && f.elastic < 0.0) ++clamped;
      const double ds = 1e-4 * eps, dr = 1e-7;
      const LinkForce sp = link_force(m, s + ds, rate), sm = link_force(m, s - ds, rate);
      const LinkForce rp = link_force(m, s, rate + dr), rm = link_force(m, s, rate - dr);
      const double scale = k + kDamping * std::abs(rate) / eps;
      if ((sp.tension < 0.0) == (sm.tension < 0.0) && (sp.tension < 0.0) == (f.tension < 0.0)) {
        EXPECT_NEAR(f.stiffness, (sp.tension - sm.tension) / (2 * ds), 1e-6 * scale)
            << s << " " << rate;
      }
      if ((rp.tension < 0.0) == (rm.tension < 0.0) && (rp.tension < 0.0) == (f.tension < 0.0)) {
        EXPECT_NEAR(f.damping, (rp.tension - rm.tension) / (2 * dr), 1e-6 * kDamping)
            << s << " " << rate;
      }
      EXPECT_NEAR(f.elastic, (sp.energy - sm.energy) / (2 * ds), 1e-6 * k * eps) << s;
      const LinkForce none = link_force(tension_only(2), s, rate);  // no jam: slack
      EXPECT_EQ(none.tension, 0.0);
      EXPECT_EQ(none.energy, 0.0);
    }
  }
  // C¹ at both ends of the ramp (v = 0 and v = ε): T_e, its slope and E meet
  for (const double v : {0.0, eps}) {
    const double s = sj + 0.5 * eps - v, d = 1e-9 * eps;
    const LinkForce lo = link_force(m, s - d, 0.0), hi = link_force(m, s + d, 0.0);
    EXPECT_NEAR(lo.elastic, hi.elastic, 1e-6 * k * eps);
    EXPECT_NEAR(lo.stiffness, hi.stiffness, 1e-6 * k);
    EXPECT_NEAR(lo.energy, hi.energy, 1e-6 * k * eps * eps);
  }
  EXPECT_GT(jammed, 1000);
  EXPECT_GT(ramp, 500);
  EXPECT_GT(slack, 1000);
  EXPECT_GT(clamped, 50);  // lengthening fast out of the jam: free, the spring still pressed
}

// Each link jams at its parity's l_jam (Model::jam_length): with alternation (rest lengths
// p + a, p − a, p + a; l_jam 70 mm for the even links, 18 mm for the odd) link 0 is 5 µm inside
// its jam, link 1 in its jam's ramp and link 2 slack (between its jam and its rest length, but
// well inside the odd links' rest length). The tensions, each node's force from them against
// −∂E/∂q of energy(), and against the integrator's residual at rest (−h × the force: the inertia's
// part is 0 at the predictor).
TEST(DynamicsTensionOnlyLinks, EachLinkJamsAtItsParitysLengthAndItsForceIsTheEnergysGradient) {
  Model m = tension_only(4);
  m.alternation = 0.018;
  m.link_jam_length = {0.070, 0.018};
  ASSERT_TRUE(validate(m).empty());
  const double eps = m.link_smoothing;
  const double len[3] = {0.070 - 5e-6, 0.018 - 0.2 * eps, 0.076};
  const double ang[3] = {0.1, -0.3, 0.7};
  State s = three_link_chain(len, ang);
  std::vector<double> t(3);
  link_tensions(m, s, t);
  EXPECT_NEAR(t[0], -kStiffness * 5e-6, 1e-6);                 // −500 N
  EXPECT_NEAR(t[1], -kStiffness * 0.7 * 0.7 * eps / 2, 1e-6);  // v = 0.7 ε: −24.5 N
  EXPECT_EQ(t[2], 0.0);
  const double h = 1e-5;
  expect_rest_residual_is_minus_the_energys_gradient(m, s, t, ang, h);
  std::vector<double> u(8), r;
  // With Model::links_discrete_gradient (θ = ½), one step with u ≠ x: link 0 going 0.5 µm deeper
  // into its jam, link 1 deeper into its jam's ramp, link 2 slack, each turning by 0.01 rad. The
  // start's velocities carry the nodes to u (the inertia's part of the residual is 0), so −r/h is
  // the links' force: each link's link_step_force(…, j) along d_θ/l_θ. Link 1 pushes: with link
  // 0's jam (70 mm, of an 82 mm link) it would push by 1.6 MN, without one not at all.
  m.links_discrete_gradient = true;
  const double len1[3] = {len[0] - 0.5e-6, len[1] - 0.4 * eps, len[2] + 1e-4};
  double step[3], dtx[3], dty[3], ltheta[3];
  for (std::size_t i = 0; i < 4; ++i) {
    double x = 0.0, y = 0.0;
    for (std::size_t j = 0; j < i; ++j) {
      x += len1[j] * std::cos(ang[j] + 0.01);
      y += len1[j] * std::sin(ang[j] + 0.01);
    }
    u[2 * i] = x, u[2 * i + 1] = y;
    s.vx[i] = (x - s.x[i]) / h, s.vy[i] = (y - s.y[i]) / h;
  }
  for (std::size_t j = 0; j < 3; ++j) {
    const double d0x = s.x[j + 1] - s.x[j], d0y = s.y[j + 1] - s.y[j];
    const double d1x = u[2 * j + 2] - u[2 * j], d1y = u[2 * j + 3] - u[2 * j + 1];
    const double l0 = std::sqrt(d0x * d0x + d0y * d0y), l1 = std::sqrt(d1x * d1x + d1y * d1y);
    step[j] = link_step_force(m, l0 - m.rest_length(j), l1 - m.rest_length(j), h, j).tension;
    dtx[j] = 0.5 * (d0x + d1x), dty[j] = 0.5 * (d0y + d1y), ltheta[j] = 0.5 * (l0 + l1);
  }
  EXPECT_LT(step[0], -500.0);
  EXPECT_LT(step[1], -24.5);  // deeper than the θ point's v = 0.7 ε, and its damper pushing
  EXPECT_EQ(step[2], 0.0);
  Integrator gradient(m, {.step = h, .theta = 0.5});
  gradient.newton_system(m, s, u, r, nullptr);
  for (std::size_t i = 0; i < 4; ++i) {
    double f[2] = {0.0, 0.0};
    if (i < 3) f[0] += step[i] * dtx[i] / ltheta[i], f[1] += step[i] * dty[i] / ltheta[i];
    if (i > 0)
      f[0] -= step[i - 1] * dtx[i - 1] / ltheta[i - 1],
          f[1] -= step[i - 1] * dty[i - 1] / ltheta[i - 1];
    for (int axis = 0; axis < 2; ++axis)
      EXPECT_NEAR(-r[2 * i + axis] / h, f[axis], 1e-9 * kStiffness * eps)
          << "discrete gradient " << i << " " << axis;
  }
}

// The step's start as the integrator keeps it (link_step_start, once a step for each link) gives
// link_step_force's result bit for bit, over steps of an odd link (jam d = 18 mm on a 46 mm link,
// damped) entering its jam's ramp, crossing it, leaving it, going deeper, inside it, from beyond
// it, beyond it deeper and beyond it lengthening slowly. The start is the link's own: with link
// 0's (no jam: E(s₀) = C(v₀) = 0) or without the jam's damper C(v₀) every step within the jam
// changes; and beyond the ramp T is the closed form k (s̄ − s_j) + c (s₁ − s₀)/h (the
// quotient of ½ k (s − s_j)², the damper c ṡ over the step), which a start of the wrong link or
// without C(v₀) misses by far.
TEST(DynamicsTensionOnlyLinks, LinkStepStartIsItsOwnLinksAndCarriesTheJamsDamper) {
  Model m = tension_only(3);
  m.alternation = 0.018;
  m.link_jam_length = {0.0, 0.018};
  ASSERT_TRUE(validate(m).empty());
  const double eps = m.link_smoothing, h = 1e-5, k = kStiffness;
  const double sj = m.jam_length(1) - m.rest_length(1);  // −28 mm
  const double x[][2] = {{0.8, 0.1},   {0.8, -1.4},  {-0.3, 0.9},  {-0.1, -2.0},
                         {0.3, -0.35}, {-3.0, -0.2}, {-3.0, -4.0}, {-10.0, -9.5}};
  int within = 0, beyond = 0;
  for (const auto& c : x) {
    const double s0 = sj + c[0] * eps, s1 = sj + c[1] * eps;
    const LinkStep plain = link_step_force(m, s0, s1, h, 1);
    const LinkStep kept = link_step_force(m, s0, s1, h, 1, link_step_start(m, s0, 1));
    EXPECT_EQ(kept.tension, plain.tension) << c[0] << " " << c[1];
    EXPECT_EQ(kept.elastic, plain.elastic) << c[0] << " " << c[1];
    EXPECT_EQ(kept.slope, plain.slope) << c[0] << " " << c[1];
    // a step within the jam: v₀ > 0 and v₁ > 0 (leaving it, the start's E(s₀) and C(v₀) are
    // all of T, clamped at 0 with either start)
    if (sj - s0 + 0.5 * eps > 0.0 && sj - s1 + 0.5 * eps > 0.0) {
      ++within;
      const LinkStep other = link_step_force(m, s0, s1, h, 1, link_step_start(m, s0, 0));
      LinkStart undamped = link_step_start(m, s0, 1);
      EXPECT_GT(undamped.jam_damper, 0.0);
      undamped.jam_damper = 0.0;
      const LinkStep dropped = link_step_force(m, s0, s1, h, 1, undamped);
      EXPECT_GT(std::abs(other.tension - plain.tension), 1.0) << c[0] << " " << c[1];
      EXPECT_GT(std::abs(dropped.tension - plain.tension), 1.0) << c[0] << " " << c[1];
    }
    if (c[0] <= -1.5 && c[1] <= -1.5) {  // both ends beyond the ramp (v ≥ ε)
      ++beyond;
      const double closed = k * (0.5 * (s0 + s1) - sj) + kDamping * (s1 - s0) / h;
      EXPECT_NEAR(plain.tension, closed, 1e-9 * k * eps) << c[0] << " " << c[1];
      EXPECT_NEAR(plain.slope, 0.5 * k + kDamping / h, 1e-9 * k) << c[0] << " " << c[1];
    }
  }
  EXPECT_EQ(within, 5);
  EXPECT_EQ(beyond, 2);
}

// The integrator's Newton matrix against central differences of its residual with jammed links:
// at the θ point (θ = 0.6, h = 10 µs) a link 20 µm inside its jam, one in the jam's ramp, one 6 µm
// inside but lengthening at 0.5 m/s (c ṡ = 1000 N against its push: free by the clamp) and a slack
// one; with Model::links_discrete_gradient (θ = ½) over steps deeper into the jam, from slack into
// its ramp, within it lengthening slowly, out of the jam so fast that the damper over the step
// clamps T at 0 (c/h = 2e8 N/m > k), and slack.
TEST(DynamicsTensionOnlyLinks, NewtonMatrixWithJammedLinksMatchesTheResidualsDifferences) {
  const double eps = 1e-6, h = 1e-5;
  {
    const Model m = jamming(5);
    const double th = 0.6;
    State s(5, 0);
    const double len[4] = {kJam - 20e-6, kJam + 0.1 * eps, kJam - 6e-6, kJam + 3e-6};
    const double ang[4] = {0.2, -0.4, 0.5, 1.1};
    const double rate[4] = {-1e-3, 1e-4, 0.5, 0.0};
    for (std::size_t j = 0; j < 4; ++j) {
      s.x[j + 1] = s.x[j] + len[j] * std::cos(ang[j]);
      s.y[j + 1] = s.y[j] + len[j] * std::sin(ang[j]);
      s.vx[j + 1] = s.vx[j] + rate[j] * std::cos(ang[j]) - 0.3 * std::sin(ang[j]);
      s.vy[j + 1] = s.vy[j] + rate[j] * std::sin(ang[j]) + 0.3 * std::cos(ang[j]);
    }
    std::vector<double> t(4);
    link_tensions(m, s, t);
    EXPECT_LT(t[0], -1000.0);
    EXPECT_LT(t[1], 0.0);
    EXPECT_EQ(t[2], 0.0);
    EXPECT_EQ(t[3], 0.0);
    Integrator integ(m, {.step = h, .theta = th});
    std::vector<double> u(integ.unknowns()), r, jac;
    for (std::size_t i = 0; i < 5; ++i) {
      u[2 * i] = s.x[i] + h * s.vx[i];
      u[2 * i + 1] = s.y[i] + h * s.vy[i];
    }
    integ.newton_system(m, s, u, r, &jac);
    const testing::ColumnsAgainstDifferences found = testing::expect_columns_match_differences(
        integ, m, s, u, jac, {}, [](std::size_t) { return 1e-11; }, 1e-6);
    std::printf("jammed links' Newton matrix (theta point): largest misfit %.2e of the column\n",
                found.worst);
  }
  {
    Model m = jamming(6);
    m.links_discrete_gradient = true;
    const double sj = kJam - kPitch;
    const double s0[5] = {sj - 20e-6, sj + 0.8 * eps, sj - 0.1 * eps, sj - 6e-6, sj + 3e-6};
    const double s1[5] = {sj - 20.5e-6, sj + 0.2 * eps, sj - 0.09 * eps, sj - 3e-6, sj + 2.5e-6};
    const double a0[5] = {0.2, -0.4, 0.5, 1.1, -0.9}, turn = 0.01;
    State s(6, 0);
    std::vector<double> u(12);
    five_link_step(s0, s1, a0, turn, s, u);
    for (std::size_t j = 0; j < 5; ++j) {
      const LinkStep law = link_step_force(m, s0[j], s1[j], h);
      if (j < 3) {
        EXPECT_LT(law.tension, 0.0) << j;
      } else if (j == 3) {
        EXPECT_LT(law.elastic, -100.0);
        EXPECT_EQ(law.tension, 0.0);
      } else {
        EXPECT_EQ(law.elastic, 0.0);
      }
    }
    Integrator integ(m, {.step = h, .theta = 0.5});
    std::vector<double> r, jac;
    integ.newton_system(m, s, u, r, &jac);
    const testing::ColumnsAgainstDifferences found = testing::expect_columns_match_differences(
        integ, m, s, u, jac, {}, [](std::size_t) { return 1e-11; }, 1e-6);
    std::printf("jammed links' Newton matrix (discrete gradient): largest misfit %.2e\n",
                found.worst);
  }
}

// Two free nodes on one link jamming at 50 mm, thrown together at 1 m/s each from just slack (as
// NodesPushedTogetherFeelNoForce, where without a jam they pass through each other): 7 ms later
// the joints reach l_jam, the link pushes them apart (undamped: up to 2 √(k m/2) = 9.2 kN) and
// they fly apart at their speeds reversed, never closer than the jam less the push's depth
// (2/√(2k/m) = 92 µm). At the θ point and with the discrete gradient: the energy kept to Newton's
// tolerance with the discrete gradient, within 1 % at the θ point (its steps into and out of the
// jam are not a discrete gradient).
TEST(DynamicsTensionOnlyLinks, NodesThrownTogetherBounceOffTheJam) {
  for (const bool gradient : {false, true}) {
    Model m = jamming(2, 0.0);
    m.links_discrete_gradient = gradient;
    State s(2, 0);
    s.x[1] = kPitch - 1e-6;
    s.vx[0] = 1.0;
    s.vx[1] = -1.0;
    const double e0 = energy(m, s).total();
    Integrator integ(m, {.step = 1e-5, .tolerance = 1e-13, .theta = 0.5});
    std::vector<double> t(1);
    double lowest = 0.0, shortest = INFINITY;
    for (int k = 0; k < 1000; ++k) {  // 10 ms
      ASSERT_TRUE(integ.step(m, s).converged) << k;
      link_tensions(m, s, t);
      lowest = std::min(lowest, t[0]);
      shortest = std::min(shortest, s.x[1] - s.x[0]);
    }
    const double de = energy(m, s).total() - e0;
    std::printf(
        "thrown together (%s): v %.9f %.9f m/s, lowest tension %.1f N, shortest l - l_jam "
        "%.2f um, dE %.2e J of %.3f J\n",
        gradient ? "discrete gradient" : "theta point", s.vx[0], s.vx[1], lowest,
        (shortest - kJam) * 1e6, de, e0);
    EXPECT_LT(lowest, -8000.0);
    EXPECT_GT(shortest, kJam - 100e-6);
    EXPECT_LT(shortest, kJam - 80e-6);
    // the θ point's steps into and out of the jam (20 µm each, the ramp 1 µm) are not a discrete
    // gradient: they lose 0.75 % of the energy here
    EXPECT_NEAR(s.vx[0], -1.0, gradient ? 1e-8 : 1e-2);
    EXPECT_NEAR(s.vx[1], 1.0, gradient ? 1e-8 : 1e-2);
    EXPECT_GT(s.x[1] - s.x[0], kJam);  // apart again
    EXPECT_NEAR(de, 0.0, (gradient ? 1e-10 : 1e-2) * e0);
  }
}

// One step at θ = ½ through the integrator's residual, as
// OneStepsWorkIsMinusTheEnergysChangeWithTheDiscreteGradient, across the jam (s = s_j + x ε):
// with Model::links_discrete_gradient the link's work is −(E(s₁) − E(s₀)) to rounding on steps
// entering the jam's ramp from slack, crossing it, leaving it to slack, going deeper, inside it,
// coming up into it from beyond, beyond it, and a step of 0.01 ε across its inner end (the
// threshold's scale from s_j: from s, 1.4e-8 m, the mean's force would miss the quotient by
// k Δs²/24ε); the θ point's force misses.
TEST(DynamicsTensionOnlyLinks, OneStepsWorkAcrossTheJamIsMinusTheEnergysChange) {
  const double eps = 1e-6, h = 1e-5;
  struct Case {
    const char* name;
    double x0, x1;  // [ε] the stretches' offsets from s_j
  };
  const Case cases[] = {{"entering", 0.8, 0.1},  {"crossing", 0.8, -1.4},
                        {"leaving", -0.3, 0.9},  {"deeper", -0.1, -2.0},
                        {"inside", 0.3, -0.35},  {"from beyond", -3.0, -0.2},
                        {"beyond", -2.0, -40.0}, {"short", -0.496, -0.506}};
  for (const Case& c : cases) {
    double misfit[2] = {0.0, 0.0};
    double de = 0.0, rounding = 0.0;
    for (const bool gradient : {false, true}) {
      Model m = uniform_chain(2, false, kPitch, 1e-12, kStiffness, 0.0, false);
      m.links_carry_compression = false;
      m.link_jam_length = {kJam, kJam};
      m.links_discrete_gradient = gradient;
      const LinkStepWork step = one_link_step(m, kJam + c.x0 * eps, kJam + c.x1 * eps, h);
      // E at the lengths of the step's ends as newton_system takes them (hypot, sqrt)
      const double e0 = link_force(m, step.length0 - kPitch, 0.0).energy;
      const double e1 = link_force(m, step.length1 - kPitch, 0.0).energy;
      de = e1 - e0;
      misfit[gradient] = step.work + de;
      if (gradient) rounding = 1e-14 * step.terms;
    }
    std::printf("jam %-12s dE %+.6e J: work + dE %+.2e J (theta point %+.2e J; rounding %.1e J)\n",
                c.name, de, misfit[1], misfit[0], rounding);
    // the jam's energy, not 0 (without the jam every one of these stretches is slack)
    EXPECT_GT(std::abs(de), 1e-9 * kStiffness * eps * eps) << c.name;
    EXPECT_LT(std::abs(misfit[1]), rounding) << c.name;
    if (std::string(c.name) != "beyond") {
      EXPECT_GT(std::abs(misfit[0]), 1e-6 * std::abs(de)) << c.name;
    }
  }
}

// Hinge friction takes the links' bilateral tension: with tension-only links it is refused, and
// a bad ε is named.
TEST(DynamicsTensionOnlyLinks, BadFieldsAreNamed) {
  Model m = tension_only(3);
  m.link_smoothing = -1e-6;
  m.hinge.arm = 1e-3;
  const std::vector<Issue> issues = validate(m);
  auto named = [&](const char* field) {
    return std::any_of(issues.begin(), issues.end(),
                       [&](const Issue& i) { return i.field == field; });
  };
  EXPECT_TRUE(named("link_smoothing"));
  EXPECT_TRUE(named("links_carry_compression"));
  EXPECT_FALSE(named("links_discrete_gradient"));
  m.links_carry_compression = true;  // the bilateral links take neither
  m.hinge.arm = 0.0;
  EXPECT_TRUE(validate(m).empty());
  m.links_discrete_gradient = true;  // nor the discrete gradient (theirs at θ = ½ already)
  EXPECT_EQ(validate(m).size(), 1u);
  EXPECT_EQ(validate(m)[0].field, "links_discrete_gradient");
}

// A jam length is 0 (none) or in (0, rest length − ε] of its parity's links (its ramp below the
// tension's), named with its index; the bilateral links take none.
TEST(DynamicsTensionOnlyLinks, BadJamLengthsAreNamed) {
  Model m = tension_only(3);
  m.alternation = 0.018;  // rest lengths 82 and 46 mm
  const double eps = m.link_smoothing;
  auto fields = [&] {
    std::vector<std::string> out;
    for (const Issue& i : validate(m)) out.push_back(i.field);
    return out;
  };
  using V = std::vector<std::string>;
  m.link_jam_length = {0.082 - eps, 0.018};  // the even links' largest: ramps touching
  EXPECT_EQ(fields(), V{});
  m.link_jam_length = {0.082 - 0.5 * eps, -0.018};
  EXPECT_EQ(fields(), (V{"link_jam_length[0]", "link_jam_length[1]"}));
  m.link_jam_length = {NAN, 0.050};  // the odd links' above their rest length
  EXPECT_EQ(fields(), (V{"link_jam_length[0]", "link_jam_length[1]"}));
  m.link_jam_length = {0.0, INFINITY};
  EXPECT_EQ(fields(), V{"link_jam_length[1]"});
  m.link_jam_length = {0.0, 0.018};
  m.links_carry_compression = true;  // a bilateral link pushes already
  EXPECT_EQ(fields(), V{"link_jam_length[1]"});
  // a bad ε is named alone: the jam's bound (rest length − ε) is not read with it
  m.links_carry_compression = false;
  m.link_smoothing = NAN;
  EXPECT_EQ(fields(), V{"link_smoothing"});
}

// The flat links (Model::link_bilateral; docs/models/dynamics.md, "Tension-only links: the jam",
// "The flat links"): the even links bilateral, the odd tension-only with their jam (a round-link
// chain on a pocket wheel: rest lengths p ± a, a = 18 mm, the odd links jamming at 18 mm).
Model flat_links(std::size_t nodes, double damping = kDamping) {
  Model m = tension_only(nodes, damping);
  m.alternation = 0.018;
  m.link_jam_length = {0.0, 0.018};
  m.link_bilateral = {true, false};
  return m;
}

// The flagged even link is the bilateral law at every stretch and rate — T = k s + c ṡ, pushing
// in compression with k through s = 0 (no ε ramp), E = ½ k s² — while the odd link's law is the
// unflagged model's bit for bit (slack, its tension ramp, taut, its jam's ramp and the jam), as
// is link_step_force's over steps of the odd link; the even link's step force is the quotient of
// ½ k s², k (s₀ + s₁)/2 + c (s₁ − s₀)/h, with the slope ½ k + c/h.
TEST(DynamicsTensionOnlyLinks, FlatLinksAreBilateralAndTheOddLinksUnchanged) {
  const Model m = flat_links(3);
  ASSERT_TRUE(validate(m).empty());
  Model plain = m;
  plain.link_bilateral = {false, false};
  const double eps = m.link_smoothing, k = kStiffness, c = kDamping, h = 1e-5;
  const double sj = m.jam_length(1) - m.rest_length(1);  // the odd links' jam, −28 mm
  int pushes = 0;
  for (int i = -300; i <= 300; ++i) {
    for (const double base : {0.0, sj}) {
      const double s = base + i * 0.01 * eps + 0.003 * eps;
      for (const double rate : {-0.5, -0.02, 0.0, 0.02, 0.5}) {
        const LinkForce even = link_force(m, s, rate, 0);
        EXPECT_EQ(even.tension, k * s + c * rate) << s << " " << rate;
        EXPECT_EQ(even.elastic, k * s);
        EXPECT_EQ(even.stiffness, k);
        EXPECT_EQ(even.damping, c);
        EXPECT_EQ(even.energy, 0.5 * k * s * s);
        if (even.tension < 0.0) ++pushes;
        const LinkForce odd = link_force(m, s, rate, 1), before = link_force(plain, s, rate, 1);
        EXPECT_EQ(odd.tension, before.tension) << s << " " << rate;
        EXPECT_EQ(odd.elastic, before.elastic);
        EXPECT_EQ(odd.stiffness, before.stiffness);
        EXPECT_EQ(odd.damping, before.damping);
        EXPECT_EQ(odd.energy, before.energy);
      }
      const double s1 = s - 0.37 * eps;
      const LinkStep even = link_step_force(m, s, s1, h, 0);
      EXPECT_NEAR(even.elastic, 0.5 * k * (s + s1), 1e-12 * k * std::max(std::abs(s), eps));
      EXPECT_NEAR(even.tension, even.elastic + c * (s1 - s) / h, 1e-12 * k * eps);
      EXPECT_EQ(even.slope, 0.5 * k + c / h);
      const LinkStep odd = link_step_force(m, s, s1, h, 1),
                     before = link_step_force(plain, s, s1, h, 1);
      EXPECT_EQ(odd.tension, before.tension) << s;
      EXPECT_EQ(odd.elastic, before.elastic);
      EXPECT_EQ(odd.slope, before.slope);
    }
  }
  EXPECT_GT(pushes, 1000);  // the even link in compression (tension-only: none)
}

// A flagged parity takes no jam (a bilateral link pushes already), named with its index; the
// flag is harmless with links_carry_compression (every link bilateral already).
TEST(DynamicsTensionOnlyLinks, FlatLinksTakeNoJam) {
  Model m = flat_links(3);
  auto fields = [&] {
    std::vector<std::string> out;
    for (const Issue& i : validate(m)) out.push_back(i.field);
    return out;
  };
  using V = std::vector<std::string>;
  m.link_jam_length = {0.070, 0.018};  // valid for tension-only even links
  ASSERT_EQ(fields(), V{"link_jam_length[0]"});
  EXPECT_NE(validate(m)[0].expected.find("link_bilateral[0]"), std::string::npos);
  m.link_bilateral = {true, true};
  EXPECT_EQ(fields(), (V{"link_jam_length[0]", "link_jam_length[1]"}));
  m.link_jam_length = {0.0, 0.0};
  EXPECT_EQ(fields(), V{});
  m.links_carry_compression = true;
  EXPECT_EQ(fields(), V{});
  for (const double s : {-3e-6, 0.0, 5e-6}) {
    Model bilateral = m;
    bilateral.link_bilateral = {false, false};
    EXPECT_EQ(link_force(m, s, 0.1, 1).tension, link_force(bilateral, s, 0.1, 1).tension);
  }
}

// On a 4-node chain at rest, the flagged even links 0 and 2 pushing 5 µm short and pulling
// 3 µm long, the odd link 1 in its jam's ramp: the tensions, each node's force from them against
// −∂E/∂q of energy(), and against the integrator's residual at rest (−h × the force).
TEST(DynamicsTensionOnlyLinks, FlatLinksForceIsMinusTheEnergysGradient) {
  const Model m = flat_links(4);
  const double eps = m.link_smoothing;
  const double len[3] = {0.082 - 5e-6, 0.018 - 0.2 * eps, 0.082 + 3e-6};
  const double ang[3] = {0.1, -0.3, 0.7};
  const State s = three_link_chain(len, ang);
  std::vector<double> t(3);
  link_tensions(m, s, t);
  EXPECT_NEAR(t[0], -kStiffness * 5e-6, 1e-6);  // −500 N: the flat link pushes
  EXPECT_NEAR(t[1], -kStiffness * 0.7 * 0.7 * eps / 2, 1e-6);
  EXPECT_NEAR(t[2], kStiffness * 3e-6, 1e-6);  // 300 N: k s, no ramp's k ε²/24 offset in E
  EXPECT_NEAR(
      energy(m, s).elastic,
      0.5 * kStiffness * (25e-12 + 9e-12) + link_force(m, 0.018 - 0.2 * eps - 0.046, 0.0, 1).energy,
      1e-12);
  expect_rest_residual_is_minus_the_energys_gradient(m, s, t, ang, 1e-5);
}

// The integrator's Newton matrix with flat links against central differences of its residual:
// the even links 0, 2, 4 pushing (3 µm short, 20 µm short and shortening at 0.5 m/s, and crossing
// s = 0), the odd links slack and taut; at the θ point (θ = 0.6) and with
// Model::links_discrete_gradient (θ = ½).
TEST(DynamicsTensionOnlyLinks, NewtonMatrixWithFlatLinksMatchesTheResidualsDifferences) {
  const double eps = 1e-6, h = 1e-5;
  for (const bool gradient : {false, true}) {
    Model m = flat_links(6);
    m.alternation = 0.0;  // (five_link_step's links are kPitch + s long)
    m.link_jam_length = {0.0, 0.0};
    m.links_discrete_gradient = gradient;
    ASSERT_TRUE(validate(m).empty());
    const double s0[5] = {-3e-6, -2e-6, -20e-6, 6e-6, 0.3 * eps};
    const double s1[5] = {-3.5e-6, -2.5e-6, -25e-6, 6.5e-6, -0.4 * eps};
    const double a0[5] = {0.2, -0.4, 0.5, 1.1, -0.9}, turn = 0.01;
    State s(6, 0);
    std::vector<double> u(12);
    five_link_step(s0, s1, a0, turn, s, u);
    for (std::size_t j = 0; j < 5; ++j) {
      const LinkStep law = link_step_force(m, s0[j], s1[j], h, j);
      if (j == 0 || j == 2) {
        EXPECT_LT(law.tension, -100.0) << j;  // the flat links push
      } else if (j == 1) {
        EXPECT_EQ(law.tension, 0.0);  // slack
      }
    }
    Integrator integ(m, {.step = h, .theta = gradient ? 0.5 : 0.6});
    std::vector<double> r, jac;
    integ.newton_system(m, s, u, r, &jac);
    const testing::ColumnsAgainstDifferences found = testing::expect_columns_match_differences(
        integ, m, s, u, jac, {}, [](std::size_t) { return 1e-11; }, 1e-6);
    std::printf("flat links' Newton matrix (%s): largest misfit %.2e of the column\n",
                gradient ? "discrete gradient" : "theta point", found.worst);
  }
}

// One step at θ = ½ through the integrator's residual (as
// OneStepsWorkIsMinusTheEnergysChangeWithTheDiscreteGradient) of a flagged even link, undamped,
// with Model::links_discrete_gradient: its work is −(E(s₁) − E(s₀)) to rounding with E = ½ k s²
// (the bilateral link's, no ramp) on steps in compression, across s = 0 either way, through the
// tension-only law's ramp and in tension.
TEST(DynamicsTensionOnlyLinks, OneStepsWorkOfAFlatLinkIsMinusTheEnergysChange) {
  const double eps = 1e-6, h = 1e-5, k = kStiffness;
  struct Case {
    const char* name;
    double s0, s1;  // [m]
  };
  const Case cases[] = {{"compressed", -3e-6, -5e-6},
                        {"opening", -5e-6, 4e-6},
                        {"closing", 2e-6, -6e-6},
                        {"in the ramp", -0.3 * eps, 0.2 * eps},
                        {"stretched", 20e-6, 22e-6}};
  for (const Case& c : cases) {
    Model m = uniform_chain(2, false, kPitch, 1e-12, kStiffness, 0.0, false);
    m.links_carry_compression = false;
    m.link_bilateral = {true, false};
    m.links_discrete_gradient = true;
    const LinkStepWork step = one_link_step(m, kPitch + c.s0, kPitch + c.s1, h);
    const double e0 = link_force(m, step.length0 - kPitch, 0.0).energy;
    const double e1 = link_force(m, step.length1 - kPitch, 0.0).energy;
    const double de = e1 - e0;
    EXPECT_NEAR(de, 0.5 * k * (c.s1 * c.s1 - c.s0 * c.s0), 1e-6 * std::abs(de)) << c.name;
    // the sum's rounding, and the lengths' (each a few ulp of the pitch, times the force)
    const double rounding =
        1e-14 * step.terms + 1e-15 * kPitch * k * std::max(std::abs(c.s0), std::abs(c.s1));
    std::printf("flat link %-12s dE %+.6e J: work + dE %+.2e J (rounding %.1e J)\n", c.name, de,
                step.work + de, rounding);
    EXPECT_LT(std::abs(step.work + de), rounding) << c.name;
  }
}

}  // namespace
}  // namespace catena::dynamics
