// Properties of the energy-conserving midpoint integrator: exact conservation laws, discrete
// dissipation, the order of convergence, pinned nodes, input validation.
#include "catena/dynamics/integrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

// A closed loop of n links on a circle whose circumference is slightly longer than n pitches
// (so the links start stretched), spinning, with a random velocity perturbation.
State spinning_loop(const Model& m, double omega, double perturbation, unsigned seed) {
  const std::size_t n = m.nodes();
  const double radius = 1.001 * m.pitch / (2.0 * std::sin(kPi / static_cast<double>(n)));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  State s(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(n);
    s.x[i] = radius * std::cos(a);
    s.y[i] = radius * std::sin(a);
    s.vx[i] = -omega * s.y[i] + perturbation * u(rng);
    s.vy[i] = omega * s.x[i] + perturbation * u(rng);
  }
  return s;
}

// An open chain pinned at node 0, held out horizontally, released under gravity.
State horizontal(const Model& m) {
  State s(m.nodes());
  for (std::size_t i = 0; i < m.nodes(); ++i) s.x[i] = m.pitch * static_cast<double>(i);
  return s;
}

Model pendulum_chain(std::size_t links, double k, double c) {
  Model m = uniform_chain(links + 1, false, 0.05, 0.1, k, c, false);
  m.pinned.assign(links + 1, 0);
  m.pinned[0] = 1;
  m.gravity_y = -9.81;
  return m;
}

TEST(DynamicsIntegrator, FreeLoopConservesMomentumAndEnergy) {
  Model m = uniform_chain(40, true, 0.02, 0.03, 2e6, 0.0, false);
  State s = spinning_loop(m, 30.0, 0.5, 1);
  Integrator integ(m, {.step = 1e-3});
  auto momentum = [&](const State& st, double& px, double& py, double& lz) {
    px = py = lz = 0.0;
    for (std::size_t i = 0; i < st.nodes(); ++i) {
      px += m.mass[i] * st.vx[i];
      py += m.mass[i] * st.vy[i];
      lz += m.mass[i] * (st.x[i] * st.vy[i] - st.y[i] * st.vx[i]);
    }
  };
  double px0, py0, lz0, px, py, lz;
  momentum(s, px0, py0, lz0);
  const double e0 = energy(m, s).total();
  for (int i = 0; i < 500; ++i) ASSERT_TRUE(integ.step(m, s).converged);
  momentum(s, px, py, lz);
  const double e1 = energy(m, s).total();
  const double p_scale = 0.03 * 40 * 0.5;  // Σ m |perturbation|
  EXPECT_NEAR(px, px0, 1e-9 * p_scale);
  EXPECT_NEAR(py, py0, 1e-9 * p_scale);
  EXPECT_NEAR(lz, lz0, 1e-9 * std::abs(lz0));
  EXPECT_NEAR(e1, e0, 1e-8 * e0);
}

// The damper's discrete dissipation c (l₁ − l₀)²/h and the drag make the energy fall every step.
TEST(DynamicsIntegrator, DampingDissipatesEveryStep) {
  Model m = pendulum_chain(12, 1e5, 5.0);
  m.drag = 0.2;
  State s = horizontal(m);
  Integrator integ(m, {.step = 2e-3});
  double e_prev = energy(m, s).total();
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(integ.step(m, s).converged);
    const double e = energy(m, s).total();
    ASSERT_LE(e, e_prev + 1e-12 * std::abs(e_prev)) << "step " << i;
    e_prev = e;
  }
}

