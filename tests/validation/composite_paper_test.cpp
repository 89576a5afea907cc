// Seed 002's stated results for the orthotropic ring, checked against the exact solver.
//
// The paper gives its results as ratios read off figures 1–2 for α = 0.472 and 0.95,
// E_r/E_φ = 0.25 and 1 ("isotropic"), without G, ν, the number of harmonics p or the grid m.
// Two readings of the isotropic ring are held side by side: G = 0.1·E_φ kept from the
// orthotropic ring (the example, G = 4 GPa with E_φ = 40 GPa), and a truly isotropic
// G = E/(2(1 + ν)). Two normalisations: the same opening 2δ (absolute stresses) and the same
// load (stress / mean stress). Where a statement concerns the inner fibre at φ = π/2 — the
// corner where the half-discs meet, where σ_φ grows without bound with the harmonics — it
// depends on the truncation, so the paper's p matters; p ≈ 20 is what its shear statement
// points to (ShearPeakLiesWhereThePaperPutsIt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "catena/composite/ring.hpp"

namespace {

using namespace catena::composite;

// [1] absolute on the growth ratios (one percentage point): the values below are pinned to show
// change
constexpr double kPinTol = 0.01;
constexpr double kCornerRatioTol = 0.03;  // [1] pinned corner ratios (they move with p)
constexpr double kEquilibriumTol = 1e-6;  // [1] Σσ̃_r ≈ 1.38 against the equilibrium identity

Ring ring(double alpha, double er, bool isotropic_G) {
  Ring r;
  r.outer_radius = 10e-3;
  r.inner_radius = alpha * r.outer_radius;
  r.thickness = 1e-3;
  r.E_phi = 40e9;
  r.E_r = er * r.E_phi;
  r.G = isotropic_G ? r.E_phi / (2 * (1 + 0.28)) : 4e9;
  r.nu_phi_r = 0.28;
  r.gap = 0.02e-3;
  return r;
}

Result solve(const Ring& r, int harmonics = 0, int points = 101) {
  Options o;
  o.harmonics = harmonics;
  o.points = points;
  return analyse(r, o);
}

// "for α = 0.472 at φ = 0 with E_r/E_φ = 0.25 the maximum stresses at the inner fibre grow by
// 40 % compared with the isotropic ring": the growth depends on the reading, 10 % to 92 %; 40 %
// lies inside that band but no single reading gives it (NOT reproduced as a number).
TEST(CompositePaper, FortyPercentAtPhiZeroDependsOnTheReading) {
  const Result ortho = solve(ring(0.472, 0.25, false));
  const Result iso_g = solve(ring(0.472, 1.0, false));  // G = 0.1 E_phi kept
  const Result iso = solve(ring(0.472, 1.0, true));     // G = E/(2(1 + ν))
  auto inner = [](const Result& r) { return r.sigma_phi_0.front(); };
  auto inner_n = [](const Result& r) { return r.sigma_phi_0.front() / r.mean_stress; };
  // the maximum at φ = 0 is at the inner fibre in every case
  for (const Result* r : {&ortho, &iso_g, &iso})
    EXPECT_DOUBLE_EQ(inner(*r), *std::max_element(r->sigma_phi_0.begin(), r->sigma_phi_0.end()));
  const double same_gap_g = inner(ortho) / inner(iso_g) - 1;       // +9.8 %
  const double same_gap_iso = inner(ortho) / inner(iso) - 1;       // +35.5 %
  const double same_load_g = inner_n(ortho) / inner_n(iso_g) - 1;  // +47.7 %
  const double same_load_iso = inner_n(ortho) / inner_n(iso) - 1;  // +92.2 %
  EXPECT_NEAR(same_gap_g, 0.098, kPinTol);
  EXPECT_NEAR(same_gap_iso, 0.355, kPinTol);
  EXPECT_NEAR(same_load_g, 0.477, kPinTol);
  EXPECT_NEAR(same_load_iso, 0.922, kPinTol);
  const double lo = std::min({same_gap_g, same_gap_iso, same_load_g, same_load_iso});
  const double hi = std::max({same_gap_g, same_gap_iso, same_load_g, same_load_iso});
  EXPECT_LT(lo, 0.40);
  EXPECT_GT(hi, 0.40);
  // nearest readings: same opening with a truly isotropic ring (35.5 %), same load with G kept
  // (47.7 %); neither within 5 points of 40 %
  EXPECT_GT(std::abs(same_gap_iso - 0.40), 0.04);
  EXPECT_GT(std::abs(same_load_g - 0.40), 0.04);
}

// "for thin rings (α = 0.95) the distribution is uniform" (φ = 0): reproduced, within 1 %.
TEST(CompositePaper, ThinRingIsUniformAtPhiZero) {
  constexpr double kUniformTol = 0.01;  // [1] max/min − 1 of σ_φ: "uniform" to 1 %
  for (double er : {0.25, 1.0}) {
    const Result r = solve(ring(0.95, er, false));
    const auto [mn, mx] = std::minmax_element(r.sigma_phi_0.begin(), r.sigma_phi_0.end());
    EXPECT_LT(*mx / *mn - 1, kUniformTol) << er;
  }
}

// "at φ = π/2 the maximum hoop stresses at the inner fibres grow 2.9 times (E/E_φ = 1) and
// 4 times (E_r/E_φ = 0.25) from α = 0.95 to α = 0.472". The inner fibre there is the singular
// corner: the ratio changes with the number of harmonics, so without the paper's p it cannot be
// reproduced as a number. What holds in every reading at equal load: the ratio is larger for
// the more orthotropic ring (conclusion 2), and it exceeds 1 (conclusion 1, thick rings are
// less uniform).
TEST(CompositePaper, CornerRatiosDependOnTruncationButKeepThePapersOrder) {
  auto corner_ratio = [](double er, bool iso_g, int n) {
    const Result thick = solve(ring(0.472, er, iso_g), n);
    const Result thin = solve(ring(0.95, er, iso_g), n);
    return (thick.corner_sigma_phi / thick.mean_stress) /
           (thin.corner_sigma_phi / thin.mean_stress);
  };
  auto k_ratio = [](double er, bool iso_g) {
    return solve(ring(0.472, er, iso_g)).stress_concentration /
           solve(ring(0.95, er, iso_g)).stress_concentration;
  };
  // p = 20 (the shear statement's truncation): 2.99 (0.25) and 2.32 / 2.77 (isotropic readings)
  const double ortho20 = corner_ratio(0.25, false, 20);
  const double iso20_g = corner_ratio(1.0, false, 20);
  const double iso20 = corner_ratio(1.0, true, 20);
  EXPECT_NEAR(ortho20, 2.99, kCornerRatioTol);
  EXPECT_NEAR(iso20_g, 2.32, kCornerRatioTol);
  EXPECT_NEAR(iso20, 2.77, kCornerRatioTol);
  EXPECT_GT(ortho20, iso20_g);
  EXPECT_GT(ortho20, iso20);
  // the paper's 4× for E_r/E_φ = 0.25 is not reached at p = 20 (2.99); at p = 10 it is 3.05:
  // the corner value moves with p, and p is not printed
  EXPECT_GT(std::abs(ortho20 - 4.0), 0.9);
  EXPECT_NE(corner_ratio(0.25, false, 10), ortho20);
  // converged, outside the corner zone (r ≥ r1 + 5 %): 1.57 (0.25) > 1.23 / 1.21 (isotropic)
  constexpr double kConcentrationRatioTol = 0.02;  // [1] the pinned converged ratio 1.574
  const double k_ortho = k_ratio(0.25, false);
  EXPECT_NEAR(k_ortho, 1.574, kConcentrationRatioTol);
  EXPECT_GT(k_ortho, k_ratio(1.0, false));
  EXPECT_GT(k_ortho, k_ratio(1.0, true));
  EXPECT_GT(k_ratio(1.0, true), 1.0);
}

// "the largest shear stress (E/E_φ = 1) lies at 0.1 of the thickness from the inner surface, in
// the section φ = 0.9·π/2, and is an order of magnitude below the normal stresses":
// reproduced with p = 20 harmonics (both isotropic readings); with the converged default N the
// peak moves into the corner (depth → 0, φ → π/2), so the statement is one about p = 20.
TEST(CompositePaper, ShearPeakLiesWhereThePaperPutsIt) {
  constexpr double kDepthTol = 0.02;  // [1] of the thickness: the paper's "0.1", read off a figure
  constexpr double kPhiDegTol = 2.0;  // [°] the paper's 0.9·π/2 = 81°, compared in degrees
  for (bool iso_g : {false, true}) {
    const Ring rg = ring(0.472, 1.0, iso_g);
    const Result r = solve(rg, 20);
    const double depth = (r.max_shear_r - rg.inner_radius) / (rg.outer_radius - rg.inner_radius);
    const double phi_deg = r.max_shear_phi * 180 / M_PI;
    EXPECT_NEAR(depth, 0.10, kDepthTol) << iso_g;
    EXPECT_NEAR(phi_deg, 81.0, kPhiDegTol) << iso_g;
    const double normal = r.stress_concentration * r.mean_stress;
    const double ratio = normal / std::abs(r.max_shear);
    EXPECT_GT(ratio, 5.0) << iso_g;  // 6.6 (G isotropic) and 11.2 (G = 0.1 E_φ)
    EXPECT_LT(ratio, 15.0) << iso_g;
    const Result converged = solve(rg);
    const double d_conv =
        (converged.max_shear_r - rg.inner_radius) / (rg.outer_radius - rg.inner_radius);
    EXPECT_LE(d_conv, 0.05) << iso_g;  // inside the corner zone r < r1 + 5 %
    EXPECT_GE(converged.max_shear_phi * 180 / M_PI, 87.5) << iso_g;
  }
}

// Conclusion 3: the largest hoop stress is at the extreme point of contact (r1, π/2).
TEST(CompositePaper, LargestHoopStressIsAtTheEndOfContact) {
  for (double al : {0.472, 0.95})
    for (double er : {0.25, 1.0}) {
      const Result r = solve(ring(al, er, false), 20);
      const double at0 = *std::max_element(r.sigma_phi_0.begin(), r.sigma_phi_0.end());
      const double at90 = *std::max_element(r.sigma_phi_90.begin(), r.sigma_phi_90.end());
      EXPECT_DOUBLE_EQ(at90, r.corner_sigma_phi) << al << " " << er;
      EXPECT_GT(r.corner_sigma_phi, at0) << al << " " << er;
    }
}

// The capacity example's K_σmax = 4.173 (α = 0.42) reads as a corner value: our corner σ_φ/mean
// at α = 0.42 depends on p and the reading — isotropic ring with G = E/(2(1 + ν)): 4.07 (p = 10)
// → 4.23 (p = 12); G = 0.1·E_φ: 3.35 (p = 10) → 4.20 (p = 40); E_r/E_φ = 0.25: 4.57 (p = 10) →
// 5.66 (p = 40) — while the converged concentration outside the corner zone is 2.3–3.0. Σσ̃_r
// with our normalisation (σ̃_r = pressure / mean stress) is the equilibrium identity
// (1 − α)/α = 1.381, not 0.2662: the paper normalises σ̃_r differently (docs/models/composite.md).
TEST(CompositePaper, CapacityExampleConstantsAreCornerValuesAndAnotherNormalisation) {
  const Ring r42 = ring(0.42, 0.25, false);
  const Result conv = solve(r42);
  EXPECT_NEAR(conv.sum_sigma_r, (1 - 0.42) / 0.42, kEquilibriumTol);
  EXPECT_GT(std::abs(conv.sum_sigma_r - 0.2662), 1.0);
  EXPECT_LT(conv.stress_concentration, 3.1);
  auto corner = [](const Ring& r, int n) {
    const Result x = solve(r, n);
    return x.corner_sigma_phi / x.mean_stress;
  };
  const Ring iso42 = ring(0.42, 1.0, true);
  EXPECT_LT(corner(iso42, 10), 4.173);
  EXPECT_GT(corner(iso42, 12), 4.173);
  EXPECT_GT(corner(r42, 10), 4.173);  // the orthotropic reading is above it at any p ≥ 10
}

}  // namespace
