// The hinges' friction couple (include/catena/dynamics/hinge_friction.hpp; docs/models/dynamics.md,
// "Hinges").
#include "catena/dynamics/hinge_friction.hpp"

#include <algorithm>
#include <cmath>

namespace catena::dynamics {

std::vector<Issue> validate(const HingeFriction& hinge, double pitch) {
  std::vector<Issue> out;
  // the arm is a fraction of a pin radius or a rolling lever: far below the pitch
  if (!std::isfinite(hinge.arm) || hinge.arm < 0.0 ||
      (std::isfinite(pitch) && pitch > 0.0 && hinge.arm >= 0.5 * pitch)) {
    out.push_back({"hinge.arm", check::format_si(hinge.arm, "m"),
                   "a finite value in [0, p/2) m (mu r or c_r R*)"});
  }
  if (!std::isfinite(hinge.rate_band) || !(hinge.rate_band > 0.0) || hinge.rate_band > 100.0) {
    out.push_back({"hinge.rate_band", check::format_si(hinge.rate_band, "rad/s"),
                   "a value in (0, 100] rad/s"});
  }
  return out;
}

double rolling_hinge_arm(double rolling_coefficient, double plate_radius, double face_radius) {
  const double reduced = std::isinf(face_radius)
                             ? plate_radius
                             : plate_radius * face_radius / (face_radius - plate_radius);
  return rolling_coefficient * reduced;
}

HingeCouple hinge_couple(const HingeFriction& hinge, double axial_stiffness, const double rest[2],
                         const double x0[3], const double y0[3], const double x1[3],
                         const double y1[3], double theta, double step) {
  HingeCouple hc;
  double turn[2], tension_sum = 0.0;
  double px[2], py[2];  // perp(d_θ)/|d_θ|² per link
  for (int j = 0; j < 2; ++j) {
    const double d0x = x0[j + 1] - x0[j], d0y = y0[j + 1] - y0[j];
    const double d1x = x1[j + 1] - x1[j], d1y = y1[j + 1] - y1[j];
    const double mx = (1.0 - theta) * d0x + theta * d1x, my = (1.0 - theta) * d0y + theta * d1y;
    const double m2 = mx * mx + my * my;
    turn[j] = (d0x * d1y - d0y * d1x) / m2;  // d_θ × (d₁ − d₀) = d₀ × d₁
    px[j] = -my / m2;
    py[j] = mx / m2;
    // the elastic tension at the θ point, with the integrator's interpolated length
    const double lt =
        (1.0 - theta) * std::sqrt(d0x * d0x + d0y * d0y) + theta * std::sqrt(d1x * d1x + d1y * d1y);
    tension_sum += axial_stiffness * (lt - rest[j]);
  }
  hc.load = std::max(0.0, 0.5 * tension_sum);
  hc.turn = turn[1] - turn[0];
  hc.rate = hc.turn / step;
  // g = ∂β/∂x: (+P₀, −P₀ − P₁, +P₁), P = perp(d_θ)/|d_θ|²
  hc.gx[0] = px[0];
  hc.gy[0] = py[0];
  hc.gx[1] = -px[0] - px[1];
  hc.gy[1] = -py[0] - py[1];
  hc.gx[2] = px[1];
  hc.gy[2] = py[1];
  const double band = hinge.rate_band;
  const double root = std::sqrt(hc.rate * hc.rate + band * band);
  const double limit = hinge.arm * hc.load;  // e F
  hc.torque = -limit * hc.rate / root;
  hc.work = hc.torque * hc.turn;
  for (int k = 0; k < 3; ++k) {
    hc.fx[k] = hc.torque * hc.gx[k];
    hc.fy[k] = hc.torque * hc.gy[k];
  }
  hc.rate_stiffness = limit * band * band / (root * root * root);
  return hc;
}

}  // namespace catena::dynamics
