// The hinges' stick law (HingeFriction::stick_stiffness; docs/models/dynamics.md, "Hinges:
// sticking"): the couple's torque and Jacobian, a loaded hinge holding under a torque below its
// friction torque (against the regularised law's creep) and sliding at it above, the work balance
// with the stick springs' energy, and the step's Newton matrix against differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "catena/dynamics/integrator.hpp"
#include "dense_solve.hpp"
#include "residual_difference.hpp"
#include "two_wheel_loops.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPitch = 0.01905, kStiffness = 5e7, kArm = 2.86e-4;  // 12B, μ 0.1 on d2 5.72 mm

// β at nodes a, b, c: the angle of link (b → c) less that of link (a → b).
double relative_angle(double ax, double ay, double bx, double by, double cx, double cy) {
  const double ux = bx - ax, uy = by - ay, vx = cx - bx, vy = cy - by;
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

// The couple's torque by the stick law: −k_t (d₀ + θ Δβ) − c_t Δβ/h while within e F, e F
// against it beyond, on three nodes of a hinge loaded by stretched links.
TEST(HingeStick, TorqueIsTheSpringsWithinTheFrictionTorqueAndCoulombsBeyond) {
  const double h = 1e-4, theta = 0.6, kt = 40.0, ct = 0.05;
  HingeFriction hinge{.arm = kArm, .rate_band = 5.0};
  hinge.stick_stiffness = kt;
  hinge.stick_damping = ct;
  // links stretched by 1e-5 m (F = 500 N), the last node moved across by 0.2 µm over the step
  const double l = kPitch + 1e-5;
  const double x0[3] = {-l, 0.0, l}, y0[3] = {0.0, 0.0, 0.0};
  const double x1[3] = {-l, 0.0, l}, y1[3] = {0.0, 0.0, 2e-7};
  int sticking = 0, sliding = 0;
  for (double d0 : {0.0, 1e-3, -2e-3, 5e-3, -9e-3, 2e-2}) {
    const HingeCouple hc = hinge_couple(hinge, kStiffness, kPitch, x0, y0, x1, y1, theta, h, 1, d0);
    EXPECT_NEAR(hc.load, kStiffness * 1e-5, 1e-6 * kStiffness * 1e-5);
    const double limit = kArm * hc.load;  // e F
    const double spring = -kt * (d0 + theta * hc.turn) - ct * hc.turn / h;
    if (std::abs(spring) <= limit) {
      ++sticking;
      EXPECT_TRUE(hc.sticking) << d0;
      EXPECT_NEAR(hc.torque, spring, 1e-12 * limit) << d0;
      EXPECT_NEAR(hc.rate_stiffness, kt * theta * h + ct, 1e-15) << d0;
    } else {
      ++sliding;
      EXPECT_FALSE(hc.sticking) << d0;
      EXPECT_NEAR(hc.torque, std::copysign(limit, spring), 1e-12 * limit) << d0;
      EXPECT_EQ(hc.rate_stiffness, 0.0) << d0;
    }
    EXPECT_NEAR(hc.work, hc.torque * hc.turn, 1e-18);
  }
  EXPECT_GE(sticking, 2);
  EXPECT_GE(sliding, 2);
  // without the stick law the same pose gives the regularised torque, ≠ the spring's
  hinge.stick_stiffness = 0.0;
  hinge.stick_damping = 0.0;
  const HingeCouple free =
      hinge_couple(hinge, kStiffness, kPitch, x0, y0, x1, y1, theta, h, 1, 1e-3);
  const double limit = kArm * free.load;
  EXPECT_NEAR(free.torque, -limit * free.rate / std::hypot(free.rate, 5.0), 1e-12 * limit);
  EXPECT_FALSE(free.sticking);
}

// The stick law's Jacobian against central differences of f = M g in the six end-of-step
// coordinates, sticking and sliding poses, θ = ½ and 0.6, both pin loads.
TEST(HingeStick, JacobianIsTheForcesDerivativeStickingAndSliding) {
  const double h = 1e-4;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), turn(-0.6, 0.6), d(-2e-6, 2e-6),
      defl(-4e-3, 4e-3);
  int sticking = 0, sliding = 0;
  for (int trial = 0; trial < 160; ++trial) {
    HingeFriction hinge{
        .arm = kArm, .rate_band = 5.0, .pin_load = trial % 2 ? PinLoad::kPinLink : PinLoad::kMean};
    hinge.stick_stiffness = 50.0;
    hinge.stick_damping = trial % 4 < 2 ? 0.0 : 0.02;
    const double theta = trial % 3 ? 0.6 : 0.5;
    const std::size_t node = static_cast<std::size_t>(trial % 5);
    const double d0 = defl(rng);
    // three nodes a stretched pitch apart (tension ≈ 500 N) at random angles, a small step
    double x0[3], y0[3], x1[3], y1[3];
    const double a = angle(rng), b = a + turn(rng), l = kPitch * 1.0005;
    x0[0] = 0.0, y0[0] = 0.0;
    x0[1] = l * std::cos(a), y0[1] = l * std::sin(a);
    x0[2] = x0[1] + l * std::cos(b), y0[2] = y0[1] + l * std::sin(b);
    for (int k = 0; k < 3; ++k) x1[k] = x0[k] + d(rng), y1[k] = y0[k] + d(rng);
    const HingeCouple hc =
        hinge_couple(hinge, kStiffness, kPitch, x0, y0, x1, y1, theta, h, node, d0);
    // away from the switch (the differences must not straddle it)
    const double spring =
        -hinge.stick_stiffness * (d0 + theta * hc.turn) - hinge.stick_damping * hc.turn / h;
    if (std::abs(std::abs(spring) - kArm * hc.load) < 1e-3 * kArm * hc.load) continue;
    (hc.sticking ? sticking : sliding) += 1;
    double scale = 0.0;
    for (const auto& row : hc.jacobian)
      for (double v : row) scale = std::max(scale, std::abs(v));
    double worst = 0.0;
    for (int q = 0; q < 6; ++q) {
      const double du = 1e-10;
      double xp[3], yp[3], xm[3], ym[3];
      for (int k = 0; k < 3; ++k) xp[k] = xm[k] = x1[k], yp[k] = ym[k] = y1[k];
      (q % 2 == 0 ? xp : yp)[q / 2] += du;
      (q % 2 == 0 ? xm : ym)[q / 2] -= du;
      const HingeCouple p =
          hinge_couple(hinge, kStiffness, kPitch, x0, y0, xp, yp, theta, h, node, d0);
      const HingeCouple m =
          hinge_couple(hinge, kStiffness, kPitch, x0, y0, xm, ym, theta, h, node, d0);
      for (int r = 0; r < 6; ++r) {
        const double fp = r % 2 == 0 ? p.fx[r / 2] : p.fy[r / 2];
        const double fm = r % 2 == 0 ? m.fx[r / 2] : m.fy[r / 2];
        worst = std::max(worst, std::abs(hc.jacobian[r][q] - (fp - fm) / (2 * du)));
      }
    }
    EXPECT_LT(worst, 1e-5 * scale) << trial << (hc.sticking ? " sticking" : " sliding");
  }
  EXPECT_GT(sticking, 30);
  EXPECT_GT(sliding, 30);
}

