// Hertz line contact of two parallel cylinders (plane strain), shared by the contact models.
//
// Source: K. L. Johnson, Contact Mechanics (1985), §4.2: for a load P' per unit length on two
// cylinders of relative curvature 1/R* = 1/R_a ± 1/R_b and contact modulus
// 1/E* = (1 − ν_a²)/E_a + (1 − ν_b²)/E_b, the half-width is b = √(4P'R*/(πE*)) and the peak
// pressure p0 = √(P'E*/(πR*)) = 2P'/(πb).
#pragma once

namespace catena {

/// Elastic constants of one body.
struct Elastic {
  double modulus = 210e9;  ///< [Pa] Young's modulus E (steel by default)
  double poisson = 0.3;    ///< [-] Poisson's ratio ν
};

/// [Pa] contact modulus E* of two bodies.
double contact_modulus(const Elastic& a, const Elastic& b);

/// [m] effective radius R* of a convex cylinder R_convex inside a concave one R_concave
/// (R_concave > R_convex); R_concave = ∞ (or 0 meaning flat) gives R_convex.
double conformal_radius(double r_convex, double r_concave);

struct LineContact {
  double peak_pressure = 0.0;  ///< [Pa] p0 (the Hertz contact stress σH)
  double half_width = 0.0;     ///< [m] b
};

/// Line contact under `load_per_length` [N/m] with effective radius `radius` [m] and contact
/// modulus `modulus` [Pa].
LineContact line_contact(double load_per_length, double radius, double modulus);

}  // namespace catena
