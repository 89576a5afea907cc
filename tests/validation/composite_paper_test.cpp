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

#include "catena/composite/capacity.hpp"
#include "catena/composite/ring.hpp"

namespace {

using namespace catena::composite;

// [1] absolute on the growth ratios (one percentage point): the values below are pinned to show
// change
constexpr double kPinTol = 0.01;
constexpr double kCornerRatioTol = 0.03;  // [1] pinned corner ratios (they move with p)
constexpr double kEquilibriumTol = 1e-6;  // [1] Σσ̃_r ≈ 1.38 against the equilibrium identity
constexpr double kRangeTol = 0.002;       // [1] pinned ends of the reading ranges (0.2 point)

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
// 40 % compared with the isotropic ring": READING-DEPENDENT. The paper prints neither ν nor G,
// nor whether the rings are compared at the same opening or the same load. Readings: ν of the
// isotropic ring and ν_φr of the orthotropic one each 0.28 or 0.30; G of the isotropic ring
// E/(2(1 + ν)) or kept at 0.1·E_φ; same opening 2δ or same load. Ranges (pinned):
//   same opening, G = E/(2(1 + ν)): 34.1–38.0 %    same opening, G kept: 8.7–11.5 %
//   same load,    G = E/(2(1 + ν)): 91.6–93.8 %    same load,    G kept: 47.2–48.4 %
// The nearest reading (same opening, a truly isotropic ring) reaches 38.0 % at ν = 0.30 and
// 40.2 % with ν_φr = 0.25, also a typical major Poisson ratio of glass/epoxy.
Ring ring_nu(double er, bool isotropic_G, double nu) {
  Ring r = ring(0.472, er, isotropic_G);
  r.nu_phi_r = nu;
  if (isotropic_G) r.G = r.E_phi / (2 * (1 + nu));
  return r;
}

TEST(CompositePaper, FortyPercentAtPhiZeroIsInsideTheRangeOfTheReadings) {
  auto inner = [](const Result& r) { return r.sigma_phi_0.front(); };
  auto inner_n = [](const Result& r) { return r.sigma_phi_0.front() / r.mean_stress; };
  struct Range {
    double lo = 1e9, hi = -1e9;
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  } gap_iso, gap_g, load_iso, load_g;
  for (double nu_ortho : {0.28, 0.30}) {
    const Result ortho = solve(ring_nu(0.25, false, nu_ortho));
    // the maximum at φ = 0 is at the inner fibre
    EXPECT_DOUBLE_EQ(inner(ortho),
                     *std::max_element(ortho.sigma_phi_0.begin(), ortho.sigma_phi_0.end()));
    double previous_gap_iso = -1;
    for (double nu : {0.28, 0.30}) {
      const Result iso = solve(ring_nu(1.0, true, nu));
      const Result iso_g = solve(ring_nu(1.0, false, nu));
      gap_iso.add(inner(ortho) / inner(iso) - 1);
      gap_g.add(inner(ortho) / inner(iso_g) - 1);
      load_iso.add(inner_n(ortho) / inner_n(iso) - 1);
      load_g.add(inner_n(ortho) / inner_n(iso_g) - 1);
      // a larger ν makes the isotropic ring softer in shear (G = E/(2(1 + ν))): its stress at
      // the same opening drops, the growth rises
      const double g = inner(ortho) / inner(iso) - 1;
      EXPECT_GT(g, previous_gap_iso) << nu_ortho << " " << nu;
      previous_gap_iso = g;
    }
  }
  EXPECT_NEAR(gap_iso.lo, 0.341, kRangeTol);
  EXPECT_NEAR(gap_iso.hi, 0.380, kRangeTol);  // ν = 0.30, ν_φr = 0.28
  EXPECT_NEAR(gap_g.lo, 0.087, kRangeTol);
  EXPECT_NEAR(gap_g.hi, 0.115, kRangeTol);
  EXPECT_NEAR(load_iso.lo, 0.916, kRangeTol);
  EXPECT_NEAR(load_iso.hi, 0.938, kRangeTol);
  EXPECT_NEAR(load_g.lo, 0.472, kRangeTol);
  EXPECT_NEAR(load_g.hi, 0.484, kRangeTol);
  // the paper's 40 % lies inside the band of the readings, between the same-opening and the
  // same-load readings, and within 2.5 points of the nearest one (a value read off a figure)
  constexpr double kFigureReadTol = 0.025;  // [1] two and a half percentage points
  EXPECT_LT(gap_iso.hi, 0.40);
  EXPECT_GT(load_g.lo, 0.40);
  EXPECT_LT(0.40 - gap_iso.hi, kFigureReadTol);
  // with ν_φr = 0.25 for the wound ring (ν = 0.30 for the isotropic one) the reading gives 40 %
  const double nu25 =
      inner(solve(ring_nu(0.25, false, 0.25))) / inner(solve(ring_nu(1.0, true, 0.30))) - 1;
  EXPECT_NEAR(nu25, 0.402, kRangeTol);
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
  // no common truncation p = 10…380 gives the paper's numbers: 2.80–3.05 for E_r/E_φ = 0.25
  // (not 4), 2.14–2.35 (G kept) and 2.27–2.83 (G = E/(2(1 + ν))) for the isotropic ring (not 2.9)
  // [1] upper ends of the scanned ranges, rounded up: every one short of the paper's 4 and 2.9
  constexpr double kOrthoCornerMax = 3.1, kIsoKeptGCornerMax = 2.4, kIsoCornerMax = 2.85;
  for (int p : {10, 12, 20, 40, 80, 160, 380}) {
    EXPECT_LT(corner_ratio(0.25, false, p), kOrthoCornerMax) << p;
    EXPECT_LT(corner_ratio(1.0, false, p), kIsoKeptGCornerMax) << p;
    EXPECT_LT(corner_ratio(1.0, true, p), kIsoCornerMax) << p;
  }
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

// Eq. (4) AS PRINTED: one G1 in both equations. With V = a ρ^λ, W = b ρ^λ the pair (4) is
// algebraic; its determinant is c11·g·μ² − (c11·B + g·A − n²D6²)·μ + A·B − n²D7² (μ = λ²),
// A and B the coefficients of V in the first and of W in the second equation. Derived
// (composite.md): A = D1 + n²D4, B = D4 + n²D1 — printed: A = B = G1. For an isotropic ring and
// n = 2 the classical (Michell) displacements go like ρ^{±1}, ρ^{±3}: μ = 1 and 9 must be roots.
// The derived pair has them; the printed one, with either reading of G1, does not — unless
// D1 = D4 (c22 = g), where the two coincide. Catena's own exact solver uses the derived pair
// (RingIsotropic.SecondHarmonicIsMichell checks its stresses against Michell's).
struct Eq4 {
  double c11, c12, c22, g;
  // the determinant at μ for coefficients A (first equation) and B (second), harmonic n
  double det(double mu, double a, double b, double n) const {
    const double d6 = c12 + g, d7 = c22 + g;
    return c11 * g * mu * mu - (c11 * b + g * a - n * n * d6 * d6) * mu + a * b - n * n * d7 * d7;
  }
  double derived(double mu, double n) const { return det(mu, c22 + n * n * g, g + n * n * c22, n); }
  double printed(double mu, double n, double g1) const { return det(mu, g1, g1, n); }
};

Eq4 stiffness_of(double er, double g_over_ephi, double nu_phi_r) {
  const double det = 1 - nu_phi_r * nu_phi_r * er;  // ν_rφ = ν_φr·E_r/E_φ (Maxwell–Betti)
  return {er / det, nu_phi_r * er / det, 1 / det, g_over_ephi};
}

TEST(CompositePaper, Eq4AsPrintedWithOneG1MissesMichellUnlessD1EqualsD4) {
  constexpr double kRootTol = 1e-12;   // [1] determinant at an exact root, relative to its scale
  constexpr double kMissFloor = 0.05;  // [1] the printed form misses by more than 5 % of the scale
  const double nu = 0.28, n = 2;
  const Eq4 iso = stiffness_of(1.0, 1 / (2 * (1 + nu)), nu);
  // scale of the determinant: its constant term for the derived coefficients
  const double scale = std::abs(iso.derived(0, n));
  for (double mu : {1.0, 9.0}) {
    EXPECT_NEAR(iso.derived(mu, n) / scale, 0.0, kRootTol) << mu;
    for (double g1 : {iso.c22 + n * n * iso.g, iso.g + n * n * iso.c22})  // either reading
      EXPECT_GT(std::abs(iso.printed(mu, n, g1)) / scale, kMissFloor) << mu << " " << g1;
  }
  // the orthotropic ring of the paper's figures (E_r/E_φ = 0.25, G = 0.1·E_φ): at μ = 1 the
  // printed determinant differs from the derived one by 93 % (n = 20) to 2200 % (n = 2)
  constexpr double kOrthoMiss = 0.5;  // [1] relative difference of the determinants, lower bound
  const Eq4 ortho = stiffness_of(0.25, 0.1, nu);
  for (int k = 2; k <= 20; k += 2) {
    const double nk = k, g1 = ortho.c22 + nk * nk * ortho.g;
    const double derived = ortho.derived(1.0, nk);
    EXPECT_GT(std::abs(ortho.printed(1.0, nk, g1) - derived) / std::abs(derived), kOrthoMiss) << k;
  }
  // With c22 = g (G = E_φ/Δ) the single G1 is exact: that is algebra on the two forms above
  // (c22 + n²g = g + n²c22), not something a test of them could show.
}

// Eq. (9) AS PRINTED, P_max = Σσ̃_r/(α(1 − α)K)·2Fσ^a, evaluated by hand here (not through
// capacity()), next to the capacity from the stress concentration P = 2Fσ^a/K
// (composite_capacity.md (C)): (9) = (C)·Σσ̃_r/(α(1 − α)). The paper's example (α = 0.42,
// Σσ̃_r = 0.2662, K = 4.173, σ^a = 2500 MPa, P = 29 700 N) implies F = 22.68 mm² and a factor
// 1.0928 above (C); with Catena's own Σσ̃_r = (1 − α)/α (σ̃_r = pressure/mean stress) the
// printed (9) exceeds (C) by 1/α² = 5.67 and even the uniform-stress strength 2Fσ^a — so the
// paper's σ̃_r cannot be normalised by the mean stress; (9) and (C) agree only at
// Σσ̃_r = α(1 − α).
TEST(CompositePaper, Eq9AsPrintedAgainstTheCapacityFromTheConcentration) {
  constexpr double kAreaTol = 0.01e-6;  // [m²] 0.01 mm², the inferred F to the printed digits
  constexpr double kRelTol = 1e-12;     // [1] the library against the hand evaluation
  constexpr double kFactorTol = 1e-4;   // [1] 1.0928, printed to four decimals
  const double alpha = 0.42, sum = 0.2662, k = 4.173, sigma_a = 2500e6, p_paper = 29700;
  auto eq9_printed = [](double a, double s, double kk, double f, double sig) {
    return s / (a * (1 - a) * kk) * 2 * f * sig;  // 002 eq. (9) as printed
  };
  const double f = p_paper / eq9_printed(alpha, sum, k, 1.0, sigma_a);
  EXPECT_NEAR(f, 22.68e-6, kAreaTol);
  EXPECT_NEAR(capacity(Eq9{alpha, sum, k, sigma_a}, f) / p_paper - 1, 0.0, kRelTol);
  const double c_form = capacity_from_concentration(f, sigma_a, k);  // (C), F per leg
  EXPECT_NEAR(eq9_printed(alpha, sum, k, f, sigma_a) / c_form, 1.0928, kFactorTol);
  EXPECT_NEAR(eq9_printed(alpha, consistent_sum_sigma_r(alpha), k, f, sigma_a) / c_form, 1.0,
              kRelTol);
  // Catena's solved ring at α = 0.42 (E_r/E_φ = 0.25): its Σσ̃_r and K in the printed (9)
  const Result r = solve(ring(alpha, 0.25, false));
  const double ours = eq9_printed(alpha, r.sum_sigma_r, r.stress_concentration, f, sigma_a);
  const double c_ours = capacity_from_concentration(f, sigma_a, r.stress_concentration);
  EXPECT_NEAR(ours / c_ours, 1 / (alpha * alpha), kFactorTol);
  EXPECT_GT(ours, 2 * f * sigma_a);  // above the strength of the two legs at uniform stress
}

// "with 100 intervals of a unit segment the error was below 1 % at every node" (the sweep (6)–(8)
// on the control example of [3], not identified): READING-DEPENDENT on the harmonic and on the
// segment. Against the exact solver (α = 0.472, E_r/E_φ = 0.25, error relative to the harmonic's
// largest stress): m = 100 intervals of [α, 1]: 0.03 % (n = 0), 0.25 % (2), 0.9 % (4), 4.8 % (10);
// h = 0.01, i.e. m = 54 over [α, 1]: 0.1 %, 0.8 %, 2.9 %, 14 %.
TEST(CompositePaper, SweepWithHundredIntervalsIsBelowOnePercentForTheLowHarmonicsOnly) {
  constexpr double kPaperError = 0.01;  // [1] the paper's "below 1 %"
  const Ring r = ring(0.472, 0.25, false);
  auto error = [&](int n, int m) {
    std::vector<double> rho;
    for (int i = 0; i <= m; ++i) rho.push_back(0.472 + i * (1 - 0.472) / m);
    const Harmonic ex = solve_exact(r, n, rho);
    const Harmonic sw = solve_sweep(r, n, m, rho);
    double big = 0, e = 0;
    for (std::size_t i = 0; i < rho.size(); ++i) {
      big = std::max({big, std::abs(ex.sigma_phi[i]), std::abs(ex.sigma_r[i])});
      e = std::max({e, std::abs(sw.sigma_phi[i] - ex.sigma_phi[i]),
                    std::abs(sw.sigma_r[i] - ex.sigma_r[i]), std::abs(sw.tau[i] - ex.tau[i])});
    }
    return e / big;
  };
  for (int n : {0, 2, 4}) EXPECT_LT(error(n, 100), kPaperError) << n;
  EXPECT_GT(error(10, 100), kPaperError);
  for (int n : {0, 2}) EXPECT_LT(error(n, 54), kPaperError) << n;
  EXPECT_GT(error(4, 54), kPaperError);
}

}  // namespace