// A hinge loaded by its pin: nodes 0 and 1 pinned with link 0 stretched to the tension `load`
// (the pin link at node 1, PinLoad::kPinLink: F = load exactly), node 2 (mass 1 kg) a pitch on,
// pushed across by a constant force giving the torque `torque` about node 1. The hinge at node 1
// takes it. θ = ½ (the balance exact but for Newton's tolerance).
struct Lever {
  Model model;
  State state;
};
Lever lever(double load, double torque, double kt, double ct) {
  Lever out;
  Model& m = out.model;
  m = uniform_chain(3, false, kPitch, 1.0, kStiffness, 0.0, false);
  m.pinned = {1, 1, 0};
  m.hinge = HingeFriction{.arm = kArm, .rate_band = 5.0, .pin_load = PinLoad::kPinLink};
  m.hinge.stick_stiffness = kt;
  m.hinge.stick_damping = ct;
  m.loads.push_back({.node = 2, .fx = 0.0, .fy = torque / kPitch});
  State& s = out.state;
  s = State(3, 0);
  s.x = {-(kPitch + load / kStiffness), 0.0, kPitch};
  s.y = {0.0, 0.0, 0.0};
  return out;
}

struct LeverRun {
  double angle_mid = 0.0, angle_end = 0.0, angle_max = 0.0;
  double hinge_work = 0.0, balance = 0.0;  // ΔE − W_loads − W_hinge (the loads' work in −ΔV)
  double slide_torque = 0.0;               // −hinge work / turn over the run's second half
  double spring_energy = 0.0;              // ½ k_t d² at the end (State::hinge_deflection)
};
LeverRun run_lever(Lever l, double duration) {
  Integrator integ(l.model, {.step = 1e-4, .tolerance = 1e-12, .theta = 0.5});
  const double e0 = energy(l.model, l.state).total();
  LeverRun out;
  const int steps = static_cast<int>(std::lround(duration / 1e-4));
  double work_half = 0.0, angle_half = 0.0;
  for (int k = 0; k < steps; ++k) {
    const StepReport r = integ.step(l.model, l.state);
    EXPECT_TRUE(r.converged) << k;
    if (!r.converged) break;
    const double beta = relative_angle(l.state.x[0], l.state.y[0], l.state.x[1], l.state.y[1],
                                       l.state.x[2], l.state.y[2]);
    out.angle_max = std::max(out.angle_max, std::abs(beta));
    if (k + 1 == steps / 2) {
      out.angle_mid = beta;
      work_half = l.state.hinge_work;
      angle_half = beta;
    }
    out.angle_end = beta;
  }
  out.hinge_work = l.state.hinge_work;
  for (const double d : l.state.hinge_deflection)
    out.spring_energy += 0.5 * l.model.hinge.stick_stiffness * d * d;
  out.balance = energy(l.model, l.state).total() - e0 - l.state.hinge_work - l.state.damper_work;
  out.slide_torque = -(l.state.hinge_work - work_half) / (out.angle_end - angle_half);
  return out;
}

// Below the friction torque (half of e F, F = 1 kN): the stick law holds the hinge at the
// spring's static deflection M/k_t (damped by c_t at half its critical value), with no creep;
// the regularised law creeps through the rate band at ω_ε r/√(1 − r²) (r = ½: 2.9 rad/s).
TEST(HingeStick, LoadedHingeHoldsBelowTheFrictionTorqueWhereTheRegularisedLawCreeps) {
  const double load = 1000.0, limit = kArm * load, torque = 0.5 * limit, kt = 50.0;
  const double ct = std::sqrt(kt * 1.0 * kPitch * kPitch);  // ½ of 2 √(k_t m p²)
  const double deflection = torque / kt;                    // 1.43 mrad
  const LeverRun held = run_lever(lever(load, torque, kt, ct), 0.2);
  const LeverRun crept = run_lever(lever(load, torque, 0.0, 0.0), 0.2);
  std::printf(
      "stick law: angle %.6e rad at 0.1 s, %.6e at 0.2 s (static deflection %.6e, max "
      "%.6e); regularised: %.6e at 0.1 s, %.6e at 0.2 s\n",
      held.angle_mid, held.angle_end, deflection, held.angle_max, crept.angle_mid, crept.angle_end);
  EXPECT_NEAR(held.angle_end, deflection, 1e-3 * deflection);
  EXPECT_LT(std::abs(held.angle_end - held.angle_mid), 1e-6 * deflection);  // no creep
  EXPECT_LT(held.angle_max, 1.5 * deflection);
  // the regularised law: past a hundred deflections in 0.2 s, still turning
  EXPECT_GT(crept.angle_end, 100.0 * deflection);
  EXPECT_GT(crept.angle_end - crept.angle_mid, 50.0 * deflection);
}

// Above the friction torque (1.5 e F): the stick law slides at Coulomb's torque e F (the hinge
// work over the turn, once the spring sits at its reach); the regularised law's torque is below
// it while the rate is within a few bands (here 4.6 % below).
TEST(HingeStick, LoadedHingeSlidesAtTheFrictionTorqueAboveIt) {
  const double load = 1000.0, limit = kArm * load, torque = 1.5 * limit, kt = 50.0;
  const LeverRun slid = run_lever(lever(load, torque, kt, 0.0), 0.04);
  const LeverRun band = run_lever(lever(load, torque, 0.0, 0.0), 0.04);
  std::printf(
      "sliding: torque %.6e N m (e F %.6e), turned %.4f rad; regularised %.6e N m, "
      "turned %.4f rad\n",
      slid.slide_torque, limit, slid.angle_end, band.slide_torque, band.angle_end);
  EXPECT_NEAR(slid.slide_torque, limit, 1e-6 * limit);
  EXPECT_GT(slid.angle_end, 0.1);
  EXPECT_LT(band.slide_torque, 0.99 * limit);
}

