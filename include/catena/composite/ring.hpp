// Orthotropic ring stretched by two rigid smooth half-discs (seed 002): the link of a
// fibre-reinforced polymer conveyor chain. Plane stress, cylindrical orthotropy.
//
// Radii are made dimensionless by the outer radius r2 (seed 002, after eq. (1)): ρ = r/r2,
// α = r1/r2 ≤ ρ ≤ 1; displacements by r2. Each even harmonic n of the Fourier series (3) obeys
// the Euler-type ODE pair (4), solved either exactly (powers ρ^λ) or by the paper's
// finite-difference sweep (6)–(8).
#pragma once

#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::composite {

/// The link: geometry, cylindrically orthotropic elastic constants and the imposed opening.
struct Ring {
  double inner_radius = 0.0;  ///< [m] r1
  double outer_radius = 0.0;  ///< [m] r2
  double thickness = 0.0;     ///< [m] t (plane stress)
  double E_r = 0.0;           ///< [Pa] radial Young's modulus
  double E_phi = 0.0;         ///< [Pa] hoop (fibre) Young's modulus
  double G = 0.0;             ///< [Pa] in-plane shear modulus G_rφ
  double nu_phi_r = 0.0;      ///< [-] −ε_r/ε_φ under pure hoop stress
  double gap = 0.0;           ///< [m] full opening 2δ between the half-discs
};

enum class Method { kExact, kSweep };

struct Options {
  Method method = Method::kExact;
  int harmonics = 0;  ///< highest even harmonic N; 0: default_harmonics(ring)
  int nodes = 0;      ///< sweep intervals m; 0: default_nodes(ring, N)
  int points = 41;    ///< output radii, equally spaced from r1 to r2 (odd, ≥ 21)
  /// Unilateral contact: where the bilateral solution would have the half-disc pull on the ring,
  /// the ring separates (σ_r = τ = 0 there, no penetration), found by an active-set iteration
  /// over collocation points (one per harmonic).
  bool unilateral = false;
};

std::vector<Issue> validate(const Ring& ring);
std::vector<Issue> validate(const Options& options);

/// Default highest harmonic: N = 2·ceil(5 / (0.05·(1 − α))), at least 40. Near the corner
/// (α, π/2) the terms decay like exp(−n·d/α) with d the distance from the inner radius; N·d ≈ 10
/// at d = 0.05(r2 − r1)/r2 converges σ_φ there to 0.1 % (RingConvergence tests).
int default_harmonics(const Ring& ring);
/// Default sweep intervals: enough that h·N/α ≤ 0.1 (second-order error ≈ (hN/α)²/12 < 0.1 %),
/// rounded up to a multiple of (points − 1), at least 200.
int default_nodes(const Ring& ring, int harmonics, int points);

/// Stress amplitudes of one harmonic at given dimensionless radii (σ = amplitude·cos nφ for
/// σ_r, σ_φ; τ = amplitude·sin nφ), in Pa for the imposed opening.
struct Harmonic {
  int n = 0;
  std::vector<double> sigma_r, sigma_phi, tau;
  double section_integral = 0.0;  ///< ∫_α^1 σ_φ,n dρ [Pa]
  double inner_sigma_r = 0.0;     ///< σ_r,n(α) [Pa]
  bool fallback = false;          ///< exact solver hit (nearly) repeated exponents: sweep used
};

/// Fourier coefficient of the inner displacement Δ|cos φ| (seed 002 eq. (2), (3), (5)):
/// c_0 = 2/π (the paper's G0), c_n = −(4/π)(−1)^{n/2}/(n² − 1) for even n ≥ 2.
double inner_coefficient(int n);

/// Exact per-harmonic solution (powers ρ^λ, λ² from a quadratic) at radii `rho`.
Harmonic solve_exact(const Ring& ring, int n, const std::vector<double>& rho);
/// The paper's finite-difference sweep (6)–(8) with m intervals: central differences inside,
/// second-order one-sided differences at both edges, block (2×2) forward elimination and back
/// substitution. Second order in h (RingSweep tests). `rho` must be nodes of the grid
/// (α + i(1 − α)/m); m must be even (Simpson's rule for the section integral).
Harmonic solve_sweep(const Ring& ring, int n, int m, const std::vector<double>& rho);

struct Summary {
  std::string method;
  int harmonics = 0;
  int nodes = 0;                   ///< sweep intervals (0 for the exact solver)
  int fallbacks = 0;               ///< harmonics the exact solver handed to the sweep
  double truncation_change = 0.0;  ///< max relative change of checked σ_φ from N/2 to N
  double richardson_error = 0.0;  ///< sweep: max |σ_φ(m) − σ_φ(m/2)|/3 relative to mean stress
};

struct Result {
  std::vector<double> r;                                 ///< [m] output radii, ascending
  std::vector<double> sigma_r_0, sigma_phi_0, tau_0;     ///< [Pa] section φ = 0
  std::vector<double> sigma_r_90, sigma_phi_90, tau_90;  ///< [Pa] section φ = π/2
  std::vector<double> contact_phi;                       ///< [rad] 0..π/2
  std::vector<double> contact_pressure;                  ///< [Pa] −σ_r(r1, φ); < 0 is tension
  /// [Pa] the stresses over the quarter ring: [j][i] at φ = contact_phi[j], r = r[i]
  std::vector<std::vector<double>> field_sigma_r, field_sigma_phi, field_tau;
  double load = 0.0;                  ///< [N] P from σ_φ on the two φ = π/2 sections
  double load_contact = 0.0;          ///< [N] P from the contact pressure (equilibrium check)
  double mean_stress = 0.0;           ///< [Pa] P / (2 (r2 − r1) t)
  double stress_concentration = 0.0;  ///< max σ_φ(π/2) for r ≥ r1 + 0.05(r2 − r1) / mean
  double corner_sigma_phi = 0.0;      ///< [Pa] σ_φ(r1, π/2), grows with N
  double max_shear = 0.0;             ///< [Pa] max |τ| over the quarter ring grid
  double max_shear_r = 0.0, max_shear_phi = 0.0;  ///< [m], [rad] where
  double sum_sigma_r = 0.0;  ///< ∫_0^{π/2} σ̃_r cos φ dφ with σ̃_r = −σ_r(r1)/mean (eq. (9))
  /// Unilateral contact: the half-disc touches the ring for φ < contact_angle (π/2: everywhere;
  /// bilateral: always π/2), found after `contact_iterations` active-set passes.
  double contact_angle = 0.0;  ///< [rad]
  int contact_iterations = 0;
  std::vector<Diagnostic> diagnostics;
  Summary summary;
};

/// Solves the contact problem (bilateral contact, seed 002 eq. (2)). Throws InputError.
Result analyse(const Ring& ring, const Options& options = {});

}  // namespace catena::composite
