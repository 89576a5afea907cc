// Orthotropic ring (seed 002): exact power-law solver against the paper's sweep, the isotropic
// Lamé solution, whole-ring equilibrium, truncation convergence and wide random inputs.
#include "catena/composite/ring.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace catena::composite;

Ring paper_ring(double alpha, double er_over_ephi) {
  Ring r;
  r.outer_radius = 10e-3;
  r.inner_radius = alpha * r.outer_radius;
  r.thickness = 1e-3;
  r.E_phi = 40e9;
  r.E_r = er_over_ephi * r.E_phi;
  r.G = 4e9;
  r.nu_phi_r = 0.28;
  r.gap = 0.02e-3;
  return r;
}

std::vector<double> grid(double alpha, int m, int points) {
  std::vector<double> rho;
  for (int i = 0; i < points; ++i) rho.push_back(alpha + (1 - alpha) * i / (points - 1.0));
  rho.back() = 1.0;
  (void)m;
  return rho;
}

[[maybe_unused]] double max_diff(const Harmonic& a, const Harmonic& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.sigma_phi.size(); ++i) {
    d = std::max(d, std::abs(a.sigma_phi[i] - b.sigma_phi[i]));
    d = std::max(d, std::abs(a.sigma_r[i] - b.sigma_r[i]));
    d = std::max(d, std::abs(a.tau[i] - b.tau[i]));
  }
  return d;
}

double max_abs(const Harmonic& a) {
  double d = 0;
  for (double v : a.sigma_phi) d = std::max(d, std::abs(v));
  return d;
}

// Isotropic n = 0 against Lamé: u = a r + b/r, σ_r(1) = 0 ⇒ b = a(1 + ν)/(1 − ν).
TEST(RingIsotropic, AxisymmetricHarmonicIsLame) {
  constexpr double kRelTol = 1e-12;             // [1] relative, round-off of the closed form
  constexpr double kHoopRelTol = 10 * kRelTol;  // [1] relative, σ_φ holds ten times less tightly
  constexpr double kStressFloorTol = 1e-6;  // [Pa] absolute floor where σ_r(1) = 0 (σ ~ 1e7 Pa)
  Ring ring = paper_ring(0.6, 1.0);
  ring.G = ring.E_phi / (2 * (1 + ring.nu_phi_r));
  const double nu = ring.nu_phi_r, E = ring.E_phi, al = 0.6;
  const double u_in = 0.5 * ring.gap / ring.outer_radius * 2.0 / M_PI;
  // u(α) = a α + b/α = u_in
  const double a = u_in / (al + (1 + nu) / (1 - nu) / al);
  const double b = a * (1 + nu) / (1 - nu);
  const auto rho = grid(al, 0, 21);
  const Harmonic h = solve_exact(ring, 0, rho);
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const double r = rho[i];
    const double sr = E / (1 - nu * nu) * ((1 + nu) * a - (1 - nu) * b / (r * r));
    const double sp = E / (1 - nu * nu) * ((1 + nu) * a + (1 - nu) * b / (r * r));
    EXPECT_NEAR(h.sigma_r[i], sr, kRelTol * std::abs(sp) + kStressFloorTol);
    EXPECT_NEAR(h.sigma_phi[i], sp, kHoopRelTol * std::abs(sp));
  }
}