// The work balance: E₁ − E₀ = Σ hinge work (+ the links' dampers, none here) with the stick
// springs' ½ k_t d² in the energy, held (at θ = ½ without the damper: the spring rings, storing
// the load's work) and sliding (the spring at its reach, e F/k_t).
TEST(HingeStick, WorkBalanceClosesWithTheStickSpringsEnergy) {
  const double load = 1000.0, limit = kArm * load, kt = 50.0;
  for (double ratio : {0.5, 1.5}) {
    Lever l = lever(load, ratio * limit, kt, 0.0);
    const LeverRun run = run_lever(l, 0.04);
    // the load's work, ≈ M β at the largest turn, and the springs' energy at the end: what the
    // balance misses without it
    const double input = ratio * limit * run.angle_max;
    std::printf("ratio %.1f: hinge work %.6e J, spring energy %.6e J, balance %.3e J\n", ratio,
                run.hinge_work, run.spring_energy, run.balance);
    EXPECT_LT(std::abs(run.balance), 1e-6 * input) << ratio;
    EXPECT_GT(run.spring_energy, 1e-3 * input) << ratio;
    if (ratio < 1.0) {
      EXPECT_LT(std::abs(run.hinge_work), 1e-9 * input);  // sticking at θ = ½: no loss
    } else {
      EXPECT_NEAR(run.spring_energy, 0.5 * limit * limit / kt, 1e-9 * input);  // at its reach
      EXPECT_LT(run.hinge_work, -0.5 * input);
    }
  }
}

// A state of a model with the stick law and the iterate a step takes from it (the tests below)
struct SwitchCase {
  Model model;
  State state;
  std::vector<double> u;  // the iterate: x + h v, a driven wheel's ψ + h ω
};

constexpr double kSwitchStep = 1e-4, kSwitchTheta = 0.6;

// The unknowns at the constant-velocity predictor (newton_system's layout)
std::vector<double> predictor(const Model& m, const State& s) {
  std::vector<double> u;
  for (std::size_t i = 0; i < m.nodes(); ++i) {
    u.push_back(s.x[i] + kSwitchStep * s.vx[i]);
    u.push_back(s.y[i] + kSwitchStep * s.vy[i]);
  }
  for (std::size_t w = 0; w < m.sprockets.size(); ++w)
    if (!m.sprockets[w].driver) u.push_back(s.angle[w] + kSwitchStep * s.speed[w]);
  return u;
}

// A free 12-link loop, stretched 4e-4 and turning at 3 rad/s with a wobble
// (`open`: the same nodes as an open chain, node 0 pinned)
SwitchCase spinning_loop(bool open = false) {
  const std::size_t n = 12;
  SwitchCase c{uniform_chain(n, !open, kPitch, 0.02, kStiffness, 20.0, false), State(n, 0), {}};
  c.model.hinge = HingeFriction{.arm = kArm, .rate_band = 5.0};
  c.model.hinge.stick_stiffness = 30.0;
  c.model.hinge.stick_damping = 0.002;
  if (open) c.model.pinned.assign(n, 0), c.model.pinned[0] = 1;
  const double radius = kPitch / (2 * std::sin(M_PI / static_cast<double>(n))) * 1.0004;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    c.state.x[i] = radius * std::cos(a);
    c.state.y[i] = radius * std::sin(a);
    c.state.vx[i] = -3.0 * c.state.y[i] + (i % 2 ? 0.01 : -0.01) * std::cos(a);
    c.state.vy[i] = 3.0 * c.state.x[i] + (i % 2 ? 0.01 : -0.01) * std::sin(a);
  }
  if (open) c.state.vx[0] = c.state.vy[0] = 0.0;
  c.u = predictor(c.model, c.state);
  return c;
}

// The step's Newton matrix (Integrator::newton_system) with the stick law against central
// differences of its residual: a free 12-link loop spinning and wobbling, its hinges' deflections
// set so that some stick and some slide, at θ = 0.6 with the damper.
TEST(HingeStick, NewtonMatrixIsTheResidualsDerivative) {
  SwitchCase c = spinning_loop();
  const std::size_t n = c.model.nodes();
  const Model& m = c.model;
  State& s = c.state;
  const double h = kSwitchStep;
  Integrator integ(m, {.step = h, .theta = kSwitchTheta});
  // deflections: within the reach at every third hinge, far beyond it (both signs) at the others
  s.hinge_deflection.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    s.hinge_deflection[i] = i % 3 == 0 ? 1e-4 : (i % 3 == 1 ? 0.05 : -0.05);
  const std::vector<double>& u = c.u;
  // which hinges stick at this iterate (the couple of each, as the step's assembly takes it)
  int sticking = 0, sliding = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = (i + n - 1) % n, b = (i + 1) % n;
    const double x0[3] = {s.x[a], s.x[i], s.x[b]}, y0[3] = {s.y[a], s.y[i], s.y[b]};
    const double x1[3] = {u[2 * a], u[2 * i], u[2 * b]};
    const double y1[3] = {u[2 * a + 1], u[2 * i + 1], u[2 * b + 1]};
    const HingeCouple hc = hinge_couple(m.hinge, m.axial_stiffness, kPitch, x0, y0, x1, y1, 0.6, h,
                                        i, s.hinge_deflection[i]);
    (hc.sticking ? sticking : sliding) += 1;
  }
  EXPECT_EQ(sticking, 4);
  EXPECT_EQ(sliding, 8);
  std::vector<double> r0, jac, regularised;
  integ.newton_system(m, s, u, r0, &jac);
  Model plain = m;
  plain.hinge.stick_stiffness = 0.0;
  plain.hinge.stick_damping = 0.0;
  integ.newton_system(plain, s, u, r0, &regularised);
  const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
      integ, m, s, u, jac, regularised, [](std::size_t) { return 1e-10; }, 1e-5);
  std::printf(
      "stick law's Newton matrix: worst |J - FD| / column scale %.2e, differs from the "
      "regularised law's by %.2e of the largest\n",
      d.worst, d.differs / d.scale);
  EXPECT_GT(d.differs, 1e-4 * d.scale);
}

