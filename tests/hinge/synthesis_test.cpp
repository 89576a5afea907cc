#include "catena/hinge/synthesis.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <numbers>
#include <random>

#include "examples.hpp"
#include "rolling_simulation.hpp"

namespace catena::hinge {
namespace {

constexpr double kPi = std::numbers::pi;

// Tolerances. Lengths are ~1e-2 m, areas 3e-4 to 1.2e-3 m².
constexpr double kLengthTol = 1e-15;    // [m] a length from the same closed form: round-off
constexpr double kOnCircleTol = 1e-14;  // [m] the point N1 on the plate's circle: round-off
constexpr double kAngleTol = 1e-12;     // [rad] closed-form angles against atan2 and each other
constexpr double kAreaTol = 1e-12;      // [m²] sections that solve eq. (10) for the area F/[τ]
constexpr double kMicronTol = 1e-6;     // [m] lengths written here to 1 µm or finer

Hinge example() { return testing::example_hinge(); }

bool has(const Synthesis& s, const std::string& code) {
  for (const auto& d : s.diagnostics) {
    if (d.code == code) return true;
  }
  return false;
}

// Area of the roller section by integrating its width over y (no lens formulas).
double section_by_quadrature(double d, double a, double face_radius) {
  const double r0 = d / 2;
  auto width = [&](double y) {
    const double circle = std::sqrt(std::max(0.0, r0 * r0 - y * y));
    double face = a;  // flat face
    if (face_radius != 0.0) {
      face = std::abs(y) < face_radius
                 ? a + face_radius - std::sqrt(face_radius * face_radius - y * y)
                 : circle;
    }
    return 2.0 * std::min(circle, face);
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(width, -r0, r0, 15, 1e-13);
}

TEST(HingeSynthesis, N1IsWhereTheTwoCirclesMeetEq4_5) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double d = 0.02 + 0.06 * u(rng), a = (0.05 + 0.4 * u(rng)) * d,
                 r1 = (0.2 + 2 * u(rng)) * d;
    const double x = x_n1(d, a, r1);
    const double y = std::sqrt(d * d / 4 - x * x);
    EXPECT_NEAR(std::hypot(x - a - r1, y), r1, kOnCircleTol);  // on the plate's circle as well
    EXPECT_NEAR(psi1_max(d, a, r1), std::atan2(y, a + r1 - x), kAngleTol);
  }
}

TEST(HingeSynthesis, R1maxIsWhereEq6NeedsAFlatFace) {
  const Hinge h = example();
  const double gmax = gamma_max(h);
  const double rmax = r1_max(h.pin_diameter, h.half_thickness, gmax);
  EXPECT_NEAR(psi1_max(h.pin_diameter, h.half_thickness, rmax), gmax, kAngleTol);
  double previous = 0.0;
  for (double f : {0.5, 0.9, 0.99, 0.999, 0.99999}) {  // R2 → ∞ as R1 → R1max, monotonically
    const double r2 = *r2_eq6(h.pin_diameter, h.half_thickness, f * rmax, gmax);
    EXPECT_GT(r2, previous);
    previous = r2;
  }
  EXPECT_GT(previous, 1000 * rmax);
  EXPECT_FALSE(r2_eq6(h.pin_diameter, h.half_thickness, 1.01 * rmax, gmax).has_value());
}

// Sprockets of very many teeth (γmax → 0): R1max stays finite and is still where Ψ1max = γmax,
// and the branch for small γ meets the ordinary one (1 − cos γ had cancelled to 0 at z ~ 1e9,
// a NaN R1max that a hinge sweep blamed on --plate-radius; issue 18).
TEST(HingeSynthesis, R1maxStaysFiniteForTinyDesignTurns) {
  const double d = 0.040, a = 0.008;
  for (double gmax : {1e-2, 1e-4, 1e-6, 3.14e-9, 1e-12}) {
    const double rmax = r1_max(d, a, gmax);
    ASSERT_TRUE(std::isfinite(rmax)) << gmax;
    // Ψ1max(R1max) = γmax by eq. (5) written as 1 − cos Ψ1max = (d²/4 − a²)/(2R1(R1 + a)),
    // compared relatively (acos near 1 would lose the digits)
    const double one_minus_cos = (0.25 * d * d - a * a) / (2.0 * rmax * (rmax + a));
    EXPECT_NEAR(one_minus_cos / (2.0 * std::pow(std::sin(0.5 * gmax), 2)), 1.0, 1e-9) << gmax;
  }
  // continuity across the switch at 1e-3
  EXPECT_NEAR(r1_max(d, a, 1e-3 * (1 - 1e-12)) / r1_max(d, a, 1e-3 * (1 + 1e-12)), 1.0, 1e-6);
}

TEST(HingeSynthesis, SectionAreasMatchQuadrature) {
  // [m²] sections of ~6e-4 m² against Gauss-Kronrod over a width with kinks: ~2e-7 relative
  constexpr double kQuadratureAreaTol = 1e-10;
  for (double face : {0.0, 0.020, 0.0395, 0.2}) {
    EXPECT_NEAR(section_area(0.040, 0.008, face), section_by_quadrature(0.040, 0.008, face),
                kQuadratureAreaTol)
        << face;
  }
  // (10) with R1 arcs overstates the true section (R2 > R1 cuts deeper at the edges)
  EXPECT_GT(section_area(0.040, 0.008, 0.020), section_area(0.040, 0.008, 0.0395));
}

TEST(HingeSynthesis, AMinSolvesTheShearEquation10) {
  const double d = 0.040, r1 = 0.020, f = 29.4e3, tau = 100e6;
  const auto a = a_min_eq10(d, r1, f, tau);
  ASSERT_TRUE(a.has_value());
  EXPECT_NEAR(section_area(d, *a, r1), f / tau, kAreaTol);
  EXPECT_FALSE(a_min_eq10(0.010, r1, 29.4e3, 100e6).has_value());  // πd²/4 = 78.5 mm² < 294 mm²
  Hinge h = example();
  Loads loads;
  loads.tension = 120e3;
  loads.allowable_shear = 100e6;
  h.half_thickness = 0.004;
  const Synthesis s = synthesize(h, loads);
  ASSERT_TRUE(s.a_min.has_value());
  EXPECT_GT(*s.a_min, 0.004);
  EXPECT_TRUE(has(s, "hinge.half_thickness_below_a_min"));
}

TEST(HingeSynthesis, Step1SolvesEqs7And10Together) {
  const double d = 0.040, f = 120e3, tau = 100e6, gmax = kPi / 8;
  const auto j = a_min_at_r1max(d, gmax, f, tau);
  ASSERT_TRUE(j.has_value());
  EXPECT_NEAR(j->r1_max, r1_max(d, j->a_min, gmax), kLengthTol);
  EXPECT_NEAR(section_area(d, j->a_min, j->r1_max), f / tau, kAreaTol);
  constexpr double kJointAngleTol = 1e-9;  // [rad] through the joint root of eqs. (7) and (10)
  EXPECT_NEAR(psi1_max(d, j->a_min, j->r1_max), gmax, kJointAngleTol);  // R1max: flat-face limit
  EXPECT_FALSE(a_min_at_r1max(0.010, gmax, f, tau).has_value());
}

TEST(HingeSynthesis, RollingLimitEq21MatchesTheSimulatedForceAngle) {
  // With the roller held, the chain force runs along the plate axis; friction holds while the
  // angle β between it and the contact normal satisfies tan β ≤ f (eq. 20).
  const Hinge h = example();
  const double r2 = *r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, gamma_max(h));
  constexpr double kFrictionTol = 1e-9;  // [1] tan β at the simulation's root-found pose
  const testing::RollingSimulation sim(h, r2);
  for (double f : {0.05, 0.15, 0.3}) {
    const double limit = rolling_limit(f, h.plate_radius, r2);
    const testing::SimulatedPose p = sim.at_phi(2 * limit);
    EXPECT_NEAR(std::tan(p.beta), f, kFrictionTol) << f;
  }
}