// Isotropic n ≥ 2 against the Michell stress function Φ = (A ρ² + B ρ⁴ + C ρ⁻² + D) cos nφ
// (n = 2): its stresses σ_r = −(2A + 6C/ρ⁴ + 4D/ρ²), σ_φ = 2A + 12Bρ² + 6C/ρ⁴,
// τ = 2A + 6Bρ² − 6C/ρ⁴ − 2D/ρ². The exact solution must be of this form: fit A..D at four
// radii, then compare everywhere.
TEST(RingIsotropic, SecondHarmonicIsMichell) {
  constexpr double kRelTol = 1e-8;  // [1] relative to the harmonic's largest σ_φ
  Ring ring = paper_ring(0.5, 1.0);
  ring.G = ring.E_phi / (2 * (1 + ring.nu_phi_r));
  const auto rho = grid(0.5, 0, 41);
  const Harmonic h = solve_exact(ring, 2, rho);
  // σ_φ and τ at two radii give A, B, C, D (4 linear equations)
  const std::size_t i1 = 0, i2 = 40;
  auto rowp = [](double r) { return std::vector<double>{2, 12 * r * r, 6 / std::pow(r, 4), 0}; };
  auto rowt = [](double r) {
    return std::vector<double>{2, 6 * r * r, -6 / std::pow(r, 4), -2 / (r * r)};
  };
  std::vector<std::vector<double>> M = {rowp(rho[i1]), rowt(rho[i1]), rowp(rho[i2]), rowt(rho[i2])};
  std::vector<double> b = {h.sigma_phi[i1], h.tau[i1], h.sigma_phi[i2], h.tau[i2]};
  for (std::size_t k = 0; k < 4; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < 4; ++i)
      if (std::abs(M[i][k]) > std::abs(M[p][k])) p = i;
    std::swap(M[k], M[p]);
    std::swap(b[k], b[p]);
    for (std::size_t i = k + 1; i < 4; ++i) {
      const double f = M[i][k] / M[k][k];
      for (std::size_t j = k; j < 4; ++j) M[i][j] -= f * M[k][j];
      b[i] -= f * b[k];
    }
  }
  std::vector<double> x(4);
  for (std::size_t k = 4; k-- > 0;) {
    double s = b[k];
    for (std::size_t j = k + 1; j < 4; ++j) s -= M[k][j] * x[j];
    x[k] = s / M[k][k];
  }
  double scale = max_abs(h);
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const double r = rho[i];
    const double sr = -(2 * x[0] + 6 * x[2] / std::pow(r, 4) + 4 * x[3] / (r * r));
    EXPECT_NEAR(h.sigma_r[i], sr, kRelTol * scale) << r;
    EXPECT_NEAR(h.sigma_phi[i], rowp(r)[0] * x[0] + rowp(r)[1] * x[1] + rowp(r)[2] * x[2],
                kRelTol * scale);
  }
  // traction-free outer boundary, τ = 0 at the inner one
  EXPECT_NEAR(h.sigma_r.back(), 0.0, kRelTol * scale);
  EXPECT_NEAR(h.tau.front(), 0.0, kRelTol * scale);
}

// Equilibrium of the whole ring: P from σ_φ on the sections equals P from the contact pressure.
TEST(RingEquilibrium, SectionLoadEqualsContactLoad) {
  constexpr double kRelTol = 1e-9;  // [1] relative, two independent integrals of the load
  for (double al : {0.3, 0.472, 0.95})
    for (double er : {0.1, 0.25, 1.0, 3.0}) {
      const Ring ring = paper_ring(al, er);
      Options o;
      o.harmonics = 200;
      const Result r = analyse(ring, o);
      EXPECT_GT(r.load, 0.0);
      EXPECT_NEAR(r.load, r.load_contact, kRelTol * r.load) << al << " " << er;
    }
}