// The crossing cut (Integrator::step's line search with the stick law): a hinge that slid at a
// correction's start and slides the other way at its full step crossed its whole stick band, and
// Newton, free at both ends, cycles between the two slides; the cut lands it in its band. On the
// 200-link drive of the benchmarks (bench/dynamics_bench.cpp,
// BM_DynamicsTwoSprocketDriveHingeStick: μ = 0.1, k_t = 1e4 N·m/rad, ratio 4.2, θ = 0.6, h = 0.1
// ms), 300 steps from the seated start: the Newton iterations, factorisations and line-search
// points are counted (deterministic): 1976, 1509 and 694 with the cut; without it (the halvings
// alone) 2480, 1968 and 1868.
TEST(HingeStick, CrossingCutSavesNewtonIterationsOnTheDrive) {
  testing::Loop drive = testing::benchmark_drive(0.1 * 5.72e-3 / 2);
  drive.model.hinge.stick_stiffness = 1e4;
  Integrator integ(drive.model, {.step = 1e-4, .theta = 0.6});
  long iterations = 0, factorizations = 0, backtracks = 0, longest = 0;
  for (int k = 0; k < 300; ++k) {
    const StepReport r = integ.step(drive.model, drive.state);
    ASSERT_TRUE(r.converged) << "step " << k;
    iterations += r.iterations;
    factorizations += r.factorizations;
    backtracks += r.backtracks;
    longest = std::max<long>(longest, r.iterations);
  }
  std::printf(
      "300 steps: %ld Newton iterations (at most %ld a step), %ld factorisations, %ld "
      "line-search points\n",
      iterations, longest, factorizations, backtracks);
  EXPECT_LT(iterations, 2200);
  EXPECT_LT(factorizations, 1750);
  EXPECT_LT(backtracks, 1200);
}

// A stick–slip switch changes the step's Newton matrix by a rank-1 term: −h g ⊗ ΔM' on the
// hinge's three nodes (g = ∂β/∂x at the θ point, ΔM' the change of ∂M/∂x₁ between the two
// branches, hinge_branch_moment_gradient), which the chord iterations' update
// (Integrator::step) adds to their kept factors. The free 12-link loop of the test above; hinge
// 0's deflection set just inside its band (sticking, M = (1 − δ) e F) and just beyond it
// (sliding, M = e F), δ = 1e-9: the two dense Newton matrices (Integrator::newton_system) differ
// by that term, in every entry, to the direction term's δ e F |∂g/∂x| (and rounding).
TEST(HingeStick, SwitchChangesTheNewtonMatrixByTheRankOneTerm) {
  SwitchCase c = spinning_loop();
  const std::size_t n = c.model.nodes();
  const Model& m = c.model;
  State& s = c.state;
  const std::vector<double>& u = c.u;
  const double h = kSwitchStep, th = kSwitchTheta;
  Integrator integ(m, {.step = h, .theta = th});
  const std::size_t size = integ.unknowns();
  // hinge 0 between links 11 (node 11 → 0) and 0 (0 → 1): its trial at d₀ = 0, and e F
  const std::size_t ends[3] = {n - 1, 0, 1};
  HingeLink link[2];
  for (int e = 0; e < 2; ++e) {
    const std::size_t a = ends[e], b = ends[e + 1];
    const double d0x = s.x[b] - s.x[a], d0y = s.y[b] - s.y[a];
    const double d1x = u[2 * b] - u[2 * a], d1y = u[2 * b + 1] - u[2 * a + 1];
    hinge_link(d0x, d0y, d1x, d1y, std::hypot(d0x, d0y), std::hypot(d1x, d1y), kPitch, kStiffness,
               th, link[e], true);
  }
  HingeCouple hc;
  hinge_couple(m.hinge, link[0], link[1], h, hc, false, 0, th, 0.0);
  const double limit = m.hinge.arm * hc.load;
  ASSERT_GT(limit, 0.0);
  const double kt = m.hinge.stick_stiffness, delta = 1e-9;
  std::vector<double> r, inside, beyond;
  s.hinge_deflection.assign(n, 0.0);
  s.hinge_deflection[0] = (hc.trial - (1.0 - delta) * limit) / kt;  // trial (1 − δ) e F: sticks
  integ.newton_system(m, s, u, r, &inside);
  s.hinge_deflection[0] = (hc.trial - (1.0 + delta) * limit) / kt;  // (1 + δ) e F: slides
  integ.newton_system(m, s, u, r, &beyond);
  hinge_couple(m.hinge, link[0], link[1], h, hc, false, 0, th, s.hinge_deflection[0]);
  ASSERT_FALSE(hc.sticking);
  double stick_x[3], stick_y[3], slide_x[3], slide_y[3];
  hinge_branch_moment_gradient(m.hinge, link[0], link[1], h, 0, th, 0, stick_x, stick_y);
  hinge_branch_moment_gradient(m.hinge, link[0], link[1], h, 0, th, +1, slide_x, slide_y);
  std::vector<double> predicted(size * size, 0.0);
  for (int k = 0; k < 3; ++k) {
    for (int q = 0; q < 3; ++q) {
      const std::size_t row = 2 * ends[k], col = 2 * ends[q];
      const double dmx = stick_x[q] - slide_x[q], dmy = stick_y[q] - slide_y[q];
      predicted[row * size + col] = -h * hc.gx[k] * dmx;
      predicted[row * size + col + 1] = -h * hc.gx[k] * dmy;
      predicted[(row + 1) * size + col] = -h * hc.gy[k] * dmx;
      predicted[(row + 1) * size + col + 1] = -h * hc.gy[k] * dmy;
    }
  }
  double worst = 0.0, largest = 0.0, matrix = 0.0;
  for (std::size_t e = 0; e < size * size; ++e) {
    worst = std::max(worst, std::abs(inside[e] - beyond[e] - predicted[e]));
    largest = std::max(largest, std::abs(predicted[e]));
    matrix = std::max(matrix, std::abs(inside[e]));
  }
  std::printf(
      "switch at hinge 0: the matrices' difference against −h g ⊗ ΔM': worst %.2e of the "
      "term's largest entry %.3e (the matrix's largest %.3e)\n",
      worst / largest, largest, matrix);
  EXPECT_GT(largest, 1e-8 * matrix);  // the switch's term is not lost in the matrix's rounding
  EXPECT_LT(worst, 1e-6 * largest);
}

