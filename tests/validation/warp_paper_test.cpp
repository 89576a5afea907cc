// Seed 000 §1.4 and conclusions 6–7: what the warp model reproduces of the thesis' numbers.
// The thesis gives no clearances, stiffnesses or plate heights; these tests sweep plausible
// values (docs/models/warp.md, "Sensitivity band") and document which numbers lie inside.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/hertz.hpp"
#include "catena/warp/warp.hpp"

namespace {

using namespace catena::warp;

constexpr double kShareTol = 1e-3;  // [1] bisection tolerance on the upper/lower share

// A t = 125 mm class hinge: plates B thick, inner gap h, roller d (plausible, not the thesis').
Warp hinge(double d, double b, double h, double k, double n) {
  Warp w;
  const double z[4] = {0.0, b, b + h, 2 * b + h};
  for (std::size_t i = 0; i < 4; ++i) w.supports[i] = {z[i], 0.0, k, b};
  w.exponent = n;
  w.roller_diameter = d;
  return w;
}

// Offset e of L1 above mid-height at which the upper/lower share reaches `target`.
double offset_for_share(const Warp& w, double force, double target) {
  const double mid = 0.5 * (w.supports[0].height + w.supports[3].height);
  double lo = 0.0, hi = 0.5 * (w.supports[3].height - w.supports[0].height) * 0.5;
  for (int i = 0; i < 60; ++i) {
    const double e = 0.5 * (lo + hi);
    (solve(w, {force, mid + e}).upper_share < target ? lo : hi) = e;
  }
  return 0.5 * (lo + hi);
}

TEST(WarpPaper, UpperHingesCarry7To19PercentMoreForAMmScaleLoadOffset) {
  // Conclusion 6: upper hinges loaded 7–19 % more than lower. Inside the band for every
  // plausible parameter set, with L1 0.4–3 mm above mid-height (the driver is the offset).
  for (double d : {0.020, 0.030})
    for (double b : {0.006, 0.010})
      for (double k : {2e8, 1e9}) {
        const Warp w = hinge(d, b, 0.040, k, 1.0);
        const double e7 = offset_for_share(w, 35e3, 0.07);
        const double e19 = offset_for_share(w, 35e3, 0.19);
        EXPECT_GT(e7, 0.3e-3);
        EXPECT_LT(e19, 3.0e-3);
        const double mid = 0.5 * w.supports[3].height;
        EXPECT_NEAR(solve(w, {35e3, mid + e19}).upper_share, 0.19, kShareTol);
      }
}

TEST(WarpPaper, FourPercentDeformationNeedsTheLevinaReshetovExponent) {
  // Conclusion 6: upper deformations ~4 % larger. With a linear joint (n = 1) the deformation
  // ratio equals the force ratio (7–19 %): 4 % is outside. With y = C·p^0.5 (n = 2) it is about
  // half the force share: 3.4–9.5 %, so 4 % lies inside at the low end of the 7–19 % band.
  const Warp lin = hinge(0.024, 0.008, 0.040, 2e8, 1.0);
  const Warp lr = hinge(0.024, 0.008, 0.040, 2e13, 2.0);
  // [1] linear joints without clearance: the deformation share is the force share 0.07
  constexpr double kLinearShareTol = 0.005;
  for (const Warp* w : {&lin, &lr}) {
    const double mid = 0.5 * w->supports[3].height;
    const WarpResult r = solve(*w, {35e3, mid + offset_for_share(*w, 35e3, 0.07)});
    const double ratio =
        (r.deformation[kF12] + r.deformation[kF22]) / (r.deformation[kF11] + r.deformation[kF21]) -
        1.0;
    if (w->exponent == 1.0) {
      EXPECT_NEAR(ratio, 0.07, kLinearShareTol);
    } else {
      EXPECT_GT(ratio, 0.03);
      EXPECT_LT(ratio, 0.045);
    }
  }
}

TEST(WarpPaper, MeasuredDifferenceOf1_4kNIsInsideTheShareBandAt30kN) {
  // §1.4: measured upper–lower difference up to 1.4 kN. At F = 30 kN that is a share of
  // 2·1.4/(30 − 1.4) = 9.8 %, inside 7–19 %; the model reaches it with L1 ≈ 1 mm above mid.
  const Warp w = hinge(0.024, 0.008, 0.040, 2e8, 1.0);
  const double share = 2 * 1.4 / (30 - 1.4);
  const double mid = 0.5 * w.supports[3].height;
  const WarpResult r = solve(w, {30e3, mid + offset_for_share(w, 30e3, share)});
  const double diff = r.force[kF12] + r.force[kF22] - r.force[kF11] - r.force[kF21];
  EXPECT_NEAR(diff, 1.4e3, 30e3 * kShareTol);
  EXPECT_GT(share, 0.07);
  EXPECT_LT(share, 0.19);
}

TEST(WarpPaper, RollingVersusSlidingStressConclusion7) {
  // Conclusion 7: rolling hinge (R1 = 34, R2 = 35.4 mm) contact stress at 30–40 kN ≈ half the
  // sliding hinge's specific pressure. NOT reproduced with p = R/(d·B) for any plausible d, B:
  // the Hertz stress of R1 in R2 is 2.5–7 times that pressure. Reproduced if the sliding
  // hinge's figure is also a Hertz stress (pin radius r in a hole r + Δ, Δ ≈ 0.6–0.7 mm):
  // the ratio is then √(R*_sliding / R*_rolling).
  for (double d : {0.020, 0.030})
    for (double b : {0.006, 0.010})
      for (double f : {30e3, 40e3}) {
        Warp w = hinge(d, b, 0.040, 2e8, 1.0);
        const double upper = solve(w, {f, 0.5 * w.supports[3].height + 1e-3}).force[kF12];
        const double sliding = contact_stress(w, kF12, upper);
        w.kind = HingeKind::kRolling;
        w.r1 = 0.034;
        w.r2 = 0.0354;
        const double rolling = contact_stress(w, kF12, upper);
        EXPECT_GT(rolling / sliding, 2.0) << d << " " << b << " " << f;
      }
  const catena::Elastic steel{};
  const double e = catena::contact_modulus(steel, steel);
  const double q = 10e3 / 0.008;  // [N/m] an upper joint at F ≈ 35 kN
  const double roll =
      catena::line_contact(q, catena::conformal_radius(0.034, 0.0354), e).peak_pressure;
  const double r = 0.012, gap = 0.00067;  // sliding pin Ø24 mm in a hole 0.67 mm larger (radius)
  const double slide =
      catena::line_contact(q, catena::conformal_radius(r, r + gap), e).peak_pressure;
  constexpr double kHalfTol = 0.05;  // [1] the thesis' "about half", to ±10 %
  EXPECT_NEAR(roll / slide, 0.5, kHalfTol);
}

}  // namespace