// The default N converges σ_φ to 0.1 % (φ = 0 everywhere, φ = π/2 outside the corner zone).
TEST(RingConvergence, DefaultHarmonicsConvergeSigmaPhi) {
  constexpr double kConvTol = 1e-3;  // [1] relative, the issue's 0.1 %
  // [1] relative to the largest |σ_φ|: a floor where σ_φ crosses zero
  constexpr double kFloorRelTol = 1e-9;
  for (double al : {0.472, 0.95})
    for (double er : {0.25, 1.0}) {
      const Ring ring = paper_ring(al, er);
      const Result base = analyse(ring);
      Options o;
      o.harmonics = 4 * base.summary.harmonics;
      const Result ref = analyse(ring, o);
      const double cutoff = ring.inner_radius + 0.05 * (ring.outer_radius - ring.inner_radius);
      double big = 0;
      for (double v : ref.sigma_phi_0) big = std::max(big, std::abs(v));
      for (std::size_t i = 0; i < ref.r.size(); ++i) {
        EXPECT_NEAR(base.sigma_phi_0[i], ref.sigma_phi_0[i],
                    kConvTol * std::abs(ref.sigma_phi_0[i]) + kFloorRelTol * big)
            << al << " " << er << " r=" << ref.r[i];
        if (ref.r[i] >= cutoff - 1e-15) {
          EXPECT_NEAR(base.sigma_phi_90[i], ref.sigma_phi_90[i],
                      kConvTol * std::abs(ref.sigma_phi_90[i]))
              << al << " " << er << " r=" << ref.r[i];
        }
      }
    }
}

// Wide random inputs: finite results, equilibrium, linear in the gap.
TEST(RingProperty, RandomRingsAreFiniteAndInEquilibrium) {
  constexpr double kRelTol = 1e-8;  // [1] relative, equilibrium and linearity in the gap
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 60; ++k) {
    Ring ring;
    ring.outer_radius = 5e-3 + 20e-3 * u(rng);
    ring.inner_radius = (0.1 + 0.85 * u(rng)) * ring.outer_radius;
    ring.thickness = 1e-3 + 5e-3 * u(rng);
    ring.E_phi = 1e9 * std::pow(10.0, 2 * u(rng));
    ring.E_r = ring.E_phi * std::pow(10.0, -1.5 + 2 * u(rng));
    ring.G = ring.E_phi * std::pow(10.0, -2 + 1.5 * u(rng));
    ring.nu_phi_r = 0.45 * u(rng) * std::min(1.0, std::sqrt(ring.E_phi / ring.E_r));
    ring.gap = 1e-3 * ring.inner_radius * (0.1 + u(rng));
    Options o;
    o.harmonics = 100;
    const Result r = analyse(ring, o);
    ASSERT_TRUE(std::isfinite(r.load));
    EXPECT_NEAR(r.load, r.load_contact, kRelTol * std::abs(r.load)) << k;
    for (double v : r.sigma_phi_90) ASSERT_TRUE(std::isfinite(v));
    for (double v : r.contact_pressure) ASSERT_TRUE(std::isfinite(v));
    Ring twice = ring;
    twice.gap *= 2;
    EXPECT_NEAR(analyse(twice, o).load, 2 * r.load, kRelTol * std::abs(r.load));
  }
}

TEST(RingValidate, ListsEveryProblem) {
  Ring bad;
  bad.inner_radius = -1;
  bad.nu_phi_r = -0.1;
  const auto issues = validate(bad);
  EXPECT_GE(issues.size(), 7u);
  EXPECT_THROW(analyse(bad), catena::InputError);
}

// The paper's sweep (6)–(8) converges to the exact power-law solution at second order: the
// error of σ_r, σ_φ, τ (relative to the harmonic's largest stress) falls by 4 per halving of h.
TEST(RingSweep, ConvergesToTheExactSolutionAtSecondOrder) {
  constexpr double kOrderLow = 1.85, kOrderHigh = 2.15;  // [1] observed order band
  // [1] relative to the harmonic's largest stress: the sweep at m = 800, the issue's 0.1 %
  constexpr double kFineErrorTol = 1e-3;
  for (double al : {0.472, 0.95})
    for (double er : {0.25, 1.0})
      for (int n : {0, 2, 4, 10}) {
        const Ring ring = paper_ring(al, er);
        const auto rho = grid(al, 0, 21);
        const Harmonic ex = solve_exact(ring, n, rho);
        double big = 0;
        for (std::size_t i = 0; i < rho.size(); ++i)
          big = std::max({big, std::abs(ex.sigma_phi[i]), std::abs(ex.sigma_r[i])});
        std::vector<double> err;
        for (int m : {200, 400, 800}) {
          const Harmonic sw = solve_sweep(ring, n, m, rho);
          double e = 0;
          for (std::size_t i = 0; i < rho.size(); ++i)
            e = std::max({e, std::abs(sw.sigma_phi[i] - ex.sigma_phi[i]),
                          std::abs(sw.sigma_r[i] - ex.sigma_r[i]),
                          std::abs(sw.tau[i] - ex.tau[i])});
          err.push_back(e / big);
        }
        for (std::size_t k = 1; k < err.size(); ++k) {
          const double order = std::log2(err[k - 1] / err[k]);
          EXPECT_GT(order, kOrderLow) << "alpha " << al << " Er/Ephi " << er << " n " << n;
          EXPECT_LT(order, kOrderHigh) << "alpha " << al << " Er/Ephi " << er << " n " << n;
        }
        EXPECT_LT(err.back(), kFineErrorTol) << al << " " << er << " " << n;
      }
}