// The chord iterations' update across stick–slip switches (Integrator::step,
// IntegratorOptions::switch_update): the 200-link drive of the benchmarks at k_t = 100 and 1e3
// N·m/rad (ratios 0.042 and 0.42), 300 steps from the seated start with the update; each step is
// taken again from the same state by an integrator with the kept factors alone (as before the
// update), which has stepped along the same states, and by one at the tolerance 1e-13 p (the
// root): both ends are as far from the root (measured at most 3.3e-10 m with the update and
// 2.4e-10 m without over both k_t: the estimate stop's error, not the update's), and the update
// takes fewer factorisations and Newton iterations over the run.
TEST(HingeStick, SwitchUpdateKeepsTheFactorsAcrossStickSlipSwitches) {
  for (const double kt : {100.0, 1000.0}) {
    testing::Loop drive = testing::benchmark_drive(0.1 * 5.72e-3 / 2);
    drive.model.hinge.stick_stiffness = kt;
    Integrator a(drive.model, {.step = 1e-4, .tolerance = 1e-10, .theta = 0.6});
    Integrator b(drive.model,
                 {.step = 1e-4, .tolerance = 1e-10, .theta = 0.6, .switch_update = false});
    Integrator c(drive.model, {.step = 1e-4, .tolerance = 1e-13, .theta = 0.6});
    long fa = 0, fb = 0, ia = 0, ib = 0, updates = 0, builds = 0;
    double worst_a = 0.0, worst_b = 0.0;
    for (int k = 0; k < 300; ++k) {
      State again = drive.state, root = drive.state;
      const StepReport ra = a.step(drive.model, drive.state);
      const StepReport rb = b.step(drive.model, again);
      ASSERT_TRUE(ra.converged && rb.converged && c.step(drive.model, root).converged)
          << "step " << k;
      fa += ra.factorizations;
      updates += ra.switch_updates;
      builds += ra.switch_builds;
      fb += rb.factorizations;
      ia += ra.iterations;
      ib += rb.iterations;
      for (std::size_t i = 0; i < root.x.size(); ++i) {
        worst_a = std::max({worst_a, std::abs(drive.state.x[i] - root.x[i]),
                            std::abs(drive.state.y[i] - root.y[i])});
        worst_b =
            std::max({worst_b, std::abs(again.x[i] - root.x[i]), std::abs(again.y[i] - root.y[i])});
      }
    }
    std::printf(
        "k_t = %g: 300 steps with the update %ld factorisations, %ld Newton iterations; without "
        "%ld, %ld; a step's end from the root (tolerance 1e-13 p) at most %.2e m with the "
        "update, %.2e m without\n",
        kt, fa, ia, fb, ib, worst_a, worst_b);
    std::printf(
        "the update corrected %ld chord iterations; its W and I + Vᵀ W made %ld times (kept "
        "while the switched hinges and the factors stay)\n",
        updates, builds);
    // both within the same bound: 5e-10 m, about twice the kept factors' worst (2.4e-10 m)
    EXPECT_LT(worst_a, 5e-10) << kt;
    EXPECT_LT(worst_b, 5e-10) << kt;
    EXPECT_LT(static_cast<double>(fa), 0.9 * static_cast<double>(fb)) << kt;
    EXPECT_LT(ia, ib) << kt;
    // each change of the switched hinges makes them once (measured 166 of 475 and 245 of 393
    // updates); remaking them at every update would take at least one a correction
    EXPECT_LT(static_cast<double>(builds), 0.75 * static_cast<double>(updates)) << kt;
  }
}

