// Roller warp (seed 000 §1.4): hand-derivable cases, equilibrium and compatibility residuals,
// the independent finite-element check, property tests over random inputs, error cases.
#include "catena/warp/warp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace catena::warp;

constexpr double kForceTol = 1e-6;  // [N] on forces of order 10 kN (solver tol 1e-10·F)
constexpr double kMomentTol = kForceTol * 0.06;  // [N·m] kForceTol over the 60 mm joint span
constexpr double kRelForceTol = 1e-7;            // [1] relative, solver vs FE / closed form
constexpr double kRigidEi = 1e5;    // [1] factor on E: bending compliance ~3e-6 of the joints'
constexpr double kRigidTol = 1e-4;  // [1] relative, rigid-roller limit vs closed form
constexpr double kTiltTol = 1e-12;  // [rad] a tilt that symmetry makes zero: round-off
constexpr double kDeflectionTol = 1e-12;  // [m] deflections of ~1e-4 m by two solvers
constexpr double kShareTol = 1e-9;        // [1] the upper share (F12 + F22)/(F11 + F21) − 1

Warp example() {
  Warp w;
  // heights [m]: lower outer, lower inner, upper inner, upper outer (a t = 125 mm class chain)
  const double z[4] = {0.0, 0.010, 0.050, 0.060};
  for (std::size_t i = 0; i < 4; ++i) w.supports[i] = {z[i], 0.0, 2e8, 0.008};
  w.roller_diameter = 0.024;
  return w;
}

TEST(Warp, RigidEqualSupportsMidHeightLoadGivesEqualForces) {
  Warp w = example();
  w.modulus *= kRigidEi;
  const Load load{20e3, 0.030};  // mid-height of a symmetric layout
  const WarpResult r = solve(w, load);
  ASSERT_TRUE(r.summary.converged) << r.summary.termination;
  for (double f : r.force) EXPECT_NEAR(f, 5e3, 5e3 * kRigidTol);
  EXPECT_NEAR(r.tilt, 0.0, kTiltTol);
}

TEST(Warp, LoadAtAnOuterSupportGoesAllToIt) {
  // Rigid roller, no clearance, linear joints, F at the upper outer joint: the top joint alone
  // balances F with no moment about itself; any share elsewhere would need a tension (the
  // bilateral closed form gives negative lower forces), so the unilateral lower joints open.
  Warp w = example();
  w.modulus *= kRigidEi;
  const Load load{10e3, 0.060};
  const WarpResult r = solve(w, load);
  ASSERT_TRUE(r.summary.converged);
  EXPECT_NEAR(r.force[kF22], 10e3, 10e3 * kRigidTol);
  for (Joint j : {kF21, kF11, kF12}) EXPECT_NEAR(r.force[j], 0.0, 10e3 * kRigidTol);
}

TEST(Warp, RigidLinearZeroClearanceMatchesClosedForm) {
  Warp w = example();
  w.modulus *= kRigidEi;
  w.supports[0].stiffness = 1e8;
  w.supports[3].stiffness = 3e8;
  const Load load{30e3, 0.036};
  const auto closed = rigid_linear(w, load);
  for (double f : closed) ASSERT_GT(f, 0.0);  // all joints in contact: the closed form applies
  const WarpResult r = solve(w, load);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(r.force[i], closed[i], 30e3 * kRigidTol);
}

TEST(Warp, AgreesWithFiniteElementModel) {
  for (double n : {1.0, 2.0}) {
    Warp w = example();
    w.exponent = n;
    w.supports[2].clearance = 5e-6;
    w.supports[0].clearance = 2e-5;
    if (n == 2.0)
      for (auto& s : w.supports) s.stiffness = 2e13;  // N/m² (≈ 2e8 N/m at 10 µm approach)
    const Load load{35e3, 0.042};
    const WarpResult r = solve(w, load);
    ASSERT_TRUE(r.summary.converged) << r.summary.termination;
    const auto fe = solve_fe(w, load, 10);
    const WarpResult flex = solve_flexibility(w, load);
    ASSERT_TRUE(flex.summary.converged) << flex.summary.termination;
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(r.force[i], fe[i], 35e3 * kRelForceTol) << "n = " << n << " joint " << i;
      EXPECT_NEAR(r.force[i], flex.force[i], 35e3 * kRelForceTol) << "n = " << n << " joint " << i;
      EXPECT_NEAR(r.deflection[i], flex.deflection[i], kDeflectionTol)
          << "n = " << n << " joint " << i;
    }
  }
}

