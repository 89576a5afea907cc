// The ISO seats' line law (contact_law = "line"; docs/models/dynamics.md, "Contact law"): the
// roller's force Q(g) inverts Johnson's plane-strain approach δ(Q), written out here from its
// formula (not through the library); its tangent, its energy, the secant the linear default
// takes at the expected load, the Newton matrix with the law, and the energy of an undamped drop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "catena/dynamics/integrator.hpp"
#include "log_simpson.hpp"
#include "pressed_loop.hpp"
#include "residual_difference.hpp"

namespace catena::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;
// 12B (ISO 606): pitch, roller diameter d1, inner width b1; steel
constexpr double kPitch = 0.01905, kRoller = 0.01207, kWidth = 0.01168;
constexpr double kModulus = 210e9, kPoisson = 0.3;

Sprocket line_wheel(int z, double damping = 0.0) {
  Sprocket w = iso606_sprocket(kPitch, kRoller, kWidth, z, 0.0, 0.0, 2e8, damping);
  use_line_law(w, kWidth);
  return w;
}

// [m] δ(Q): Johnson's approach of the roller d1 in the concave seat ri = 0.505 d1 over b1
double johnson_approach(double load) {
  const double q = load / kWidth, ri = 0.505 * kRoller;
  const double rho = kRoller * ri / (2 * (ri - 0.5 * kRoller));
  const double e_star = kModulus / (2 * (1 - kPoisson * kPoisson));
  const double b = std::sqrt(4 * q * rho / (kPi * e_star));
  return q / kPi * 2 * (1 - kPoisson * kPoisson) / kModulus * (2 * std::log(2 * kRoller / b) - 1);
}

// The seat law's elastic part at penetration g, the roller at rest on a still wheel (no damping)
SeatContact law(const Sprocket& w, double g) {
  SeatContact c;
  c.nx = 0.0;
  c.ny = 1.0;
  apply_seat_law(w, g, 0.0, w.pitch_radius, 0.0, 0.0, 0.0, c);
  return c;
}

// ∫ Q dg' over [from, to] by Simpson's rule in s = ln g' (from g·1e-14: the rest is below 1e-28)
double quadrature(const Sprocket& w, double from, double to) {
  return testing::simpson_in_log(from, to, [&w](double g) { return law(w, g).force; });
}

// (1) The law against independent numerics: at 200 random loads over 1 N … 100 kN, the inverse
// gives back the load whose approach the formula gives, to 1e-12; within the cap (50 kN for 12B)
// the seat's force is that load, its stiffness the central difference of the force, its energy
// the quadrature of the force over g; beyond the cap the tangent there, C¹ and with its energy.
TEST(DynamicsSeatLineLaw, InverseTangentAndEnergyAgainstIndependentNumerics) {
  const Sprocket w = line_wheel(12);
  const double cap = kWidth * w.line.law.cap_load();
  EXPECT_GT(cap, 4e4);
  EXPECT_LT(cap, 6e4);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> decade(0.0, 5.0);
  int within = 0;
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double load = std::pow(10.0, decade(rng));
    const double g = johnson_approach(load);
    const double back = kWidth * w.line.law.load(g);
    worst = std::max(worst, std::abs(back / load - 1.0));
    EXPECT_NEAR(back / load, 1.0, 1e-12) << load;
    if (load >= 0.999 * cap) continue;
    ++within;
    const SeatContact c = law(w, g);
    EXPECT_NEAR(c.force / load, 1.0, 1e-12) << load;
    const double d = 1e-5 * g;
    const double slope = (law(w, g + d).force - law(w, g - d).force) / (2 * d);
    EXPECT_NEAR(c.stiffness / slope, 1.0, 1e-6) << load;
    if (i % 10 == 0) {
      const double e = quadrature(w, 1e-14 * g, g);
      EXPECT_NEAR(c.energy / e, 1.0, 1e-9) << load;
    }
  }
  std::printf("line law: 200 loads, worst |Q(g(Q))/Q - 1| %.2e, %d within the cap %.4g N\n", worst,
              within, cap);
  EXPECT_GT(within, 150);
  // the tangent at first touch falls to 0 (dδ/dQ grows as −ln Q): below the secant's
  EXPECT_LT(law(w, johnson_approach(1.0)).stiffness, 0.5 * law(w, johnson_approach(1e3)).stiffness);
  // past the branch's end e^(C−1) the inverse has no value
  EXPECT_TRUE(std::isnan(w.line.law.load(1.001 * w.line.law.approach(w.line.law.max_load()))));
  // beyond the cap: force and stiffness continuous, then linear, energy its integral
  const double g_cap = w.line.law.approach(w.line.law.cap_load());
  const SeatContact below = law(w, g_cap * (1 - 1e-9)), above = law(w, g_cap * (1 + 1e-9));
  EXPECT_NEAR(above.force / below.force, 1.0, 1e-8);
  EXPECT_NEAR(above.stiffness / below.stiffness, 1.0, 1e-6);
  const SeatContact deep = law(w, 1.5 * g_cap);
  EXPECT_NEAR(deep.force, above.force + above.stiffness * 0.5 * g_cap, 1e-9 * deep.force);
  const double e_deep = quadrature(w, 1e-14 * g_cap, g_cap) + quadrature(w, g_cap, 1.5 * g_cap);
  EXPECT_NEAR(deep.energy / e_deep, 1.0, 1e-9);
}