// The step's reported dissipation, against closed forms from the states before and after: at
// θ = ½ the dampers' −Σ c (l₁ − l₀)²/h and the drag's −Σ α m |x₁ − x₀|²/h, and they close the
// step's energy balance (no contact: the rest is the Newton tolerance). At θ = 0.7 the dampers'
// work is −Σ c (l₁ − l₀)/h · [l̄ (l₁ − l₀) + (θ − ½)|d₁ − d₀|²]/l_θ, and the balance leaves the
// θ-method's own loss, which is < 0.
TEST(DynamicsIntegrator, StepReportsItsDissipation) {
  for (const double theta : {0.5, 0.7}) {
    Model m = pendulum_chain(12, 1e5, 5.0);
    m.drag = 0.2;
    State s = horizontal(m);
    Integrator integ(m, {.step = 2e-3, .theta = theta});
    double numerical = 0.0, dissipated = 0.0;
    for (int i = 0; i < 200; ++i) {
      const State s0 = s;
      const double e0 = energy(m, s).total();
      const StepReport r = integ.step(m, s);
      ASSERT_TRUE(r.converged);
      double dampers = 0.0, drag = 0.0;
      for (std::size_t j = 0; j + 1 < m.nodes(); ++j) {
        const double d0x = s0.x[j + 1] - s0.x[j], d0y = s0.y[j + 1] - s0.y[j];
        const double d1x = s.x[j + 1] - s.x[j], d1y = s.y[j + 1] - s.y[j];
        const double l0 = std::hypot(d0x, d0y), l1 = std::hypot(d1x, d1y);
        const double dd2 = (d1x - d0x) * (d1x - d0x) + (d1y - d0y) * (d1y - d0y);
        const double lt = (1.0 - theta) * l0 + theta * l1;
        dampers -= m.axial_damping * (l1 - l0) / 2e-3 *
                   (0.5 * (l0 + l1) * (l1 - l0) + (theta - 0.5) * dd2) / lt;
      }
      for (std::size_t i2 = 0; i2 < m.nodes(); ++i2) {
        const double dx = s.x[i2] - s0.x[i2], dy = s.y[i2] - s0.y[i2];
        drag -= m.drag * m.mass[i2] * (dx * dx + dy * dy) / 2e-3;
      }
      const double scale = std::abs(dampers) + std::abs(drag) + 1e-12;
      ASSERT_NEAR(r.damper_work, dampers, 1e-6 * scale) << "theta " << theta << " step " << i;
      ASSERT_NEAR(r.drag_work, drag, 1e-6 * scale) << "theta " << theta << " step " << i;
      EXPECT_EQ(r.contact_damping_work, 0.0);
      EXPECT_EQ(r.friction_work, 0.0);
      numerical += energy(m, s).total() - e0 - r.damper_work - r.drag_work;
      dissipated += r.damper_work + r.drag_work;
    }
    EXPECT_NEAR(s.damper_work + s.drag_work, dissipated, 1e-12 * std::abs(dissipated));
    EXPECT_LT(dissipated, 0.0);
    if (theta == 0.5) {
      EXPECT_LT(std::abs(numerical), 1e-6 * std::abs(dissipated));
    } else {
      EXPECT_LT(numerical, -1e-3 * std::abs(dissipated));
    }
  }
}

// Validation (7): the midpoint rule is second order. With the axial modes resolved, the change
// of the free end's position when the step is halved falls by 4 (2² ) each halving.
TEST(DynamicsIntegrator, SecondOrderConvergence) {
  const Model m = pendulum_chain(8, 2e3, 0.0);
  auto end_at = [&](double h) {
    State s = horizontal(m);
    Integrator integ(m, {.step = h, .tolerance = 1e-13});
    const int steps = static_cast<int>(std::lround(0.4 / h));
    for (int i = 0; i < steps; ++i) EXPECT_TRUE(integ.step(m, s).converged);
    return std::pair{s.x.back(), s.y.back()};
  };
  const auto a = end_at(2e-3), b = end_at(1e-3), c = end_at(5e-4), d = end_at(2.5e-4);
  auto dist = [](auto p, auto q) { return std::hypot(p.first - q.first, p.second - q.second); };
  const double r1 = dist(a, b) / dist(b, c), r2 = dist(b, c) / dist(c, d);
  EXPECT_GT(dist(a, b), 1e-6);  // the steps do change the result
  EXPECT_NEAR(r1, 4.0, 0.6);
  EXPECT_NEAR(r2, 4.0, 0.4);
}

// Stable at steps set by accuracy, not by k: the highest axial mode here has ω = √(4k/m) = 4e4
// rad/s, and an explicit method needs h < 2/ω = 5e-5 s; the step is 40 times that. An arch of 30
// links between two pins collapses under gravity and swings through (nodes move up to about a
// tenth of a pitch per step: the step is set by the motion).
TEST(DynamicsIntegrator, StableFarBeyondTheExplicitLimit) {
  constexpr std::size_t kLinks = 30;
  Model m = uniform_chain(kLinks + 1, false, 0.05, 0.1, 4e7, 0.0, true);
  m.gravity_y = -9.81;
  State s(m.nodes());
  // a half-circle arch of radius R: n links of chord p span the angle π, R = p / (2 sin(π/2n))
  const double radius = m.pitch / (2.0 * std::sin(kPi / (2.0 * kLinks)));
  for (std::size_t i = 0; i <= kLinks; ++i) {
    const double a = kPi * static_cast<double>(i) / static_cast<double>(kLinks);
    s.x[i] = -radius * std::cos(a);
    s.y[i] = radius * std::sin(a);
  }
  s.y.front() = s.y.back() = 0.0;
  Integrator integ(m, {.step = 2e-3});
  const double e0 = energy(m, s).total();
  double kinetic_max = 0.0;
  for (int i = 0; i < 1500; ++i) {
    const StepReport r = integ.step(m, s);
    ASSERT_TRUE(r.converged) << "step " << i << " iterations " << r.iterations;
    kinetic_max = std::max(kinetic_max, energy(m, s).kinetic);
  }
  EXPECT_GT(kinetic_max, 1.0);  // it fell: m g R ≈ 3 kg · 9.81 m/s² · 0.48 m
  EXPECT_NEAR(energy(m, s).total(), e0, 1e-6 * kinetic_max);
  // No link blew up: a stretch can hold at most all the energy, ½ k δ² ≤ E_kin,max + m g R.
  const double stretch_max = std::sqrt(2.0 * (kinetic_max + 3.1 * 9.81 * radius) / 4e7);
  for (std::size_t j = 0; j < m.links(); ++j) {
    const double l = std::hypot(s.x[j + 1] - s.x[j], s.y[j + 1] - s.y[j]);
    EXPECT_NEAR(l, m.pitch, stretch_max);
  }
}

