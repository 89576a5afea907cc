// Seed 000 §1.4 and conclusions 6–7: what the warp model reproduces of the thesis' numbers.
// The thesis gives no clearances, stiffnesses or plate heights; these tests sweep plausible
// values (docs/models/warp.md, "Sensitivity band") and document which numbers lie inside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "catena/core/hertz.hpp"
#include "catena/warp/warp.hpp"

namespace {

using namespace catena::warp;

// A t = 125 mm class hinge: plates B thick, inner gap h, roller d (plausible, not the thesis').
Warp hinge(double d, double b, double h, double k, double n) {
  Warp w;
  const double z[4] = {0.0, b, b + h, 2 * b + h};
  for (std::size_t i = 0; i < 4; ++i) w.supports[i] = {z[i], 0.0, k, b};
  w.exponent = n;
  w.roller_diameter = d;
  return w;
}

// Upper/lower deformation ratio − 1: (δ12 + δ22)/(δ11 + δ21) − 1 (conclusion 6's "4 % more").
double deformation_excess(const WarpResult& r) {
  return (r.deformation[kF12] + r.deformation[kF22]) / (r.deformation[kF11] + r.deformation[kF21]) -
         1.0;
}

// Offset e of L1 above mid-height at which `measure` of the solution reaches `target` (both
// measures rise with the offset).
template <class Measure>
double offset_for(const Warp& w, double force, double target, Measure measure) {
  const double mid = 0.5 * (w.supports[0].height + w.supports[3].height);
  double lo = 0.0, hi = 0.5 * (w.supports[3].height - w.supports[0].height) * 0.5;
  for (int i = 0; i < 60; ++i) {
    const double e = 0.5 * (lo + hi);
    (measure(solve(w, {force, mid + e})) < target ? lo : hi) = e;
  }
  return 0.5 * (lo + hi);
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
        // [m] the offsets the doc quotes (0.4–3 mm), with 0.1 mm to spare at the low end
        constexpr double kLeastOffset = 0.3e-3, kMostOffset = 3.0e-3;
        EXPECT_GT(e7, kLeastOffset);
        EXPECT_LT(e19, kMostOffset);  // L1 is fitted: the share itself is not asserted
      }
}

// The plausible input band of docs/models/warp.md for the n = 2 (Levina–Reshetov) joint: d, B,
// k and F = 30–40 kN, equal clearances (which only translate the roller). Unequal clearances
// are left out: with the inner pair 20 µm looser and k = 2e14 N/m² the inner joints carry
// almost nothing (tens of N) and the summed deformations jump as they touch — the ratio of
// conclusion 6 has no stable meaning there.
template <class Body>
void for_each_n2_hinge(Body body) {
  for (double d : {0.020, 0.030})
    for (double b : {0.006, 0.010})
      for (double k : {2e13, 2e14})
        for (double f : {30e3, 40e3}) body(hinge(d, b, 0.040, k, 2.0), f);
}

