// Capacity of a fibre-wound conveyor link (seed 002 eq. (9)), its mass against a steel plate,
// and a design helper that sizes the link for a required breaking force.
//
// Normalisation (docs/models/composite_capacity.md): ring.hpp's Result normalises stresses by
// the mean stress s = P/(2(r2 − r1)t), so its Σσ̃_r = ∫_0^{π/2} σ̃_r cos φ dφ equals (1 − α)/α
// identically (equilibrium of the half-disc, P = 2 r1 t s Σσ̃_r). Eq. (9) read with that Σσ̃_r
// would give P = 2Fσ^a/(α²K), above the uniform-stress strength 2Fσ^a for the paper's α and
// K: the paper's σ̃_r is normalised differently (it is not printed). Eq. (9) equals the
// capacity implied by the stress concentration, P = 2Fσ^a/K, exactly when Σσ̃_r = α(1 − α)
// (consistent_sum_sigma_r). The design helper uses P = 2Aσ_c/K (A = (r2 − r1)t per leg).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "catena/composite/ring.hpp"
#include "catena/core/error.hpp"

namespace catena::composite {

// ---------------------------------------------------------------------------------------------
// Eq. (9)

/// The coefficients of eq. (9) as the paper states them.
struct Eq9 {
  double alpha = 0.0;           ///< [-] r1/r2, 0 < α < 1
  double sum_sigma_r = 0.0;     ///< [-] Σσ̃_r in the paper's (unstated) normalisation
  double k_max = 0.0;           ///< [-] K_σ^max ≥ 1
  double fibre_strength = 0.0;  ///< [Pa] σ^a, tensile strength of the reinforcement
};

std::vector<Issue> validate(const Eq9& e);
/// Σσ̃_r / (α(1 − α) K_σ^max): P_max = factor · 2Fσ^a. Throws InputError.
double eq9_factor(const Eq9& e);
/// P_max = Σσ̃_r/(α(1 − α)K) · 2Fσ^a [N]; F [m²] the reinforcement area (eq. (9)).
double capacity(const Eq9& e, double fibre_area);
/// The F [m²] for which eq. (9) gives `load` [N].
double area_for_load(const Eq9& e, double load);
/// The Σσ̃_r that makes eq. (9) equal to 2Fσ^a/K (the capacity from the stress concentration
/// relative to the mean stress P/(2F)): α(1 − α). Equivalently σ̃_r = α²·σ_r/s with s the mean
/// stress of ring.hpp; ring.hpp's own Σσ̃_r is (1 − α)/α.
double consistent_sum_sigma_r(double alpha);
/// P = 2Aσ/K [N]: the load at which the hoop stress at the critical point, K times the mean
/// stress P/(2A), reaches σ. A [m²] per leg, σ [Pa], K ≥ 1.
double capacity_from_concentration(double leg_area, double strength, double k);

// ---------------------------------------------------------------------------------------------
// Micromechanics of the hoop-wound ring (fibres along φ)

struct Fibre {
  double modulus = 0.0;   ///< [Pa] E_f (isotropic fibre: E-glass)
  double poisson = 0.0;   ///< [-] ν_f
  double strength = 0.0;  ///< [Pa] σ_f, tensile
  double density = 0.0;   ///< [kg/m³]
};

struct Matrix {
  double modulus = 0.0;  ///< [Pa] E_m
  double poisson = 0.0;  ///< [-] ν_m
  double density = 0.0;  ///< [kg/m³]
};

/// Cylindrically orthotropic constants of the ring (ring.hpp's Ring fields) and its strength.
struct Lamina {
  double fibre_fraction = 0.0;  ///< [-] V_f
  double E_phi = 0.0;           ///< [Pa] rule of mixtures (Voigt)
  double E_r = 0.0;             ///< [Pa] Halpin–Tsai, ξ = 2
  double G = 0.0;               ///< [Pa] Halpin–Tsai, ξ = 1
  double nu_phi_r = 0.0;        ///< [-] rule of mixtures (major Poisson ratio ν_12)
  double strength = 0.0;        ///< [Pa] hoop: V_f σ_f + (1 − V_f) E_m σ_f/E_f
  double density = 0.0;         ///< [kg/m³] V_f ρ_f + (1 − V_f) ρ_m (no voids)
};

/// V_f·p_f + (1 − V_f)·p_m (Voigt bound).
double rule_of_mixtures(double p_fibre, double p_matrix, double fibre_fraction);
/// 1 / (V_f/p_f + (1 − V_f)/p_m) (Reuss bound).
double inverse_rule_of_mixtures(double p_fibre, double p_matrix, double fibre_fraction);
/// Halpin–Tsai: p_m (1 + ξηV_f)/(1 − ηV_f), η = (p_f/p_m − 1)/(p_f/p_m + ξ).
double halpin_tsai(double p_fibre, double p_matrix, double xi, double fibre_fraction);

/// Field names: fibre_modulus, fibre_poisson, fibre_strength, fibre_density, matrix_modulus,
/// matrix_poisson, matrix_density, fibre_fraction.
std::vector<Issue> validate(const Fibre& f, const Matrix& m, double fibre_fraction);
/// Throws InputError.
Lamina ring_lamina(const Fibre& f, const Matrix& m, double fibre_fraction);

// ---------------------------------------------------------------------------------------------
// Mass

/// The link: a wound band of cross-section (r2 − r1)·t around a stadium (two pins of radius r1,
/// centres `pitch` apart), filled between the pins by a polyamide insert of thickness t.
struct LinkGeometry {
  double inner_radius = 0.0;    ///< [m] r1 (pin)
  double outer_radius = 0.0;    ///< [m] r2
  double thickness = 0.0;       ///< [m] t (band width)
  double pitch = 0.0;           ///< [m] p, pin centre distance, p > 2 r1
  double band_density = 0.0;    ///< [kg/m³] composite
  double insert_density = 0.0;  ///< [kg/m³] polyamide
};

struct LinkMass {
  double band_length = 0.0;  ///< [m] centre line 2p + π(r1 + r2)
  double band_area = 0.0;    ///< [m²] (r2 − r1) t
  double insert_area = 0.0;  ///< [m²] face 2 r1 p − π r1² (stadium interior minus the two pins)
  double band = 0.0;         ///< [kg]
  double insert = 0.0;       ///< [kg]
  double total = 0.0;        ///< [kg]
};

std::vector<Issue> validate(const LinkGeometry& g);
LinkMass link_mass(const LinkGeometry& g);

/// A flat steel link plate carrying the same force without stress concentration (as the paper
/// rates the steel plate): net section 2·b·t_s = P/σ_B beside a pin hole of radius r_h; outline a
/// stadium of width w = 2 r_h + 2b and centre distance p, with two holes.
struct SteelPlate {
  double strength = 0.0;     ///< [Pa] σ_B
  double thickness = 0.0;    ///< [m] t_s
  double density = 7850.0;   ///< [kg/m³]
  double pitch = 0.0;        ///< [m] p
  double hole_radius = 0.0;  ///< [m] r_h
};

struct SteelPlateResult {
  double net_area = 0.0;   ///< [m²] P/σ_B
  double width = 0.0;      ///< [m] w
  double face_area = 0.0;  ///< [m²] w p + π w²/4 − 2π r_h²
  double mass = 0.0;       ///< [kg]
};

/// Field names steel_strength, steel_thickness, steel_density, pitch, hole_radius, load.
std::vector<Issue> validate(const SteelPlate& s, double load);
SteelPlateResult steel_plate(const SteelPlate& s, double load);

// ---------------------------------------------------------------------------------------------
// Design helper

struct DesignInput {
  double load = 0.0;  ///< [N] required breaking force P
  Fibre fibre;
  Matrix matrix;
  double fibre_fraction = 0.0;     ///< [-] V_f
  double thickness = 0.0;          ///< [m] t, band width: given; r2 follows
  double pitch = 0.0;              ///< [m] p
  double insert_density = 1130.0;  ///< [kg/m³] PA6
  std::vector<double> alphas;      ///< r1/r2 to try; empty: 0.30, 0.35, …, 0.90
  double steel_strength = 0.0;     ///< [Pa]; 0: no steel comparison
  double steel_thickness = 0.0;    ///< [m]
  double steel_density = 7850.0;
  Options analysis;  ///< ring solver options (exact method)
};

struct DesignPoint {
  double alpha = 0.0;
  double k = 0.0;             ///< stress concentration (ring.hpp Result)
  double sum_sigma_r = 0.0;   ///< ring.hpp normalisation: (1 − α)/α
  double leg_area = 0.0;      ///< [m²] A = PK/(2σ_c)
  double fibre_area = 0.0;    ///< [m²] V_f A (F of eq. (9))
  double inner_radius = 0.0;  ///< [m] r1
  double outer_radius = 0.0;  ///< [m] r2 = A/((1 − α)t)
  LinkMass mass;
  bool feasible = true;  ///< p > 2 r1: the pins clear each other, the insert exists
};

struct Design {
  Lamina lamina;
  std::vector<DesignPoint> scan;
  std::size_t best = 0;  ///< index into scan: the feasible point of least mass
  bool has_steel = false;
  SteelPlateResult steel;
  double mass_ratio = 0.0;              ///< steel / composite (0 without steel)
  std::vector<Diagnostic> diagnostics;  ///< the chosen α's ring analysis, then the design's
};

/// Field names as the CLI flags: load, fibre_*, matrix_*, fibre_fraction, thickness, pitch,
/// insert_density, alpha, steel_*.
std::vector<Issue> validate(const DesignInput& d);
/// Sizes the link for each α (K from analyse() on a reference ring of the lamina's constants;
/// K does not depend on the scale), picks the lightest feasible one. Throws InputError; no
/// feasible α is a kInfeasible diagnostic (best then indexes the lightest point anyway).
Design design(const DesignInput& d);

}  // namespace catena::composite