// With its defaults the sweep gives the exact solver's σ_φ to the issue's 0.1 % (φ = 0, and
// φ = π/2 outside the corner zone), the same load, and a Richardson estimate that is the
// size of the error it estimates.
TEST(RingSweep, DefaultsAgreeWithTheExactSolverAndRichardsonEstimatesTheError) {
  constexpr double kAgreeTol = 1e-3;  // [1] relative to the largest checked σ_φ
  for (double al : {0.472, 0.95})
    for (double er : {0.25, 1.0}) {
      const Ring ring = paper_ring(al, er);
      const Result ex = analyse(ring);
      Options o;
      o.method = Method::kSweep;
      const Result sw = analyse(ring, o);
      ASSERT_EQ(sw.summary.harmonics, ex.summary.harmonics);
      EXPECT_GT(sw.summary.nodes, 0);
      const double cutoff = ring.inner_radius + 0.05 * (ring.outer_radius - ring.inner_radius);
      double big = 0, err = 0;
      for (std::size_t i = 0; i < ex.r.size(); ++i) {
        big = std::max(big, std::abs(ex.sigma_phi_0[i]));
        err = std::max(err, std::abs(sw.sigma_phi_0[i] - ex.sigma_phi_0[i]));
        if (ex.r[i] >= cutoff - 1e-15) {
          big = std::max(big, std::abs(ex.sigma_phi_90[i]));
          err = std::max(err, std::abs(sw.sigma_phi_90[i] - ex.sigma_phi_90[i]));
        }
      }
      EXPECT_LT(err / big, kAgreeTol) << al << " " << er;
      EXPECT_NEAR(sw.load, ex.load, kAgreeTol * ex.load);
      // the estimate (relative to the mean stress) against the true error (same measure)
      const double actual = err / std::abs(ex.mean_stress);
      EXPECT_GT(sw.summary.richardson_error, 0.0);
      EXPECT_GT(sw.summary.richardson_error, 0.5 * actual) << al << " " << er;
      EXPECT_LT(sw.summary.richardson_error, 2.0 * actual) << al << " " << er;
    }
}