// The chord iterations' update across switches as a solve (Integrator::chord_solve_after_switch):
// the Newton matrix factored at one state, the hinges' deflections then moved so that the chosen
// hinges sit just inside their band on one side (trial (1 − 1e-9) e F) and just beyond it on the
// other (1 + 1e-9, either way), the iterate unchanged, so that the two Newton matrices differ by
// the switches alone (and the direction term's 2e-9 e F |∂g/∂x|). The kept factors' solve,
// corrected, against a dense Gaussian elimination of the second state's Newton system
// (Integrator::newton_system): the chain's and the wheels' parts each to 1e-8 of their largest
// entry; the kept factors alone miss it by far more.
// The benchmarks' drive with the stick law (its driven wheel an unknown; `two_wheels`: the
// driver made a driven wheel of the same inertia, two unknowns)
SwitchCase stick_drive(bool two_wheels) {
  testing::Loop drive = testing::benchmark_drive(kArm);
  drive.model.hinge.stick_stiffness = 1000.0;
  if (two_wheels) {
    drive.model.sprockets[0].driver = false;
    drive.model.sprockets[0].inertia = drive.model.sprockets[1].inertia;
  }
  // 100 steps on, the wheels in contact (at the seated start none presses: no coupling)
  Integrator run(drive.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  for (int k = 0; k < 100; ++k) EXPECT_TRUE(run.step(drive.model, drive.state).converged);
  SwitchCase c{drive.model, drive.state, {}};
  c.u = predictor(c.model, c.state);
  return c;
}

// The deflection that puts hinge i's trial torque at the iterate at `ratio` × its limit e F
double deflection_at(const SwitchCase& c, std::size_t i, double ratio) {
  const Model& m = c.model;
  const std::size_t n = m.nodes();
  const std::size_t ends[3] = {(i + n - 1) % n, i, (i + 1) % n};
  HingeLink link[2];
  for (int e = 0; e < 2; ++e) {
    const std::size_t a = ends[e], b = ends[e + 1];
    const double d0x = c.state.x[b] - c.state.x[a], d0y = c.state.y[b] - c.state.y[a];
    const double d1x = c.u[2 * b] - c.u[2 * a], d1y = c.u[2 * b + 1] - c.u[2 * a + 1];
    hinge_link(d0x, d0y, d1x, d1y, std::hypot(d0x, d0y), std::hypot(d1x, d1y), m.rest_length(a),
               m.axial_stiffness, kSwitchTheta, link[e], true);
  }
  HingeCouple hc;
  hinge_couple(m.hinge, link[0], link[1], kSwitchStep, hc, false, i, kSwitchTheta, 0.0);
  const double limit = m.hinge.arm * hc.load;
  EXPECT_GT(limit, 0.0) << "hinge " << i << " unloaded";
  return (hc.trial - ratio * limit) / m.hinge.stick_stiffness;
}

constexpr double kIn = 1.0 - 1e-9, kOut = 1.0 + 1e-9;
struct Switch {
  std::size_t node;
  double kept, now;  // the trial's ratio to e F where the factors are taken, and after
};

struct SwitchSolves {
  std::vector<double> updated, plain, reference;
};

// max |δ − δ_ref| / max |δ_ref| over the entries [from, to)
double part_error(const std::vector<double>& d, const std::vector<double>& ref, std::size_t from,
                  std::size_t to) {
  double worst = 0.0, largest = 0.0;
  for (std::size_t k = from; k < to; ++k) {
    worst = std::max(worst, std::abs(d[k] - ref[k]));
    largest = std::max(largest, std::abs(ref[k]));
  }
  return worst / largest;
}

SwitchSolves solve_across(const SwitchCase& c, const std::vector<Switch>& switches) {
  const std::size_t n = c.model.nodes();
  State kept = c.state, now = c.state;
  if (c.state.hinge_deflection.size() != n) {
    kept.hinge_deflection.assign(n, 0.0);
    now.hinge_deflection.assign(n, 0.0);
  }
  for (const Switch& sw : switches) {
    kept.hinge_deflection[sw.node] = deflection_at(c, sw.node, sw.kept);
    now.hinge_deflection[sw.node] = deflection_at(c, sw.node, sw.now);
  }
  Integrator integ(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  SwitchSolves out;
  EXPECT_TRUE(integ.chord_solve_after_switch(c.model, kept, now, c.u, true, out.updated));
  EXPECT_TRUE(integ.chord_solve_after_switch(c.model, kept, now, c.u, false, out.plain));
  std::vector<double> r, j;
  integ.newton_system(c.model, now, c.u, r, &j);
  const std::size_t size = r.size();
  testing::Dense a(size, std::vector<double>(size));
  for (std::size_t row = 0; row < size; ++row) {
    for (std::size_t col = 0; col < size; ++col) a[row][col] = j[row * size + col];
    r[row] = -r[row];
  }
  out.reference = testing::dense_solve(a, r);
  return out;
}

// Asserts the corrected solve is the switched system's and the kept factors' alone is not
void expect_switched_solve(const SwitchCase& c, const std::vector<Switch>& switches,
                           const char* what) {
  const SwitchSolves s = solve_across(c, switches);
  const std::size_t nodes = 2 * c.model.nodes(), size = s.reference.size();
  const double chain = part_error(s.updated, s.reference, 0, nodes);
  const double chain_plain = part_error(s.plain, s.reference, 0, nodes);
  std::printf("%s: the chain's part %.2e (the kept factors alone %.2e)", what, chain, chain_plain);
  EXPECT_LT(chain, 1e-8) << what;
  EXPECT_GT(chain_plain, 1e-4) << what;
  if (size > nodes) {
    const double wheels = part_error(s.updated, s.reference, nodes, size);
    const double wheels_plain = part_error(s.plain, s.reference, nodes, size);
    std::printf(", the wheels' %.2e (%.2e)", wheels, wheels_plain);
    EXPECT_LT(wheels, 1e-8) << what;
    EXPECT_GT(wheels_plain, 1e-6) << what;
  }
  std::printf("\n");
  for (std::size_t i = 0; i < c.model.nodes(); ++i) {
    if (!c.model.is_pinned(i)) continue;
    EXPECT_EQ(s.updated[2 * i], 0.0) << what;
    EXPECT_EQ(s.updated[2 * i + 1], 0.0) << what;
  }
}

TEST(HingeStick, SwitchUpdateSolvesTheSwitchedNewtonSystem) {
  const SwitchCase loop = spinning_loop();
  expect_switched_solve(loop, {{0, kIn, kOut}}, "loop, stick to +slide");
  expect_switched_solve(loop, {{0, -kIn, -kOut}}, "loop, stick to -slide");
  expect_switched_solve(loop, {{0, kOut, kIn}}, "loop, +slide to stick");
  expect_switched_solve(loop, {{0, -kOut, -kIn}}, "loop, -slide to stick");
  expect_switched_solve(loop, {{3, -kIn, -kOut}, {4, kOut, kIn}}, "loop, 2 adjacent hinges");
  expect_switched_solve(loop, {{3, kIn, kOut}, {4, -kOut, -kIn}, {5, -kIn, -kOut}, {9, kOut, kIn}},
                        "loop, 4 hinges (3 adjacent)");
  SwitchCase pin_link = loop;
  pin_link.model.hinge.pin_load = PinLoad::kPinLink;
  expect_switched_solve(pin_link, {{4, -kIn, -kOut}, {7, kIn, kOut}},
                        "loop, PinLoad::kPinLink at an even and an odd node");
  expect_switched_solve(spinning_loop(true), {{1, -kIn, -kOut}, {2, kOut, kIn}},
                        "open chain, node 0 pinned");
  expect_switched_solve(stick_drive(false), {{100, -kIn, -kOut}, {101, kOut, kIn}},
                        "drive, its driven wheel an unknown");
  expect_switched_solve(stick_drive(true), {{100, kIn, kOut}, {150, -kOut, -kIn}},
                        "drive, both wheels unknowns");
}

// More than kMaxSwitches switched hinges: the kept factors' solve alone, bit for bit.
TEST(HingeStick, SwitchUpdateLeavesMoreThanFourSwitchesToTheKeptFactors) {
  const SwitchSolves s = solve_across(
      spinning_loop(),
      {{0, kIn, kOut}, {2, kIn, kOut}, {4, -kIn, -kOut}, {6, kOut, kIn}, {8, kIn, kOut}});
  EXPECT_EQ(s.updated, s.plain);
  EXPECT_GT(part_error(s.plain, s.reference, 0, s.reference.size()), 1e-4);
}

// The switch update's guard on I + Vᵀ W (SmallLu::factor, Integrator::kSwitchPivotFloor):
// constructed matrices, the size of their entries' terms given. A pivot at most 1e-12 of the
// terms is refused — one entry 1e-14 summed from terms of size 2 (1 and −1 + 1e-14: the
// switched Newton matrix singular to rounding), and a 2×2 whose second pivot is 1e-13 of its
// terms — and so are non-finite terms or entries; the same small entry summed from terms its
// own size, a 2×2 at 1e-10, and a 4×4 that needs row exchanges are factored, and solve as a
// dense elimination does.
TEST(HingeStick, SwitchUpdateGuardRefusesANearSingularMatrix) {
  constexpr double floor = Integrator::kSwitchPivotFloor;
  SmallLu one;
  one.lu[0][0] = 1e-14;
  EXPECT_FALSE(one.factor(1, 2.0, floor));
  one.lu[0][0] = 1e-14;
  EXPECT_TRUE(one.factor(1, 1e-14, floor));
  auto two = [](double d) {
    SmallLu m;
    m.lu[0][0] = 1.0, m.lu[0][1] = 1.0, m.lu[1][0] = 1.0, m.lu[1][1] = 1.0 + d;
    return m;
  };
  SmallLu near = two(1e-13), far = two(1e-10);
  EXPECT_FALSE(near.factor(2, 2.0 + 1e-13, floor));
  ASSERT_TRUE(far.factor(2, 2.0 + 1e-10, floor));
  double z[SmallLu::kMax] = {2.0, 2.0 + 1e-10};  // x = (1, 1)
  far.solve(z);
  EXPECT_NEAR(z[0], 1.0, 1e-5);
  EXPECT_NEAR(z[1], 1.0, 1e-5);
  SmallLu bad = two(1.0);
  EXPECT_FALSE(bad.factor(2, INFINITY, floor));
  bad = two(1.0);
  bad.lu[1][1] = NAN;
  EXPECT_FALSE(bad.factor(2, 3.0, floor));
  // 4×4, its first column's largest entry in the last row
  const testing::Dense a = {
      {0.1, 1.0, 0.2, 0.3}, {0.5, 0.2, 2.0, 0.1}, {0.3, 0.4, 0.1, 1.5}, {2.0, 0.3, 0.4, 0.2}};
  const std::vector<double> b = {1.0, -2.0, 0.5, 3.0};
  SmallLu four;
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t c = 0; c < 4; ++c) four.lu[k][c] = a[k][c];
  ASSERT_TRUE(four.factor(4, 3.0, floor));
  double y[SmallLu::kMax] = {b[0], b[1], b[2], b[3]};
  four.solve(y);
  const std::vector<double> x = testing::dense_solve(a, b);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(y[k], x[k], 1e-14 * std::abs(x[k])) << k;
}

// Hinge 0 sticking where the factors are kept (its deflection inside the band) and sliding forwards
// now, every other hinge undeflected: the kept and the current state of one switch.
std::pair<State, State> hinge0_switch(const SwitchCase& c) {
  State kept = c.state, now = c.state;
  kept.hinge_deflection.assign(c.model.nodes(), 0.0);
  now.hinge_deflection.assign(c.model.nodes(), 0.0);
  kept.hinge_deflection[0] = deflection_at(c, 0, kIn);
  now.hinge_deflection[0] = deflection_at(c, 0, kOut);
  return {kept, now};
}

// Where the guard refuses I + Vᵀ W, the chord iteration's correction is the kept factors'
// alone, bit for bit (the one a chord iteration without the update takes, and whose iterations
// converge: SwitchUpdateKeepsTheFactorsAcrossStickSlipSwitches). On the loop no switch makes
// I + Vᵀ W near-singular: hinge 0 from sticking to sliding either way, the others sticking or
// sliding, det(J_now)/det(J_kept) measured 0.74–1.0 at its k_t = 30 N·m/rad over arms from
// 2.86e-4 to 8.6e-3 m, and at k_t up to 3e4 N·m/rad smaller (about 0.01) but with the same
// zero, near e = 0.06 m, past the arm's bound p/2. So the guard is raised to 0.9 of the terms to
// make it act: the correction is then the kept factors' alone; at 0.5 it is the corrected one
// (the switched system's, SwitchUpdateSolvesTheSwitchedNewtonSystem).
TEST(HingeStick, SwitchUpdateLeavesANearSingularMatrixToTheKeptFactors) {
  const SwitchCase c = spinning_loop();
  const auto [kept, now] = hinge0_switch(c);
  Integrator integ(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  std::vector<double> plain, refused, corrected;
  ASSERT_TRUE(integ.chord_solve_after_switch(c.model, kept, now, c.u, false, plain));
  ASSERT_TRUE(integ.chord_solve_after_switch(c.model, kept, now, c.u, true, refused, 0.9));
  ASSERT_TRUE(integ.chord_solve_after_switch(c.model, kept, now, c.u, true, corrected, 0.5));
  EXPECT_EQ(refused, plain);
  EXPECT_GT(part_error(plain, corrected, 0, plain.size()), 1e-4);
}

// The update's parts are kept only with the factors they were made on (Integrator::factor clears
// them): a second chord_solve_after_switch on the same integrator, hinge 0's switch the same but
// the iterate moved (nodes 3 … n − 4 by up to 2e-4 m, so the factors differ), equals a fresh
// integrator's correction for that iterate bit for bit. Kept across the refactorisation, the
// first call's W and I + Vᵀ W would be used with the second's factors (measured: 1.2e-4 of the
// largest entry off, the update's change of the correction 7.2e-3).
TEST(HingeStick, SwitchUpdateIsMadeAfreshWithNewFactors) {
  const SwitchCase c = spinning_loop();
  const std::size_t n = c.model.nodes();
  const auto [kept, now] = hinge0_switch(c);
  std::vector<double> moved = c.u;
  for (std::size_t i = 3; i + 4 <= n; ++i) {
    moved[2 * i] += 2e-4 * std::sin(static_cast<double>(i));
    moved[2 * i + 1] += 2e-4 * std::cos(static_cast<double>(i));
  }
  Integrator reused(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  Integrator fresh(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  std::vector<double> first, second, alone, plain;
  ASSERT_TRUE(reused.chord_solve_after_switch(c.model, kept, now, c.u, true, first));
  ASSERT_TRUE(reused.chord_solve_after_switch(c.model, kept, now, moved, true, second));
  ASSERT_TRUE(fresh.chord_solve_after_switch(c.model, kept, now, moved, true, alone));
  ASSERT_TRUE(fresh.chord_solve_after_switch(c.model, kept, now, moved, false, plain));
  std::printf(
      "the second call's correction %.2e from a fresh integrator's; the update's change %.2e\n",
      part_error(second, alone, 0, alone.size()), part_error(plain, alone, 0, alone.size()));
  EXPECT_EQ(second, alone);
  // the case is one the update acts on, and the two iterates' corrections differ
  EXPECT_GT(part_error(plain, alone, 0, plain.size()), 1e-4);
  EXPECT_GT(part_error(first, alone, 0, alone.size()), 1e-4);
}

// On one factorisation (chord_solves_after_switch, a step's successive chord iterations), the
// update's parts are made afresh where a switched hinge's branch changes: hinge 0 sticking near
// its band's forward edge where the factors are taken, then sliding forwards, backwards, forwards
// again. Each forward slide's correction is its switched system's (a dense elimination of
// newton_system's, as SwitchUpdateSolvesTheSwitchedNewtonSystem), to 1e-8. The backward slide's
// system differs from the kept one by the rank-1 term and the direction term of the torque's jump
// 2 e F (not in the update: measured 8.5e-5 from the dense solve), so it is held to 1e-3 of it,
// and bit for bit to a fresh integrator's correction of that state alone. The forward slide's V
// reused for the backward slide would miss both.
TEST(HingeStick, SwitchUpdateIsMadeAfreshWhereTheBranchChanges) {
  const SwitchCase c = spinning_loop();
  const std::size_t n = c.model.nodes();
  State kept = c.state;
  kept.hinge_deflection.assign(n, 0.0);
  kept.hinge_deflection[0] = deflection_at(c, 0, kIn);
  std::vector<State> now(3, kept);
  now[0].hinge_deflection[0] = deflection_at(c, 0, kOut);
  now[1].hinge_deflection[0] = deflection_at(c, 0, -kOut);
  now[2].hinge_deflection[0] = deflection_at(c, 0, kOut);
  Integrator integ(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  std::vector<std::vector<double>> updated, plain;
  ASSERT_TRUE(integ.chord_solves_after_switch(c.model, kept, now, c.u, true, updated));
  ASSERT_TRUE(integ.chord_solves_after_switch(c.model, kept, now, c.u, false, plain));
  for (std::size_t k = 0; k < now.size(); ++k) {
    std::vector<double> r, j;
    integ.newton_system(c.model, now[k], c.u, r, &j);
    const std::size_t size = r.size();
    testing::Dense a(size, std::vector<double>(size));
    for (std::size_t row = 0; row < size; ++row) {
      for (std::size_t col = 0; col < size; ++col) a[row][col] = j[row * size + col];
      r[row] = -r[row];
    }
    const std::vector<double> reference = testing::dense_solve(a, r);
    const double error = part_error(updated[k], reference, 0, size);
    std::printf(
        "state %zu: the correction %.2e from the switched system's (the kept factors alone "
        "%.2e)\n",
        k, error, part_error(plain[k], reference, 0, size));
    EXPECT_LT(error, k == 1 ? 1e-3 : 1e-8) << k;
    EXPECT_GT(part_error(plain[k], reference, 0, size), 1e-2) << k;
  }
  Integrator fresh(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  std::vector<double> alone;
  ASSERT_TRUE(fresh.chord_solve_after_switch(c.model, kept, now[1], c.u, true, alone));
  EXPECT_EQ(updated[1], alone);
}

// A step's switch counts are summed over its starts, as its iterations are: the 200-link drive at
// k_t = 1e3 N·m/rad with at most 8 Newton iterations a start, 300 steps. Its restarted steps'
// first starts corrected chord iterations (measured: 1, 4 and 1 at steps 14, 160 and 269, their
// parts made 1, 1 and 1 times) where the second starts corrected none: counted only from the last
// start, the restarted steps would report no update.
TEST(HingeStick, SwitchCountsAreSummedOverTheStarts) {
  testing::Loop drive = testing::benchmark_drive(0.1 * 5.72e-3 / 2);
  drive.model.hinge.stick_stiffness = 1e3;
  Integrator integ(drive.model, {.step = 1e-4, .max_iterations = 8, .theta = 0.6});
  int restarted = 0, updates = 0, builds = 0;
  for (int k = 0; k < 300; ++k) {
    const StepReport r = integ.step(drive.model, drive.state);
    ASSERT_TRUE(r.converged) << k;
    if (r.starts == 1) continue;
    ++restarted;
    updates += r.switch_updates;
    builds += r.switch_builds;
  }
  std::printf("%d restarted steps: %d switch updates, %d builds\n", restarted, updates, builds);
  EXPECT_GE(updates, 6);
  EXPECT_GE(builds, 3);
}

// The update's guard's floor is a fraction of the terms: outside [0, 1) (or not a number) the
// verification entry point refuses it, naming it
TEST(HingeStick, SwitchUpdateRefusesAPivotFloorOutsideItsRange) {
  const SwitchCase c = spinning_loop();
  Integrator integ(c.model, {.step = kSwitchStep, .theta = kSwitchTheta});
  std::vector<double> delta;
  for (const double floor :
       {-1e-12, 1.0, static_cast<double>(NAN), static_cast<double>(INFINITY)}) {
    try {
      integ.chord_solve_after_switch(c.model, c.state, c.state, c.u, true, delta, floor);
      ADD_FAILURE() << floor << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("pivot_floor"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("[0, 1)"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(integ.chord_solve_after_switch(c.model, c.state, c.state, c.u, true, delta, 0.0));
}

// The last start from constant velocity with the halvings alone (Integrator::step) runs only
// where the crossing cut acted in the failed starts: otherwise it would repeat the second start
// from the same point with the same line search. The 200-link drive at k_t = 100 N·m/rad (ratio
// 0.04: no hinge crosses its whole band), 20 steps on, then one Newton iteration a start from a
// fresh integrator (no history: one start): the step fails from its one start, and no last start
// runs (the text names no starting points).
TEST(HingeStick, LastStartRunsOnlyWhereTheCrossingCutActed) {
  testing::Loop drive = testing::benchmark_drive(0.1 * 5.72e-3 / 2);
  drive.model.hinge.stick_stiffness = 100.0;
  Integrator integ(drive.model, {.step = 1e-4, .theta = 0.6});
  for (int k = 0; k < 20; ++k) integ.step(drive.model, drive.state);
  Integrator one(drive.model, {.step = 1e-4, .max_iterations = 1, .theta = 0.6});
  const StepReport first = one.step(drive.model, drive.state);
  ASSERT_FALSE(first.converged);
  EXPECT_EQ(first.starts, 1);
  EXPECT_EQ(newton_iterations_text(first, 1).find("starting points"), std::string::npos)
      << newton_iterations_text(first, 1);
}

// The last start converges a step the first two did not: the 200-link drive at k_t = 8e4 N·m/rad
// (ratio 33, past the warning at 14), h = 0.1 ms, from the seated start: its third step (index 2)
// converges only from the third start, after the crossing cut acted in the first two (measured:
// the only such step of the first five; the run stops at its sixth). Near the failure edge by
// design: if a change elsewhere moves it, re-measure rather than loosen it.
TEST(HingeStick, LastStartConvergesAStepTheCutDidNot) {
  testing::Loop drive = testing::benchmark_drive(0.1 * 5.72e-3 / 2);
  drive.model.hinge.stick_stiffness = 8e4;
  Integrator integ(drive.model, {.step = 1e-4, .theta = 0.6});
  for (int k = 0; k < 2; ++k) ASSERT_TRUE(integ.step(drive.model, drive.state).converged) << k;
  const StepReport third = integ.step(drive.model, drive.state);
  EXPECT_TRUE(third.converged);
  EXPECT_EQ(third.starts, 3);
}

TEST(HingeStick, InvalidLawListsEveryProblem) {
  HingeFriction hinge{.arm = kArm, .rate_band = 5.0};
  hinge.stick_stiffness = -1.0;
  hinge.stick_damping = NAN;
  std::vector<Issue> issues = validate(hinge, kPitch);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "hinge.stick_stiffness");
  EXPECT_EQ(issues[1].field, "hinge.stick_damping");
  // a spring on a frictionless hinge, a damper without the spring
  HingeFriction bare{.arm = 0.0, .rate_band = 5.0};
  bare.stick_stiffness = 10.0;
  issues = validate(bare, kPitch);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "hinge.stick_stiffness");
  HingeFriction damper{.arm = kArm, .rate_band = 5.0};
  damper.stick_damping = 0.1;
  issues = validate(damper, kPitch);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "hinge.stick_damping");
  damper.stick_stiffness = 10.0;
  EXPECT_TRUE(validate(damper, kPitch).empty());
}

}  // namespace
}  // namespace catena::dynamics