TEST(HingeSynthesis, DiagnosticsNameTheLimit) {
  Hinge h = example();
  h.plate_radius = 0.050;  // R1max = 43.15 mm
  Loads loads;
  loads.friction = 0.15;
  loads.tension = 29.4e3;
  loads.contact_length = 0.024;
  loads.allowable_contact = 500e6;
  const Synthesis s = synthesize(h, loads);
  ASSERT_TRUE(has(s, "hinge.r1_exceeds_r1max"));
  for (const auto& d : s.diagnostics) {
    if (d.code == "hinge.r1_exceeds_r1max") {
      EXPECT_NEAR(d.limit, 0.0431490, kMicronTol);
      EXPECT_NE(d.message.find("R1max = 43.149 mm"), std::string::npos) << d.message;
    }
  }
  EXPECT_TRUE(has(s, "hinge.rolling_limit_below_working_turn"));
  EXPECT_TRUE(has(s, "hinge.contact_stress"));
  h.plate_radius = 0.020;
  loads.allowable_contact = 5000e6;
  const Synthesis ok = synthesize(h, loads);
  EXPECT_FALSE(has(ok, "hinge.contact_stress"));
  EXPECT_FALSE(has(ok, "hinge.r1_exceeds_r1max"));
  EXPECT_NEAR(ok.r2, 0.0395033, kMicronTol);
}

TEST(HingeSynthesis, InvalidInputListsEveryProblem) {
  Hinge h;
  h.pin_diameter = 0.02;
  h.half_thickness = 0.011;
  h.plate_radius = -1;
  h.teeth = 2;
  Loads loads;
  loads.friction = -0.1;
  try {
    synthesize(h, loads);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.issues().size(), 4u) << e.what();
  }
}

}  // namespace
}  // namespace catena::hinge