// The model's check refuses the line law on a pocket wheel, without its width and without the
// cap's constants use_line_law sets, by field.
TEST(DynamicsSeatLineLaw, ModelCheckNamesTheLawsFields) {
  Model m = uniform_chain(2, false, kPitch, 0.0238, 5e7, 0.0, false);
  m.sprockets = {line_wheel(12)};
  m.sprockets[0].driver = true;
  m.sprockets[0].speed = 13.0;
  for (const Issue& i : validate(m))
    ADD_FAILURE() << i.field << " " << i.value << " " << i.expected;
  // the line set without use_line_law: the cap's constants missing, named
  Sprocket bare = m.sprockets[0];
  bare.line.cap_depth = bare.line.cap_stiffness = 0.0;
  Model unset = m;
  unset.sprockets = {bare};
  bool cap = false;
  for (const Issue& i : validate(unset))
    cap = cap || i.field.find("line_cap_depth") != std::string::npos;
  EXPECT_TRUE(cap);
  m.sprockets[0].line.width = 0.0;
  m.sprockets[0].pocket = true;
  bool width = false, pocket = false;
  for (const Issue& i : validate(m)) {
    width = width || i.field.find("line_width") != std::string::npos;
    pocket = pocket || i.field.find("line_law") != std::string::npos;
  }
  EXPECT_TRUE(width);
  EXPECT_TRUE(pocket);
}

// (2) The linear default's secant k_c = Q0/δ(Q0) at the expected load Q0 (the example's
// T_L/R + pretension): the line law gives Q0 at g = Q0/k_c, the linear penalty with its ramp at
// Q0/k_c + ε/2; the line law's tangent there is the secant times 1 + 1/(2 ln(4R_ref/b) − 2).
TEST(DynamicsSeatLineLaw, AtTheExpectedLoadItGivesTheSecantsApproach) {
  Sprocket w = line_wheel(12);
  const double load = 10.0 / w.pitch_radius + 950.0;
  const double kc = load / johnson_approach(load);
  w.contact_stiffness = kc;  // as the command sets it: the take-up stops' and guides' default
  Sprocket linear = iso606_sprocket(kPitch, kRoller, kWidth, 12, 0.0, 0.0, kc, 0.0);
  const double g = load / kc;
  EXPECT_NEAR(law(w, g).force / load, 1.0, 1e-12);
  EXPECT_NEAR(law(linear, g + 0.5 * linear.contact_smoothing).force / load, 1.0, 1e-12);
  const double q = load / kWidth, ri = 0.505 * kRoller;
  const double rho = kRoller * ri / (2 * (ri - 0.5 * kRoller));
  const double b = std::sqrt(4 * q * rho / (kPi * kModulus / (2 * (1 - kPoisson * kPoisson))));
  const double ratio = 1 + 1 / (2 * std::log(2 * kRoller / b) - 2);
  EXPECT_NEAR(law(w, g).stiffness / kc, ratio, 1e-9);
  std::printf("at Q0 = %.1f N: g = %.4g um, secant %.4g N/m, tangent %.4g N/m (x %.4f)\n", load,
              g * 1e6, kc, law(w, g).stiffness, ratio);
}