TEST(DynamicsIntegrator, PinnedNodesStayPut) {
  Model m = uniform_chain(20, false, 0.02, 0.03, 1e6, 1.0, true);
  m.gravity_y = -9.81;
  State s(m.nodes());
  for (std::size_t i = 0; i < s.nodes(); ++i) s.x[i] = 0.02 * static_cast<double>(i);
  Integrator integ(m, {.step = 1e-3});
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(integ.step(m, s).converged);
  EXPECT_EQ(s.x.front(), 0.0);
  EXPECT_EQ(s.y.front(), 0.0);
  EXPECT_EQ(s.x.back(), 0.02 * 19);
  EXPECT_EQ(s.y.back(), 0.0);
  EXPECT_LT(s.y[10], -1e-4);  // the middle has fallen, stretching the links
}

// A constant force on the free end of a chain pinned at node 0 (NodeLoad): settled, every link
// carries the force (statics, independent of the integrator); undamped at θ = ½, the energy
// with the load's potential −f·x is conserved as the chain swings.
TEST(DynamicsIntegrator, NodeLoadTensionsTheChainAndHasAPotential) {
  const std::size_t n = 12;
  Model m = uniform_chain(n, false, 0.02, 0.03, 1e6, 5.0, false);
  m.pinned.assign(n, 0);
  m.pinned[0] = 1;
  m.drag = 50.0;
  const double fx = 300.0, fy = 400.0;  // 500 N at 53° to the chain's start
  m.loads = {{.node = n - 1, .fx = fx, .fy = fy}};
  State s = horizontal(m);
  Integrator settle(m, {.step = 1e-3, .theta = 0.6});
  for (int i = 0; i < 3000; ++i) ASSERT_TRUE(settle.step(m, s).converged) << i;
  std::vector<double> tension(m.links());
  link_tensions(m, s, tension);
  for (double t : tension) EXPECT_NEAR(t / 500.0, 1.0, 1e-6);
  const double dx = s.x[n - 1] - s.x[0], dy = s.y[n - 1] - s.y[0];
  EXPECT_NEAR(std::atan2(dy, dx), std::atan2(fy, fx), 1e-6);  // a straight line along the force

  Model free = m;
  free.drag = 0.0;
  free.axial_damping = 0.0;
  State swing = horizontal(free);
  Integrator integ(free, {.step = 2e-4});
  const double e0 = energy(free, swing).total();
  double largest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    ASSERT_TRUE(integ.step(free, swing).converged) << i;
    largest = std::max(largest, energy(free, swing).kinetic);
  }
  EXPECT_GT(largest, 1.0);  // it swung
  EXPECT_NEAR(energy(free, swing).total() - e0, 0.0, 1e-8 * largest);

  Model bad = m;
  bad.loads = {{.node = n, .fx = NAN, .fy = 0.0}};
  std::vector<std::string> fields;
  for (const Issue& i : validate(bad)) fields.push_back(i.field);
  for (const char* f : {"load[0].node", "load[0].force"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
}

TEST(DynamicsIntegrator, InvalidInputListsEveryProblem) {
  Model m = uniform_chain(2, true, -1.0, 0.0, 0.0, -1.0, false);
  m.drag = NAN;
  try {
    Integrator integ(m, {.step = 0.0, .max_iterations = 0});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    std::vector<std::string> fields;
    for (const Issue& i : e.issues()) fields.push_back(i.field);
    for (const char* f : {"nodes", "pitch", "axial_stiffness", "axial_damping", "drag", "mass[0]",
                          "step", "max_iterations"}) {
      EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
    }
  }
  Model ok = uniform_chain(5, false, 0.02, 0.03, 1e6, 0.0, true);
  State s(4);
  EXPECT_FALSE(validate(ok, s).empty());
  Integrator integ(ok, {});
  EXPECT_THROW(integ.step(ok, s), InputError);  // a state of the wrong size
  Model other = uniform_chain(6, false, 0.02, 0.03, 1e6, 0.0, true);
  State s6(6);
  EXPECT_THROW(integ.step(other, s6), InputError);  // another model
  // hinge friction switched on after the build (its arrays were not made): refused, both ways
  Model hinged = ok;
  hinged.hinge = {.arm = 1e-4, .rate_band = 5.0};
  State s5 = horizontal(ok);
  try {
    integ.step(hinged, s5);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_FALSE(e.issues().empty());
    EXPECT_EQ(e.issues()[0].field, "model.hinge");
  }
  Integrator with_hinges(hinged, {});
  EXPECT_THROW(with_hinges.step(ok, s5), InputError);
  State t(5);  // all nodes at the origin: links of zero length
  EXPECT_FALSE(validate(ok, t).empty());
}

}  // namespace
}  // namespace catena::dynamics
