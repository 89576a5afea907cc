#include "catena/pocketwheel/geometry.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "geometry_detail.hpp"

namespace catena::pocketwheel {

std::vector<Issue> validate(const PocketWheel& wheel) {
  std::vector<Issue> issues;
  check::finite_positive(issues, "pitch", wheel.pitch, "m");
  check::finite_positive(issues, "wire", wheel.wire, "m");
  if (std::isfinite(wheel.pitch) && std::isfinite(wheel.wire) && wheel.wire > 0.0 &&
      wheel.pitch > 0.0 && wheel.pitch <= wheel.wire) {
    issues.push_back(
        {"pitch", check::format_si(wheel.pitch, "m"),
         "a pitch t greater than the wire diameter d = " + check::format_si(wheel.wire, "m") +
             " (the t − d side of the joint polygon must be positive)"});
  } else if (std::isfinite(wheel.pitch) && std::isfinite(wheel.wire) && wheel.pitch > 0.0 &&
             wheel.wire > 0.5 * wheel.pitch) {
    // a link's inner length t holds its two neighbours' wires, one at each end: 2d ≤ t
    issues.push_back(
        {"wire", check::format_si(wheel.wire, "m"),
         "a wire diameter d at most t/2 = " + check::format_si(0.5 * wheel.pitch, "m") +
             " (a link's inner length t holds its two neighbours' wires)"});
  }
  if (wheel.teeth < 3) {
    issues.push_back({"teeth", std::to_string(wheel.teeth), "an integer z ≥ 3"});
  }
  return issues;
}

WheelGeometry detail::geometry_of_valid(const PocketWheel& wheel) {
  const double t = wheel.pitch;
  const double d = wheel.wire;
  const double half = std::numbers::pi / (2.0 * wheel.teeth);  // π/(2z)
  WheelGeometry g;
  // 003 eq. (6), printed with 's' for z (OCR). From t ± d = 2R sin(δ1,2/2), δ1 + δ2 = 2π/z:
  // t = 2R sin(π/2z) cos c, d = 2R cos(π/2z) sin c, c = (δ1 − δ2)/4. Checked against the root of
  // the closure condition in tests/pocketwheel/geometry_test.cpp.
  g.pitch_radius = 0.5 * std::hypot(t / std::sin(half), d / std::cos(half));
  g.delta1 = 2.0 * std::asin((t + d) / (2.0 * g.pitch_radius));                   // 003 eq. (7)
  g.delta2 = 2.0 * std::asin((t - d) / (2.0 * g.pitch_radius));                   // 003 eq. (8)
  g.tooth_angle = 2.0 * std::numbers::pi / wheel.teeth;                           // 003 eq. (9)
  g.transverse_displacement = g.pitch_radius * (1.0 - std::cos(0.5 * g.delta1));  // 003 §2
  g.chordal_height = g.pitch_radius * std::cos(0.5 * g.delta1);                   // 003 §3
  return g;
}

WheelGeometry wheel_geometry(const PocketWheel& wheel) {
  throw_if_any(validate(wheel));
  return detail::geometry_of_valid(wheel);
}

}  // namespace catena::pocketwheel