// (3) The Newton matrix with the line law against central differences of the step's residual,
// every column, with the seats' damping; and it is the line law's matrix: the seat columns differ
// from the linear law's (k_c = 2e8 N/m) at the same iterate.
TEST(DynamicsSeatLineLaw, NewtonMatrixMatchesTheResidualsDifferences) {
  const double h = 1e-4;
  std::vector<double> jac_linear;
  for (const bool line : {false, true}) {
    testing::Loop l =
        testing::pressed_loop({.contact_damping = 800.0, .line_law = line, .load = 10.0});
    Integrator integ(l.model, {.step = h, .theta = 0.6});
    const std::size_t n = l.model.nodes(), size = integ.unknowns();
    const std::vector<double> u = testing::pressed_iterate(l, size, h, 0.0);
    std::vector<double> r0, jac;
    integ.newton_system(l.model, l.state, u, r0, &jac);
    if (!line) {
      jac_linear = jac;
      continue;
    }
    const testing::ColumnsAgainstDifferences d = testing::expect_columns_match_differences(
        integ, l.model, l.state, u, jac, jac_linear,
        [n](std::size_t c) { return c == 2 * n ? 1e-8 : 1e-10; }, 1e-5);
    std::printf("line law's Newton matrix: worst |J - FD| / column scale %.2e\n", d.worst);
    EXPECT_GT(d.differs, 0.1 * d.scale);
  }
}

// (4) Frictionless and undamped at θ = ½: two linked rollers dropped at 0.3 m/s into the top seats
// of a free z = 17 wheel under gravity bounce in them; the energy (the contacts' from the line
// law) is conserved as the linear law's (k_c = 2e8 N/m) is in the same drop, over 1 ms of 0.2 µs
// (the bounce takes about 30 µs) steps, and the contacts' energy at the start is the law's.
struct Drop {
  double e0 = 0.0, elastic0 = 0.0, drift = 0.0, kinetic_max = 0.0, damping_work = 0.0;
};
Drop drop(bool line, double g0) {
  constexpr double kG = 9.81, kMass = 0.0238;
  Sprocket w = iso606_sprocket(kPitch, kRoller, kWidth, 17, 0.0, 0.0, 2e8, 0.0);
  if (line) use_line_law(w, kWidth);
  w.inertia = 0.01;
  const double tau = 2 * kPi / w.teeth;
  State s(2, 1);
  s.angle = {kPi / 2 - tau / 2};
  const double clearance = w.seat_radius - w.roller_radius;
  for (int i = 0; i < 2; ++i) {
    const double sigma = s.angle[0] + i * tau;
    const double r = w.pitch_radius - clearance - g0;
    s.x[i] = r * std::cos(sigma);
    s.y[i] = r * std::sin(sigma);
    s.vy[i] = -0.3;
  }
  Model model =
      uniform_chain(2, false, std::hypot(s.x[1] - s.x[0], s.y[1] - s.y[0]), kMass, 1e6, 0.0, false);
  model.gravity_y = -kG;
  model.sprockets = {w};
  Drop d;
  d.elastic0 = energy(model, s).elastic;
  d.e0 = energy(model, s).total();
  // the contact resolved: ω_c h ≈ 0.03 for either law (the line law's tangent at the bounce's
  // few hundred N is 5e8–9e8 N/m; θ = ½ evaluates the contact at the midpoint, not by a discrete
  // gradient, and its error grows as (ω_c h)²: at 10 µs both laws lost 12–13 %)
  Integrator integ(model, {.step = 2e-7, .theta = 0.5});
  for (int k = 0; k < 5000; ++k) {
    const StepReport rep = integ.step(model, s);
    if (!rep.converged) {
      ADD_FAILURE() << "step " << k << " did not converge";
      return d;
    }
    const Energy e = energy(model, s);
    d.kinetic_max = std::max(d.kinetic_max, e.kinetic);
    d.drift = std::max(d.drift, std::abs(e.total() - d.e0));
  }
  d.damping_work = s.contact_damping_work;
  return d;
}

TEST(DynamicsSeatLineLaw, UndampedDropConservesEnergyAsTheLinearLaws) {
  const double g0 = 1e-6;
  const Drop line = drop(true, g0), linear = drop(false, g0);
  std::printf("undamped drop: largest |E - E0| / largest kinetic: line law %.3g, linear %.3g\n",
              line.drift / line.kinetic_max, linear.drift / linear.kinetic_max);
  // the links at rest length: the elastic energy is the two contacts', the law's at g0
  const Sprocket w = line_wheel(17);
  EXPECT_NEAR(line.elastic0 / (2 * kWidth * w.line.law.energy(w.line.law.load(g0))), 1.0, 1e-9);
  EXPECT_EQ(line.damping_work, 0.0);
  EXPECT_GT(line.kinetic_max, 1e-3);
  EXPECT_LT(line.drift, 1e-3 * line.kinetic_max);
  EXPECT_LT(linear.drift, 1e-3 * linear.kinetic_max);
}

}  // namespace
}  // namespace catena::dynamics
