// Roller–sprocket tooth line contact with axis skew (seed 001: Harshniev & Maksymovych).
//
// Frame: s runs along the roller axis from its centre (−L/2 … L/2); the skew φ tilts the
// roller axis against the tooth's generatrix in the plane of the contact normal, so the gap
// opens linearly along s: g(s) = s·tan φ (the measuring device's Δh over the base B).
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/hertz.hpp"

namespace catena::contact {

enum class Profile {
  kConcave,  ///< tooth flank hollow (the roller sits in it): 1/ρ = 2/D − 1/r1
  kConvex,   ///< tooth flank convex: 1/ρ = 2/D + 1/r1
};

/// The roller and the tooth flank (constant model).
struct RollerTooth {
  double roller_diameter = 0.0;  ///< [m] D_p
  double roller_length = 0.0;    ///< [m] L_p, the length of the line contact when aligned
  double tooth_radius = 0.0;     ///< [m] r1, the flank's profile radius in the contact zone
  Profile profile = Profile::kConcave;
  Elastic roller;  ///< roller material (steel)
  Elastic tooth;   ///< tooth material (steel)
};

std::vector<Issue> validate(const RollerTooth& c);

/// [m] ρ = D_p r1 / (2(r1 ± 0.5 D_p)), + convex, − concave (001, below eq. 1).
double reduced_radius(const RollerTooth& c);

/// [Pa] the paper's eq. (1): σ = 0.418 √(Q E/(L ρ)), steel on steel (E the modulus of both).
double paper_stress(double load, double modulus, double length, double radius);

/// General Hertz line contact of the aligned roller under `load` [N] over its length.
struct HertzResult {
  double peak_pressure = 0.0;    ///< [Pa] p0
  double half_width = 0.0;       ///< [m] b
  double max_shear = 0.0;        ///< [Pa] τ1max = 0.300·p0 (principal shear, plane strain)
  double max_shear_depth = 0.0;  ///< [m] z = 0.786·b below the surface
};
HertzResult hertz(const RollerTooth& c, double load);

/// γ of eq. (2) from the paper's table for the pitches 12.7, 15.875, 19.05 and 25.4 mm; nothing
/// for any other pitch (no extrapolation: give γ explicitly).
std::optional<double> skew_gamma(double pitch);

/// [rad] skew from the measuring device: φ = arctg(Δh/B) (001).
double skew_from_gauge(double dh, double base);

/// Q_n/Q_nom = 1 + γ·φ_p², φ_p = φ·K_φ in arc-minutes (eqs. 2–3).
double load_factor(double gamma, double skew, double skew_factor = 1.0);

/// Beyond the paper: the skewed roller as slices along its length, each a plane-strain Hertz
/// line contact with the compliance δ(q) of Johnson (1985, eq. 5.36 form):
/// δ = (q/π)·Σ_bodies (1 − ν²)/E·(2 ln(4R_ref/b) − 1), R_ref = D_p/2 for both bodies (an
/// assumption: the reference depth of the approach), b = √(4qρ/(πE*)). The roller approaches by
/// δ0 at its centre and the gap opens as s·tan φ; δ0 is solved so that the slice loads sum to Q.
struct SliceOptions {
  int slices = 201;  ///< number of slices (odd keeps one at the centre)
};

struct SliceResult {
  std::vector<double> s;       ///< [m] slice centres along the roller
  std::vector<double> q;       ///< [N/m] load per unit length
  double approach = 0.0;       ///< [m] δ0 at the roller centre
  double loaded_length = 0.0;  ///< [m] length carrying load, where δ0 − s·tan φ > 0 (exact)
  double peak_load = 0.0;      ///< [N/m] at the roller's most loaded end s = −L/2
  double stress_peak = 0.0;    ///< [Pa] Hertz p0 of peak_load
  /// [m] Hertz half-width b of peak_load. The slices are plane-strain strips: the model is a
  /// fair approximation while loaded_length ≫ peak_half_width and rough below ~5 b, where the
  /// contact is closer to a short elliptical (3-D Hertz) patch.
  double peak_half_width = 0.0;
  double load_sum = 0.0;  ///< [N] Σ q·Δs (equals the load)
  int iterations = 0;     ///< outer iterations of the approach solve
};
SliceResult slice_model(const RollerTooth& c, double load, double skew,
                        const SliceOptions& options = {});

/// [m] plane-strain approach δ(q) of the slice law above.
double slice_approach(const RollerTooth& c, double load_per_length);

/// The plane-strain line contact's approach as a law of the load per length q (Johnson 1985,
/// eq. 5.36 form; docs/models/dynamics.md, "Contact law"): δ(q) = (q/π)·Σ(1 − ν²)/E·(2 ln(4R_ref/b)
/// − 1), b = √(4qρ/(πE*)), R_ref = d1/2, which is δ(q) = A q (C − ln q) with A = Σ(1 − ν²)/E / π
/// and C = 2 ln(4R_ref) − ln(4ρ/(πE*)) − 1. It increases while dδ/dq = A (C − ln q − 1) > 0,
/// i.e. for q < max_load() = e^(C−1) (b < 4R_ref/e). slice_approach evaluates it.
struct LineApproach {
  double e_star = 0.0;      ///< [Pa] E*
  double rho = 0.0;         ///< [m] the reduced radius ρ
  double r_ref = 0.0;       ///< [m] R_ref
  double compliance = 0.0;  ///< [1/Pa] Σ(1 − ν²)/E over both bodies
  double a = 0.0;           ///< [m²/N] A
  double c = 0.0;           ///< C (q in N/m)
  /// [m] δ(q); 0 for q ≤ 0
  double approach(double q) const;
  /// [m²/N] dδ/dq
  double slope(double q) const { return a * (c - std::log(q) - 1.0); }
  /// [N/m] the q at which δ stops increasing
  double max_load() const { return std::exp(c - 1.0); }
  /// [N/m] the dynamics seat law's cap e^(C−2), where dδ/dq has fallen to A (b = 4R_ref/e^(3/2),
  /// 0.37 of max_load()); beyond it the seat law continues along the tangent there
  double cap_load() const { return std::exp(c - 2.0); }
  /// [N/m] the inverse: q with δ(q) = delta, for 0 ≤ delta < δ(max_load()) (Newton in ln q,
  /// bracketed, no allocation); 0 for delta ≤ 0, NaN beyond the increasing branch
  double load(double delta) const;
  /// [J/m] ∫₀^δ(q) q dδ = A q² ((C − ln q)/2 − 1/4), the elastic energy per length at q
  double energy(double q) const;
};
LineApproach line_approach(const RollerTooth& c);
/// The same law for any two bodies pressed along a line: `a` and `b` their materials, ρ the
/// reduced radius [m] (1/ρ = 1/r1 ± 1/r2; r1 on a flat), R_ref the reference depth [m].
/// line_approach(c) is this with c's materials, reduced_radius(c) and D_p/2.
LineApproach line_approach(const Elastic& a, const Elastic& b, double rho, double r_ref);

}  // namespace catena::contact
