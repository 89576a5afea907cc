// Synthesis of the rolling-friction hinge: the six-step procedure of seed 000 §1.2.
#pragma once

#include <optional>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/hertz.hpp"
#include "catena/hinge/hinge.hpp"

namespace catena::hinge {

/// [m] x of N1, where the plate's R1 circle meets the roller's d circle, eq. (4).
double x_n1(double d, double a, double r1);
/// [rad] Ψ1max, the plate-arc angle of N1, eq. (5) (π when the R1 circle lies inside the roller).
double psi1_max(double d, double a, double r1);
/// [m] R1max, the plate radius at which eq. (6) needs a flat face, eq. (7) with γmax.
double r1_max(double d, double a, double gamma_max);
/// [m] R2 from eq. (6); +∞ at R1 = R1max; nothing when R1 > R1max (no concave face can do).
std::optional<double> r2_eq6(double d, double a, double r1, double gamma_max);

/// [m²] roller section: the d circle less the two parts cut by a working-face circle of radius
/// `face_radius` touching x = ±a (0 or ∞ = flat faces). With face_radius = R1 this is the
/// approximation of eq. (10); with R2 the true section.
double section_area(double d, double a, double face_radius);

/// [m] a_min: the half-thickness at which the section of eq. (10) (R1 arcs) carries F at [τ];
/// nothing when even the full circle cannot (πd²/4 < F/[τ]).
std::optional<double> a_min_eq10(double d, double r1, double tension, double allowable_shear);

/// Step 1 of the procedure: eqs. (7) and (10) solved together — the half-thickness a at which
/// the section of eq. (10) with R1 = R1max(a) carries F at [τ], and that R1max. Nothing when no
/// a in (0, d/2) does.
struct JointLimit {
  double a_min = 0.0;   ///< [m]
  double r1_max = 0.0;  ///< [m]
};
std::optional<JointLimit> a_min_at_r1max(double d, double gamma_max, double tension,
                                         double allowable_shear);

/// [rad] the roller turn up to which friction alone keeps the hinge rolling with the roller
/// held, eq. (21): γ = arctan(f)·(1 − R1/R2).
double rolling_limit(double friction, double r1, double r2);

/// Loads and materials for the checks of the synthesis (all optional).
struct Loads {
  std::optional<double> tension;            ///< [N] chain tension F
  std::optional<double> allowable_shear;    ///< [Pa] [τ] of the roller
  std::optional<double> contact_length;     ///< [m] length of the R1–R2 line contact
  Elastic plate;                            ///< plate material (steel)
  Elastic roller;                           ///< roller material (steel)
  std::optional<double> allowable_contact;  ///< [Pa] [σH]
  std::optional<double> friction;           ///< [-] f between roller and plate
};

std::vector<Issue> validate(const Loads& loads);

struct Synthesis {
  double gamma_max = 0.0;    ///< [rad] eqs. (3), (12)
  double phi_max = 0.0;      ///< [rad] 2γmax, the largest mutual turn of the links
  double x_n1 = 0.0;         ///< [m] eq. (4)
  double psi1_max = 0.0;     ///< [rad] eq. (5)
  double r1_max = 0.0;       ///< [m] eq. (7)
  double r2 = 0.0;           ///< [m] R2 used (given or eq. 6; +∞ for flat faces)
  bool r2_from_eq6 = false;  ///< R2 came from eq. (6)
  double face_margin = 0.0;  ///< [m] arc left on the roller's face beyond the contact at φmax
  double section_area_eq10 = 0.0;      ///< [m²] the section as eq. (10) approximates it (R1 arcs)
  double section_area = 0.0;           ///< [m²] the true section (R2 arcs or flat faces)
  std::optional<double> a_min;         ///< [m] eq. (10) solved for a (with F and [τ])
  std::optional<JointLimit> step1;     ///< eqs. (7) + (10) solved together (with F and [τ])
  std::optional<double> shear_stress;  ///< [Pa] F / true section
  std::optional<double> contact_stress;      ///< [Pa] Hertz σH of R1 in R2 over the contact length
  std::optional<double> contact_half_width;  ///< [m]
  std::optional<double> rolling_limit;       ///< [rad] eq. (21), roller turn
  std::vector<Diagnostic> diagnostics;
};

/// The six steps: R1max, R2, a_min, section, σH, rolling limit, with a diagnostic for every step
/// that cannot be met. Throws InputError for invalid input.
Synthesis synthesize(const Hinge& hinge, const Loads& loads);

}  // namespace catena::hinge