TEST(Warp, EquilibriumAndCompatibilityResiduals) {
  Warp w = example();
  w.supports[1].clearance = 1e-5;
  const Load load{40e3, 0.045};
  const WarpResult r = solve(w, load);
  ASSERT_TRUE(r.summary.converged);
  double sum = 0, mom = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    sum += r.force[i];
    mom += r.force[i] * w.supports[i].height;
    // compatibility: every joint force follows its law from the solved deflection
    const double g = r.deflection[i] - w.supports[i].clearance;
    EXPECT_NEAR(r.force[i], g > 0 ? w.supports[i].stiffness * g : 0.0, kForceTol);
    EXPECT_GE(r.force[i], 0.0);
  }
  EXPECT_NEAR(sum, load.force, kForceTol);
  EXPECT_NEAR(mom, load.force * load.height, kMomentTol);
  EXPECT_LE(r.force_residual, kForceTol);
}

TEST(Warp, UpperLoadRaisesUpperShareAndTilt) {
  const Warp w = example();
  const WarpResult mid = solve(w, {30e3, 0.030});
  const WarpResult up = solve(w, {30e3, 0.036});
  EXPECT_NEAR(mid.upper_share, 0.0, kShareTol);
  EXPECT_GT(up.upper_share, 0.0);
  EXPECT_GT(up.tilt, 0.0);
  EXPECT_GT(up.deformation[kF22], up.deformation[kF21]);
}

TEST(Warp, SlidingAndRollingStresses) {
  constexpr double kStressTol = 1e-6;      // [Pa] p = F/(dB) ≈ 4e7 Pa: round-off
  constexpr double kHertzStressTol = 1.0;  // [Pa] p0 ≈ 2e8 Pa by hand: 5e-9 relative
  Warp w = example();
  EXPECT_NEAR(contact_stress(w, kF12, 8e3), 8e3 / (0.024 * 0.008), kStressTol);
  w.kind = HingeKind::kRolling;
  w.r1 = 0.034;
  w.r2 = 0.0354;
  // Johnson §4.2: p0 = sqrt(P' E* / (π R*)), R* = R1 R2/(R2 − R1), E* = E/(2(1 − ν²))
  const double rstar = 0.034 * 0.0354 / 0.0014;
  const double estar = 210e9 / (2 * (1 - 0.09));
  EXPECT_NEAR(contact_stress(w, kF12, 8e3), std::sqrt(8e3 / 0.008 * estar / (M_PI * rstar)),
              kHertzStressTol);
}

TEST(Warp, PropertyRandomInputs) {
  constexpr int kTrials = 300;
  constexpr double kEquilibriumTol = 1e-6;  // [1] of F (stiff random rollers: round-off)
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> u(0, 1);
  int failures = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    Warp w;
    double z = 0;
    for (auto& s : w.supports) {
      s.height = z;
      z += 0.002 + 0.05 * u(rng);
      s.clearance = 1e-4 * u(rng) * u(rng);
      s.width = 0.002 + 0.02 * u(rng);
    }
    w.exponent = 1 + 2 * u(rng);
    for (auto& s : w.supports)
      s.stiffness = std::pow(10.0, 6 + 3 * u(rng)) * std::pow(1e-5, 1 - w.exponent);
    w.roller_diameter = 0.005 + 0.04 * u(rng);
    const Load load{100 + 1e5 * u(rng),
                    w.supports[0].height + u(rng) * (w.supports[3].height - w.supports[0].height)};
    const WarpResult r = solve(w, load);
    for (double f : r.force) EXPECT_TRUE(std::isfinite(f) && f >= 0.0) << trial;
    if (!r.summary.converged) {  // allowed, but never silent
      ++failures;
      bool flagged = false;
      for (const auto& d : r.diagnostics) flagged |= d.code == "warp.not_converged";
      EXPECT_TRUE(flagged) << trial;
      continue;
    }
    EXPECT_LE(r.force_residual, kEquilibriumTol * load.force) << trial;
    EXPECT_LE(r.moment_residual, kEquilibriumTol * load.force * w.supports[3].height) << trial;
    for (double f : r.force) {
      EXPECT_TRUE(std::isfinite(f));
      EXPECT_GE(f, 0.0);
    }
    EXPECT_TRUE(std::isfinite(r.tilt) && std::isfinite(r.bending_stress));
  }
  EXPECT_EQ(failures, 0) << failures << " of " << kTrials << " did not converge";
}

TEST(Warp, ValidateListsEveryProblem) {
  Warp w = example();
  w.supports[2].height = 0.005;  // below the lower inner joint
  w.supports[1].clearance = -1e-6;
  w.supports[0].stiffness = 0;
  w.exponent = 5;
  w.roller_diameter = NAN;
  w.kind = HingeKind::kRolling;
  w.r1 = 0.034;
  w.r2 = 0.030;
  const auto issues = validate(w, {-1, 0.2});
  EXPECT_GE(issues.size(), 7u);
  EXPECT_THROW(solve(w, {-1, 0.2}), catena::InputError);
  EXPECT_THROW(solve(example(), {1e3, 0.1}), catena::InputError);  // L1 above the top joint
}

}  // namespace