TEST(WarpPaper, FourPercentDeformationPredictsAShareAtTheLowEndOfTheBandOnlyWithTheN2Law) {
  // Conclusion 6 gives two numbers: upper hinges loaded 7–19 % more, deformed ~4 % more. Fit L1
  // to the deformation (4 %) and the share is a prediction: with the Levina–Reshetov law (n = 2)
  // it is 6.0–8.2 % over the input band — the low end of 7–19 %; with a linear joint (n = 1) the
  // deformation ratio IS the force ratio, so the predicted share is 4 %, outside the band.
  double lo = 1.0, hi = 0.0;
  for_each_n2_hinge([&](const Warp& w, double f) {
    const double e = offset_for(w, f, 0.04, deformation_excess);
    const double share = solve(w, {f, 0.5 * w.supports[3].height + e}).upper_share;
    lo = std::min(lo, share);
    hi = std::max(hi, share);
  });
  constexpr double kQuotedShareTol = 0.0005;  // [1] the band is quoted to 0.1 %
  EXPECT_NEAR(lo, 0.0598, kQuotedShareTol);
  EXPECT_NEAR(hi, 0.0816, kQuotedShareTol);
  constexpr double kThesisLowShare = 0.07;    // [1] the thesis' band 7–19 %
  constexpr double kFarBelowUpperEnd = 0.10;  // [1] nowhere near its 19 %
  EXPECT_LT(lo, kThesisLowShare);             // reaches below the thesis' band ...
  EXPECT_GT(hi, kThesisLowShare);             // ... and into it, but nowhere near its upper end
  EXPECT_LT(hi, kFarBelowUpperEnd);
  constexpr double kLinearShareTol = 1e-3;  // [1] bisection on the deformation to 60 halvings
  for (double k : {2e8, 1e9}) {
    const Warp lin = hinge(0.024, 0.008, 0.040, k, 1.0);
    const double e = offset_for(lin, 35e3, 0.04, deformation_excess);
    EXPECT_NEAR(solve(lin, {35e3, 0.5 * lin.supports[3].height + e}).upper_share, 0.04,
                kLinearShareTol);
  }
}

TEST(WarpPaper, DeformationRatioOverTheShareBandIsTheBandTheDocQuotes) {
  // docs/models/warp.md quotes the n = 2 deformation excess for L1 fitted to the ends of the
  // thesis' share band (7 % and 19 %) over the whole input band: this pins that range.
  double lo = 1.0, hi = 0.0, lo_at_19 = 1.0;
  for_each_n2_hinge([&](const Warp& w, double f) {
    for (double share : {0.07, 0.19}) {
      const double e = offset_for_share(w, f, share);
      const double x = deformation_excess(solve(w, {f, 0.5 * w.supports[3].height + e}));
      lo = std::min(lo, x);
      hi = std::max(hi, x);
      if (share == 0.19) lo_at_19 = std::min(lo_at_19, x);
    }
  });
  constexpr double kQuotedRatioTol = 0.0005;  // [1] quoted to 0.1 %
  EXPECT_NEAR(lo, 0.0344, kQuotedRatioTol);   // √1.07 − 1: rigid roller, equal joints
  EXPECT_NEAR(hi, 0.1244, kQuotedRatioTol);
  constexpr double kThesisDeformation = 0.04;  // [1] conclusion 6: ~4 % more deformation
  constexpr double kLeastAt19 = 0.09;          // [1] the doc's 9–12 % at a 19 % share
  EXPECT_LT(lo, kThesisDeformation);  // 4 % lies inside only near the low end of the share band
  EXPECT_GT(lo_at_19, kLeastAt19);    // at 19 % the upper hinges deform 9–12 % more, not 4 %
}

TEST(WarpPaper, MeasuredDifferenceOf1_4kNFromTheFourPercentDeformation) {
  // §1.4: tensometry gives an upper–lower difference reaching 1.4 kN (the load is not stated).
  // The share and the difference are NOT independent in the model: all four joints react F, so
  // difference = F·s/(2 + s) for any s; fitting L1 to the share and asserting the difference
  // would be arithmetic. What is tested instead: with L1 fitted to the 4 % deformation (the
  // other number of conclusion 6), the n = 2 model predicts 1.11–1.47 kN at F = 30–40 kN,
  // which brackets 1.4 kN; the linear law cannot reach 1.4 kN at any F up to 45 kN.
  const Warp lr = hinge(0.024, 0.008, 0.040, 2e13, 2.0);
  auto difference = [](const Warp& w, double f) {
    const double e = offset_for(w, f, 0.04, deformation_excess);
    const WarpResult r = solve(w, {f, 0.5 * w.supports[3].height + e});
    return r.force[kF12] + r.force[kF22] - r.force[kF11] - r.force[kF21];
  };
  const double d30 = difference(lr, 30e3), d40 = difference(lr, 40e3);
  constexpr double kQuotedForceTol = 5.0;     // [N] quoted to 0.01 kN
  EXPECT_NEAR(d30, 1113.0, kQuotedForceTol);  // [N] 1.11 kN
  EXPECT_NEAR(d40, 1468.0, kQuotedForceTol);  // [N] 1.47 kN
  EXPECT_LT(d30, 1.4e3);
  EXPECT_GT(d40, 1.4e3);
  const Warp lin = hinge(0.024, 0.008, 0.040, 2e8, 1.0);
  EXPECT_LT(difference(lin, 45e3), 1.4e3);
}