// Unilateral contact: where the bilateral solution pulls, the ring separates. The minimum of
// strain energy over the larger admissible set is lower, and with the energy = ½·P·δ identity
// (Clapeyron; no work where the ring is free) the load for the same opening cannot rise.
// Pressure no longer pulls (to the collocation's resolution), equilibrium still holds, and the
// contact angle is stable under refinement.
TEST(RingUnilateral, SeparatesWhereTheBilateralPullsAndCarriesNoMore) {
  constexpr double kPullTol = 0.03;  // [1] of the mean stress, between collocation points
  constexpr double kRelTol = 1e-9;   // [1] relative, two independent integrals of the load
  constexpr double kAngleTol = 1.5 * M_PI / 180;  // [rad] 1.5°: the contact angle, 160 → 320 terms
  constexpr double kRefineRelTol = 2e-3;          // [1] relative, the load from 160 to 320 terms
  for (double er : {0.25, 1.0}) {
    Ring ring = paper_ring(0.472, er);
    if (er == 1.0) ring.G = ring.E_phi / (2 * (1 + ring.nu_phi_r));
    Options o;
    o.harmonics = 160;
    const Result bi = analyse(ring, o);
    o.unilateral = true;
    const Result uni = analyse(ring, o);
    EXPECT_LT(uni.contact_angle, 0.5 * M_PI);
    EXPECT_GT(uni.contact_angle, 0.25 * M_PI);
    EXPECT_LE(uni.load, bi.load);
    EXPECT_NEAR(uni.load, uni.load_contact, kRelTol * uni.load);
    for (std::size_t j = 0; j < uni.contact_pressure.size(); ++j) {
      EXPECT_GT(uni.contact_pressure[j], -kPullTol * uni.mean_stress) << uni.contact_phi[j];
      if (uni.contact_phi[j] > uni.contact_angle + 0.05) {  // well inside the free zone
        EXPECT_NEAR(uni.contact_pressure[j], 0.0, kPullTol * uni.mean_stress);
      }
    }
    o.harmonics = 320;
    const Result fine = analyse(ring, o);
    EXPECT_NEAR(fine.contact_angle, uni.contact_angle, kAngleTol) << er;
    EXPECT_NEAR(fine.load, uni.load, kRefineRelTol * uni.load) << er;
  }
}

// The quarter-ring field is the same series: its φ = 0 and φ = π/2 rows are the sections, its
// inner column is minus the contact pressure, τ vanishes on both symmetry sections, and σ_r and τ
// vanish on the free outer edge.
TEST(RingField, AgreesWithSectionsContactAndFreeEdges) {
  constexpr double kFieldRelTol = 1e-9 * 100;  // [1] of the mean stress: the same series twice
  constexpr double kEdgeRelTol = 1e-6;  // [1] of the mean stress: tractions the series truncates
  const Ring ring = paper_ring(0.6, 0.5);
  Options o;
  o.harmonics = 120;
  const Result r = analyse(ring, o);
  ASSERT_EQ(r.field_sigma_phi.size(), r.contact_phi.size());
  const double tol = kFieldRelTol * r.mean_stress;
  const std::size_t last = r.contact_phi.size() - 1, np = r.r.size();
  for (std::size_t i = 0; i < np; ++i) {
    EXPECT_NEAR(r.field_sigma_phi[0][i], r.sigma_phi_0[i], tol);
    EXPECT_NEAR(r.field_sigma_r[0][i], r.sigma_r_0[i], tol);
    EXPECT_NEAR(r.field_sigma_phi[last][i], r.sigma_phi_90[i], tol);
    EXPECT_NEAR(r.field_tau[0][i], 0.0, tol);
    EXPECT_NEAR(r.field_tau[last][i], 0.0, tol);
  }
  for (std::size_t j = 0; j <= last; ++j) {
    EXPECT_NEAR(r.field_sigma_r[j][0], -r.contact_pressure[j], tol);
    EXPECT_NEAR(r.field_sigma_r[j][np - 1], 0.0, kEdgeRelTol * r.mean_stress);
    EXPECT_NEAR(r.field_tau[j][np - 1], 0.0, kEdgeRelTol * r.mean_stress);
    EXPECT_NEAR(r.field_tau[j][0], 0.0, kEdgeRelTol * r.mean_stress);  // smooth half-discs
  }
}

TEST(RingValidate, OptionsListEveryProblem) {
  Options o;
  o.harmonics = 1;
  o.nodes = 5;
  o.points = 20;
  const auto issues = validate(o);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "harmonics");
  EXPECT_EQ(issues[1].field, "nodes");
  EXPECT_EQ(issues[2].field, "points");
  Options sweep;
  sweep.method = Method::kSweep;
  EXPECT_TRUE(validate(sweep).empty());
}

}  // namespace
