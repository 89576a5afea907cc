// Closed-form hinge kinematics against the independent rolling simulation.
#include "catena/hinge/kinematics.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "catena/hinge/synthesis.hpp"
#include "rolling_simulation.hpp"

namespace catena::hinge {
namespace {

constexpr double kPositionTol = 1e-9;  // [m] the bound
constexpr double kRootTol = 1e-9;      // [rad] the simulation's root finder for the turn
// [m] lengths of ~1e-2 m where both sides are the same closed form (or exactly 0): round-off
constexpr double kRoundOffLengthTol = 1e-15;
// [m] below one ulp of a = 8 mm: the zero-turn values must come out exact
constexpr double kZeroTurnTol = 1e-18;
// [1] relative: the small-turn expansion drops terms of relative order Ψ1 = 1e-3
constexpr double kExpansionRelTol = 1e-3;

struct Case {
  const char* name;
  Hinge hinge;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

Hinge concave(double d, double a, double r1, int z, int m = 1, double r2 = 0.0) {
  Hinge h;
  h.pin_diameter = d;
  h.half_thickness = a;
  h.plate_radius = r1;
  h.teeth = z;
  h.strokes = m;
  h.roller_radius = r2;
  return h;
}

Hinge flat(double d, double b, double r1, int z, double half_length, double loaded) {
  Hinge h = concave(d, b, r1, z);
  h.face = Face::kFlat;
  h.face_half_length = half_length;
  h.loaded_length = loaded;
  return h;
}

double r2_of(const Hinge& h) {
  if (h.face == Face::kFlat) return std::numeric_limits<double>::infinity();
  return h.roller_radius > 0
             ? h.roller_radius
             : *r2_eq6(h.pin_diameter, h.half_thickness, h.plate_radius, gamma_max(h));
}

class HingeCase : public ::testing::TestWithParam<Case> {};

TEST_P(HingeCase, ClosedFormsAgreeWithTheRollingSimulation) {
  const Hinge& h = GetParam().hinge;
  const double r2 = r2_of(h);
  const testing::RollingSimulation sim(h, r2);
  const double phi_max = 2 * gamma_max(h);
  const std::vector<Point> corners = feature_points(h, r2);
  for (int i = 0; i <= 20; ++i) {
    const double phi = phi_max * i / 20.0;
    const testing::SimulatedPose s = sim.at_phi(phi);
    EXPECT_NEAR(s.gamma, phi / 2, kRootTol);  // the simulation's root finder
    const Pose p = pose(h, r2, 2 * s.gamma);  // at the simulated turn itself
    EXPECT_NEAR(p.contact.x, s.contact.x, kPositionTol) << "phi " << phi;
    EXPECT_NEAR(p.contact.y, s.contact.y, kPositionTol) << "phi " << phi;
    EXPECT_NEAR(p.centre.x, s.centre.x, kPositionTol) << "phi " << phi;
    EXPECT_NEAR(p.centre.y, s.centre.y, kPositionTol) << "phi " << phi;
    EXPECT_NEAR(pitch_change(h, r2, 2 * s.gamma), 2 * s.centre.x, 2 * kPositionTol);
    for (const Point& c : corners) {  // eq. (11) for the feature points
      const Point q = roller_point(p, c);
      const testing::Vec r = s.body({c.x, c.y});
      EXPECT_NEAR(q.x, r.x, kPositionTol);
      EXPECT_NEAR(q.y, r.y, kPositionTol);
    }
  }
}

TEST_P(HingeCase, StartsStraightAndIsMirrorSymmetric) {
  const Hinge& h = GetParam().hinge;
  const double r2 = r2_of(h);
  EXPECT_NEAR(pitch_change(h, r2, 0.0), 0.0, kRoundOffLengthTol);
  const Pose zero = pose(h, r2, 0.0);
  EXPECT_NEAR(zero.centre.x, 0.0, kRoundOffLengthTol);
  EXPECT_NEAR(zero.centre.y, 0.0, kRoundOffLengthTol);
  if (h.face == Face::kFlat && flat_contact_offset(h) != 0.0) return;  // offset breaks the mirror
  for (double phi : {0.05, 0.2, 0.4}) {  // turning the other way mirrors the hinge in y
    const Pose p = pose(h, r2, phi);
    const Pose m = pose(h, r2, -phi);
    EXPECT_NEAR(p.centre.x, m.centre.x, kRoundOffLengthTol);
    EXPECT_NEAR(p.centre.y, -m.centre.y, kRoundOffLengthTol);
    EXPECT_NEAR(p.contact.y, -m.contact.y, kRoundOffLengthTol);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Hinges, HingeCase,
    ::testing::Values(Case{"d40_a8_r20_z8", concave(0.040, 0.008, 0.020, 8)},
                      Case{"d30_a5_r12_z12", concave(0.030, 0.005, 0.012, 12)},
                      Case{"two_strokes", concave(0.040, 0.008, 0.012, 16, 2)},
                      Case{"given_r2", concave(0.040, 0.008, 0.020, 8, 1, 0.060)},
                      Case{"near_r1max", concave(0.040, 0.008, 0.0430, 8)},
                      Case{"flat_centred", flat(0.040, 0.008, 0.020, 8, 0.015, 0.015)},
                      Case{"flat_offset", flat(0.040, 0.008, 0.020, 8, 0.015, 0.010)}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(HingeKinematics, DerivedV1V2ReproduceThePrintedForm18_19) {
  const Hinge h = concave(0.040, 0.008, 0.020, 8);
  const double r2 = r2_of(h);
  const double a = h.half_thickness, r1 = h.plate_radius;
  for (double phi = 0.0; phi <= 2 * gamma_max(h); phi += 0.05) {
    const Pose p = pose(h, r2, phi);
    // 000 eqs. (18)–(19), Latvian printing, with V1, V2 as derived
    const double x = a + r1 - (r1 + p.v2) * std::cos(p.psi1) - p.v1 * std::sin(phi / 2);
    const double y = (r1 + p.v2) * std::sin(p.psi1) - p.v1 * std::cos(phi / 2);
    EXPECT_NEAR(x, p.centre.x, kRoundOffLengthTol);
    EXPECT_NEAR(y, p.centre.y, kRoundOffLengthTol);
  }
  EXPECT_NEAR(pose(h, r2, 0).v1, 0.0, kZeroTurnTol);
  EXPECT_NEAR(pose(h, r2, 0).v2, a, kZeroTurnTol);
  EXPECT_GT(pose(h, r2, 0.5).v1, 0.0);  // not constants
}

TEST(HingeKinematics, RandomHingesAreFiniteAndMatchTheSmallTurnExpansion) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> teeth(6, 40);
  for (int i = 0; i < 2000; ++i) {
    const double d = 0.01 + 0.09 * unit(rng);
    const double a = (0.05 + 0.4 * unit(rng)) * d;
    const int z = teeth(rng);
    const double rmax = r1_max(d, a, std::numbers::pi / z);
    const double r1 = (0.02 + 0.97 * unit(rng)) * rmax;
    Hinge h = concave(d, a, r1, z);
    const auto r2 = r2_eq6(d, a, r1, gamma_max(h));
    ASSERT_TRUE(r2.has_value());
    ASSERT_GT(*r2, r1);
    for (int k = 0; k <= 10; ++k) {
      const double phi = 2 * gamma_max(h) * k / 10;
      const Pose p = pose(h, *r2, phi);
      ASSERT_TRUE(std::isfinite(p.centre.x) && std::isfinite(p.centre.y) && std::isfinite(p.v1) &&
                  std::isfinite(p.v2));
    }
    // small turns: Δt ≈ −γ²[R1R2 − a(R2 − R1)]/(R2 − R1) (second-order expansion of 2·X_O2)
    const double g = 1e-3 * (*r2 - r1) / *r2;  // Ψ1 = 1e-3: the expansion is in Ψ1
    const double expected = -g * g * (r1 * *r2 - a * (*r2 - r1)) / (*r2 - r1);
    EXPECT_NEAR(pitch_change(h, *r2, 2 * g), expected,
                kExpansionRelTol * std::abs(expected) + kRoundOffLengthTol);
  }
}

}  // namespace
}  // namespace catena::hinge