TEST(WarpPaper, RollingVersusSlidingStressConclusion7) {
  // Conclusion 7: rolling hinge (R1 = 34, R2 = 35.4 mm) contact stress at 30–40 kN ≈ half the
  // sliding hinge's specific pressure. NOT reproduced with p = R/(d·B) for any plausible d, B:
  // the Hertz stress of R1 in R2 is 2.5–7 times that pressure. The other reading (the sliding
  // figure a Hertz stress too) needs a fitted clearance:
  // HalfTheSlidingStressIsAFittedClearanceAndHoldsOver30To40kN.
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
}

TEST(WarpPaper, HalfTheSlidingStressIsAFittedClearanceAndHoldsOver30To40kN) {
  // The second reading of conclusion 7: the sliding figure is also a Hertz stress, of a pin of
  // radius r in a hole r + Δ. Δ is not printed; it is FITTED: Δ = 0.710 mm gives the ratio 0.5
  // for r = 12 mm (the doc's former 0.67 mm gives 0.514), and over pin diameters 20–30 mm the
  // fitted Δ runs 0.49–1.13 mm. What the fit did not use: the thesis says the ratio holds "at
  // 30–40 kN"; Hertz p0 ∝ √q for both, so the ratio is load-independent — checked at the
  // model's upper-joint loads for F = 30 and 40 kN.
  const catena::Elastic steel{};
  const double e = catena::contact_modulus(steel, steel);
  auto ratio = [&](double q, double r, double gap) {
    const double roll =
        catena::line_contact(q, catena::conformal_radius(0.034, 0.0354), e).peak_pressure;
    return roll / catena::line_contact(q, catena::conformal_radius(r, r + gap), e).peak_pressure;
  };
  auto fitted_gap = [&](double r) {
    double lo = 1e-5, hi = 5e-3;  // ratio falls as the gap grows
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (ratio(1e6, r, mid) > 0.5 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  constexpr double kQuotedGapTol = 0.005e-3;  // [m] Δ quoted to 0.01 mm
  constexpr double kQuotedRatioTol = 0.0005;  // [1] quoted to 3 digits
  EXPECT_NEAR(fitted_gap(0.012), 0.710e-3, kQuotedGapTol);
  EXPECT_NEAR(ratio(1e6, 0.012, 0.67e-3), 0.514, kQuotedRatioTol);
  EXPECT_NEAR(fitted_gap(0.010), 0.49e-3, kQuotedGapTol);
  EXPECT_NEAR(fitted_gap(0.015), 1.13e-3, kQuotedGapTol);
  const Warp w = hinge(0.024, 0.008, 0.040, 2e8, 1.0);
  const double mid = 0.5 * w.supports[3].height;
  const double q30 = solve(w, {30e3, mid + 1e-3}).force[kF12] / 0.008;
  const double q40 = solve(w, {40e3, mid + 1e-3}).force[kF12] / 0.008;
  constexpr double kLoadIndependenceTol = 1e-12;  // [1] the same ratio at two loads: round-off
  const double gap = fitted_gap(0.012);
  EXPECT_NEAR(ratio(q30, 0.012, gap), ratio(q40, 0.012, gap), kLoadIndependenceTol);
  constexpr double kDistinctLoads = 1.2;  // [1] the upper joint's load at 40 kN over 30 kN
  EXPECT_GT(q40, kDistinctLoads * q30);   // the loads do differ
}

}  // namespace
