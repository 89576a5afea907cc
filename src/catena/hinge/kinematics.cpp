#include "catena/hinge/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace catena::hinge {

Pose pose(const Hinge& h, double r2, double phi) {
  Pose p;
  p.phi = phi;
  p.gamma = 0.5 * phi;  // 000 eq. (3): the roller turns φ/2 relative to each plate
  const double a = h.half_thickness;
  const double r1 = h.plate_radius;
  const double g = p.gamma;
  if (h.face == Face::kFlat || !std::isfinite(r2)) {
    // A plane rolling on the circle: Ψ1 = γ; the contact travels R1·γ along the face.
    const double e = h.face == Face::kFlat ? flat_contact_offset(h) : 0.0;
    const double s = e + r1 * g;  // contact's position along the face (body frame)
    p.psi1 = g;
    p.contact = {a + r1 - r1 * std::cos(g), e + r1 * std::sin(g)};
    // O2 = M − Rot(−γ)(a, s)
    p.centre = {p.contact.x - (a * std::cos(g) + s * std::sin(g)),
                p.contact.y - (-a * std::sin(g) + s * std::cos(g))};
    p.v1 = s - e;  // R2 → ∞ limit of (a + R2) tan Ψ2 = (a + R2) R1γ/(R2 − R1) → R1γ
    p.v2 = a;
    return p;
  }
  // 000 eqs. (1)–(2): R1Ψ1 = R2Ψ2, γ = Ψ1 − Ψ2 ⇒ Ψ1 = γR2/(R2 − R1).
  p.psi1 = g * r2 / (r2 - r1);
  p.psi2 = p.psi1 - g;
  // 000 eqs. (8)–(9), the Latvian printing (the English one prints (R2 − R1)/2·φ).
  p.contact = {a + r1 - r1 * std::cos(p.psi1), r1 * std::sin(p.psi1)};
  // The face's centre C2 lies on O1M beyond M at R2 (internal tangency); the roller is turned by
  // −γ, so O2 = C2 + Rot(−γ)(−(a + R2), 0). 000 eqs. (18)–(19) write this as
  // X = a + R1 − (R1 + V2) cos Ψ1 − V1 sin γ, Y = (R1 + V2) sin Ψ1 − V1 cos γ with
  // V1 = (a + R2) tan Ψ2 and V2 = (a + R2)/cos Ψ2 − R2 (derived; not constants).
  // X written with 1 − cos = 2 sin²(·/2): no cancellation of the O(R2) terms near R1max.
  const double half1 = std::sin(0.5 * p.psi1);
  const double half_g = std::sin(0.5 * g);
  p.centre = {2.0 * ((a + r2) * half_g * half_g - (r2 - r1) * half1 * half1),
              -(r2 - r1) * std::sin(p.psi1) + (a + r2) * std::sin(g)};
  p.v1 = (a + r2) * std::tan(p.psi2);
  p.v2 = (a + r2) / std::cos(p.psi2) - r2;
  return p;
}

Point roller_point(const Pose& p, Point body) {
  // 000 eq. (11): rotation of the body point by −γ about O2.
  const double c = std::cos(p.gamma);
  const double s = std::sin(p.gamma);
  return {p.centre.x + body.x * c + body.y * s, p.centre.y - body.x * s + body.y * c};
}

double pitch_change(const Hinge& h, double r2, double phi) {
  return 2.0 * pose(h, r2, phi).centre.x;  // convention of 000 eq. (14)
}

std::vector<Point> feature_points(const Hinge& h, double r2) {
  const double a = h.half_thickness;
  const double r0 = 0.5 * h.pin_diameter;
  // Corner where the face meets the d circle: the face circle (centre a + R2, radius R2) and the
  // roller's circle intersect at x = (r0² + a² + 2aR2)/(2(a + R2)) — eq. (4) with R2 for R1.
  const bool flat = h.face == Face::kFlat || !std::isfinite(r2);
  const double x = flat ? a : (r0 * r0 + a * a + 2.0 * a * r2) / (2.0 * (a + r2));
  const double y = std::sqrt(std::max(0.0, r0 * r0 - x * x));
  return {{x, y}, {x, -y}, {-x, y}, {-x, -y}};
}

}  // namespace catena::hinge
