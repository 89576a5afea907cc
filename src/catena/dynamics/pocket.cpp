// The pocket wheel's joint contact (docs/models/dynamics.md, "Pocket wheel").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/pocket_wheel.hpp"
#include "catena/pocketwheel/geometry.hpp"

namespace catena::dynamics {

Sprocket pocket_wheel(double pitch, double wire, int teeth, double centre_x, double centre_y,
                      double clearance, double contact_stiffness, double contact_damping) {
  const pocketwheel::WheelGeometry g =
      pocketwheel::wheel_geometry({.pitch = pitch, .wire = wire, .teeth = teeth});
  Sprocket s;
  s.pocket = true;
  s.centre_x = centre_x;
  s.centre_y = centre_y;
  s.teeth = teeth;
  s.pitch_radius = g.pitch_radius;
  s.pocket_angle = g.delta1;
  s.pocket_clearance = clearance;
  s.contact_stiffness = contact_stiffness;
  s.contact_damping = contact_damping;
  s.contact_smoothing = std::min(s.contact_smoothing, clearance);
  return s;
}

PocketVertex nearest_pocket(const Sprocket& w, double polar, double angle) {
  // Within one tooth period [ψ + mτ, ψ + (m + 1)τ) the vertices are at 0, δ1 and τ; the nearest
  // is decided by the two mid-angles δ1/2 and δ1 + δ2/2.
  const double tau = 2.0 * std::numbers::pi / w.teeth;
  const double d1 = w.pocket_angle, d2 = tau - d1;
  const double m = std::floor((polar - angle) / tau);
  const double b = polar - angle - m * tau;
  const int k = 2 * static_cast<int>(m);
  if (b < 0.5 * d1) return {k, angle + m * tau};
  if (b < d1 + 0.5 * d2) return {k + 1, angle + m * tau + d1};
  return {k + 2, angle + (m + 1.0) * tau};
}

SeatContact pocket_contact(const Sprocket& w, double x, double y, double vx, double vy,
                           double angle, double speed) {
  SeatContact c;
  const double rx = x - w.centre_x, ry = y - w.centre_y;
  const double reach = contact_reach(w);  // the mouth: R + c/2
  if (rx * rx + ry * ry > reach * reach) return c;
  const PocketVertex v = nearest_pocket(w, std::atan2(ry, rx), angle);
  c.seat = v.index;
  c.seat_x = w.centre_x + w.pitch_radius * std::cos(v.angle);
  c.seat_y = w.centre_y + w.pitch_radius * std::sin(v.angle);
  const double ex = x - c.seat_x, ey = y - c.seat_y;
  const double dist = std::sqrt(ex * ex + ey * ey);
  const double g = dist - w.pocket_clearance;
  if (!(g > 0.0)) return c;
  c.nx = ex / dist;
  c.ny = ey / dist;
  c.curvature = 1.0 / dist;
  apply_seat_law(w, g, rx, ry, vx, vy, speed, c);  // the seats' force law
  return c;
}

void pocket_issues(std::vector<Issue>& out, const Sprocket& w, const std::string& f) {
  constexpr double kPi = std::numbers::pi;
  const double tau = w.teeth > 0 ? 2.0 * kPi / w.teeth : 0.0;
  const double top = std::min(tau, kPi / 3.0);
  if (!std::isfinite(w.pocket_angle) || !(w.pocket_angle > 0.0) || !(w.pocket_angle < top)) {
    out.push_back({f + "pocket_angle", check::format_si(w.pocket_angle, "rad"),
                   "an angle in (0, min(2 pi/z, pi/3)) rad (delta1 < 2 pi/z; below 60 deg the "
                   "pocket's mouth R + c/2 admits a joint and holds the crank)"});
  }
  const double r = w.pitch_radius;
  if (!std::isfinite(w.pocket_clearance) || !(w.pocket_clearance > 0.0) ||
      !(std::isfinite(r) && w.pocket_clearance <= 0.1 * r)) {
    out.push_back({f + "pocket_clearance", check::format_si(w.pocket_clearance, "m"),
                   "a length in (0, R/10] (R the pitch radius)"});
  }
  check::finite_positive(out, (f + "contact_stiffness").c_str(), w.contact_stiffness, "N/m");
  if (!std::isfinite(w.contact_smoothing) || !(w.contact_smoothing > 0.0) ||
      !(w.contact_smoothing <= w.pocket_clearance)) {
    out.push_back({f + "contact_smoothing", check::format_si(w.contact_smoothing, "m"),
                   "a length in (0, pocket clearance]"});
  }
}

}  // namespace catena::dynamics
